// isSimple (sim/Crossings.h) by a sweep line (Shamos and Hoey, 1976): n log n for any input, and
// it stops at the first contact. findCrossings' uniform grid compares every pair of edges that
// share a cell, and edges lying close together by the thousand (1,000 nested squares a millionth
// apart, 40 KB of SVG) share every cell: minutes there, where the sweep takes a second.
//
// The sweep visits the vertices in lexicographic order (x, then y) and keeps the edges its line
// crosses, ordered along it. Two edges in contact are next to each other there before the sweep
// passes their first common point, so only edges that become neighbours in that order are
// tested. Every test is exact (orientation()), and ties in the order are broken the way a line
// turned infinitesimally from the vertical would break them, so vertical and collinear edges need
// no special case.
#include "sim/Crossings.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <set>
#include <vector>

namespace vf::sim {
namespace {

bool before(Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// One edge of one polygon, from vertex `index` to the next, with its ends in sweep order.
struct Edge {
    Vec2 left, right;
    std::uint32_t polygon, index, count;
    bool reversed;  // the polygon runs from right to left

    Edge(Vec2 from, Vec2 to, std::uint32_t polygon, std::uint32_t index, std::uint32_t count)
        : left(before(to, from) ? to : from), right(before(to, from) ? from : to), polygon(polygon), index(index),
          count(count), reversed(before(to, from))
    {
    }
    Vec2 from() const { return reversed ? right : left; }
    Vec2 to() const { return reversed ? left : right; }
};

// p on the closed edge: on its line, and between its ends in sweep order.
bool onEdge(Vec2 p, const Edge& e)
{
    return orientation(e.left, e.right, p) == 0 && !before(p, e.left) && !before(e.right, p);
}

bool properlyCross(const Edge& s, const Edge& t)
{
    const int d1 = orientation(s.left, s.right, t.left), d2 = orientation(s.left, s.right, t.right);
    if (d1 == 0 || d2 == 0 || d1 == d2)
        return false;
    const int d3 = orientation(t.left, t.right, s.left), d4 = orientation(t.left, t.right, s.right);
    return d3 != 0 && d4 != 0 && d3 != d4;
}

// Whether two edges meet where a simple polygon's may not: anywhere, unless they follow each other
// in one polygon, where they share their common vertex and may not fold back onto each other. A
// triangle's edges all follow each other; only a zero area would be wrong, which is not this test's.
bool inContact(const Edge& s, const Edge& t)
{
    if (s.polygon == t.polygon) {
        const std::uint32_t d = s.index > t.index ? s.index - t.index : t.index - s.index;
        if (d <= 1 || d == s.count - 1) {
            if (s.count == 3)
                return false;
            const bool sFirst = (s.index + 1) % s.count == t.index;
            const Edge& first = sFirst ? s : t;
            const Edge& second = sFirst ? t : s;
            return orientation(first.left, first.right, second.to()) == 0 &&
                   glm::dot(first.to() - first.from(), second.to() - second.from()) < 0.0;
        }
    }
    return properlyCross(s, t) || onEdge(s.left, t) || onEdge(s.right, t) || onEdge(t.left, s) || onEdge(t.right, s);
}

// The order along the sweep line of two edges it crosses: which side of the edge that started
// first the other one starts (or, from a common start, ends) on. Edges on one line, which are in
// contact anyway, keep their order in the list.
class Below {
public:
    explicit Below(const std::vector<Edge>& edges) : m_edges(&edges) {}

    bool operator()(std::uint32_t a, std::uint32_t b) const
    {
        if (a == b)
            return false;
        const Edge& ea = (*m_edges)[a];
        const Edge& eb = (*m_edges)[b];
        const bool aFirst = !before(eb.left, ea.left);
        const Edge& first = aFirst ? ea : eb;
        const Edge& second = aFirst ? eb : ea;
        // A shared vertex is on the line by definition: no need for the exact arithmetic that
        // orientation() falls back to on a line.
        const bool shared = second.left == first.left || second.left == first.right;
        int side = shared ? 0 : orientation(first.left, first.right, second.left);
        if (side == 0)
            side = orientation(first.left, first.right, second.right);
        if (side == 0)
            return a < b;
        return aFirst ? side > 0 : side < 0;  // side > 0: the second lies above the first
    }

private:
    const std::vector<Edge>* m_edges;
};

} // namespace

bool isSimple(const Polygon& polygon)
{
    return isSimple(std::vector<const Polygon*>{&polygon});
}

bool isSimple(const std::vector<const Polygon*>& polygons)
{
    std::vector<Edge> edges;
    for (std::uint32_t p = 0; p < polygons.size(); ++p) {
        const Polygon& polygon = *polygons[p];
        const auto n = std::uint32_t(polygon.size());
        for (std::uint32_t i = 0; i < n; ++i) {
            if (polygon[i] == polygon[(i + 1) % n])
                return false;  // a repeated vertex
            edges.emplace_back(polygon[i], polygon[(i + 1) % n], p, i, n);
        }
    }
    // Where each edge starts and ends; at one point starts come first, so that an edge ending
    // where another starts still meets it.
    struct Event {
        Vec2 point;
        std::uint32_t edge;
        bool start;
    };
    std::vector<Event> events;
    events.reserve(2 * edges.size());
    for (std::uint32_t k = 0; k < edges.size(); ++k) {
        events.push_back({edges[k].left, k, true});
        events.push_back({edges[k].right, k, false});
    }
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
        if (a.point != b.point)
            return before(a.point, b.point);
        return a.start && !b.start;
    });

    using Line = std::set<std::uint32_t, Below>;
    Line line{Below(edges)};
    std::vector<Line::iterator> where(edges.size());
    const auto meet = [&edges](Line::iterator a, Line::iterator b) { return inContact(edges[*a], edges[*b]); };
    for (const Event& event : events) {
        const std::uint32_t k = event.edge;
        if (event.start) {
            const Line::iterator it = line.insert(k).first;
            where[k] = it;
            if ((it != line.begin() && meet(std::prev(it), it)) || (std::next(it) != line.end() && meet(it, std::next(it))))
                return false;
        } else {
            const Line::iterator it = where[k];
            if (it != line.begin() && std::next(it) != line.end() && meet(std::prev(it), std::next(it)))
                return false;
            line.erase(it);
        }
    }
    return true;
}

} // namespace vf::sim
