#include "sim/Separation.h"

#include "sim/Crossings.h"
#include "sim/EdgeGrid.h"
#include "sim/Pinches.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace vf::sim {

namespace {

// Segments a–b and c–d cross or touch (collinear ones where they overlap): what a moved vertex's
// edges must not do.
bool meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d)
{
    const int abc = orientation(a, b, c), abd = orientation(a, b, d);
    if (abc == 0 && abd == 0)
        return std::max(std::min(a.x, b.x), std::min(c.x, d.x)) <= std::min(std::max(a.x, b.x), std::max(c.x, d.x)) &&
               std::max(std::min(a.y, b.y), std::min(c.y, d.y)) <= std::min(std::max(a.y, b.y), std::max(c.y, d.y));
    return abc * abd <= 0 && orientation(c, d, a) * orientation(c, d, b) <= 0;
}

// Whether the edge from vertex j of contour q lies farther along the contour from vertex i (either
// way round) than twice `distance`, its straight distance from it: another part of the contour, as
// the far side of a thin filament is (eq. 7's rule).
bool anotherPart(const Outline& q, std::size_t i, std::size_t j, double distance)
{
    const std::size_t n = q.size(), jNext = after(j, n);
    if (j == i || jNext == i)
        return false;
    const double limit = 2.0 * distance;
    double way = 0.0;
    for (std::size_t v = i; way <= limit && v != j; v = after(v, n))
        way += glm::distance(q[v], q[after(v, n)]);
    if (way <= limit)
        return false;
    way = 0.0;
    for (std::size_t v = i; way <= limit && v != jNext; v = (v + n - 1) % n)
        way += glm::distance(q[v], q[(v + n - 1) % n]);
    return way > limit;
}

// Where vertex i of contour k goes to stand at least the pinch width off every other contour near
// it: pushed straight away from each such contour's nearest edge by what it lacks (one push per
// contour, however many of its short edges lie within reach), the sum at most one width long.
// Itself where nothing is that near, where it lies on another contour (which side it belongs on is
// then unknown), or where another part of its own contour is that near: a layer of one contour
// thinner than the width is the pinch cut's to take, and a push would press it thinner still.
Vec2 separated(const std::vector<Outline>& contours, const EdgeGrid& grid, const std::vector<double>& widths,
               std::size_t k, std::size_t i)
{
    struct Nearest {
        std::uint32_t contour;
        double distance;
        Vec2 from;  // the nearest point of that contour
        double width;
    };
    std::vector<Nearest> near;
    const Vec2 p = contours[k][i];
    bool ownLayer = false;
    grid.forEdgesNear(p, p, [&](EdgeGrid::Edge e) {
        const Outline& other = contours[e.contour];
        const Vec2 a = other[e.from], b = other[after(e.from, other.size())];
        const double width = std::max(widths[k], widths[e.contour]);
        if (p.x < std::min(a.x, b.x) - width || p.x > std::max(a.x, b.x) + width ||
            p.y < std::min(a.y, b.y) - width || p.y > std::max(a.y, b.y) + width)
            return;
        const Vec2 ab = b - a;
        const double length2 = glm::dot(ab, ab);
        const Vec2 nearest = a + (length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0) * ab;
        const double distance = glm::distance(p, nearest);
        if (distance >= width)
            return;
        if (e.contour == k) {
            ownLayer = ownLayer || anotherPart(other, i, e.from, distance);
            return;
        }
        const auto same = std::find_if(near.begin(), near.end(), [&](const Nearest& n) { return n.contour == e.contour; });
        if (same == near.end())
            near.push_back({e.contour, distance, nearest, width});
        else if (distance < same->distance)
            *same = {e.contour, distance, nearest, width};
    });
    if (ownLayer)
        return p;
    Vec2 push(0.0);
    double widest = 0.0;
    for (const Nearest& n : near) {
        if (n.distance == 0.0)
            return p;
        push += (n.width - n.distance) / n.distance * (p - n.from);
        widest = std::max(widest, n.width);
    }
    const double length = glm::length(push);
    return length > widest ? p + widest / length * push : p + push;
}

// Whether vertex i of contour k may move to `to`: its two edges, so moved, meet no edge of any
// contour but their own neighbours (at the vertex they share). `positions` holds the contours as
// moved so far; no vertex has moved farther than its contour's width, which the grid's boxes allow.
bool moveIsClean(const std::vector<std::vector<Vec2>>& positions, const EdgeGrid& grid, std::size_t k,
                 std::size_t i, Vec2 to)
{
    const std::vector<Vec2>& q = positions[k];
    const std::size_t n = q.size(), before = (i + n - 1) % n, next = after(i, n);
    for (const auto& edge : {std::pair{before, i}, std::pair{i, next}}) {
        const std::size_t from = edge.first, end = edge.second;  // named, not bound: clang 14 cannot capture bindings
        const Vec2 a = from == i ? to : q[from], b = end == i ? to : q[end];
        bool clean = true;
        grid.forEdgesNear(a, b, [&](EdgeGrid::Edge e) {
            const std::vector<Vec2>& other = positions[e.contour];
            const std::size_t j = e.from, jNext = after(j, other.size());
            if (e.contour == k && (j == from || j == end || jNext == from || jNext == end))
                return;  // the edge itself, its neighbour (they share a vertex) or the vertex's other edge
            clean = clean && !meet(a, b, other[j], other[jNext]);
        });
        if (!clean)
            return false;
    }
    return true;
}

// How far vertex i of contour k, put at `at`, lies from the nearest other ink, as moved so far: an
// edge of another contour, or of another part of its own (anotherPart); infinite beyond the grid's
// reach (twice the width).
double nearestOtherInk(const std::vector<std::vector<Vec2>>& positions, const EdgeGrid& grid, std::size_t k,
                       std::size_t i, Vec2 at)
{
    double nearest = std::numeric_limits<double>::infinity();
    grid.forEdgesNear(at, at, [&](EdgeGrid::Edge e) {
        const std::vector<Vec2>& other = positions[e.contour];
        const double distance = std::sqrt(squaredDistanceToSegment(at, other[e.from], other[after(e.from, other.size())]));
        if (distance < nearest && (e.contour != k || anotherPart(other, i, e.from, distance)))
            nearest = distance;
    });
    return nearest;
}

// The longest of the move, its half, its quarter and so on (to a few stored positions' spacing) that
// moveIsClean allows and that leaves the vertex no nearer other ink (its own too) than it was. The
// pushes are found from the positions before any move: in a stack of layers all thinner than the
// width, the push away from the thinnest layer carries a vertex toward the next, whose vertices the
// next layer's push may carry toward it, and both moves made whole could press that layer to
// nothing; a push off another contour can carry a vertex onto another part of its own. Another layer
// of the stack can also refuse the whole move (it would cross) and allow a part. A layer left a few
// float spacings thin is crossed by the next rounding (a split's midpoint on a device).
std::optional<Vec2> cleanPartOf(const std::vector<std::vector<Vec2>>& positions, const EdgeGrid& grid,
                                const VertexMove& m, bool singlePrecision)
{
    constexpr int parts = 12;
    const Vec2 from = positions[m.contour][m.vertex];
    const double before = nearestOtherInk(positions, grid, m.contour, m.vertex, from);
    double share = 1.0;
    for (int part = 0; part < parts; ++part, share *= 0.5) {
        const Vec2 to = part == 0 ? m.to : storedPosition(from + share * (m.to - from), singlePrecision);
        if (to == from)
            break;
        if (nearestOtherInk(positions, grid, m.contour, m.vertex, to) >= before &&
            moveIsClean(positions, grid, m.contour, m.vertex, to))
            return to;
    }
    return std::nullopt;
}

// The window grown by the longest edge at a vertex inside it: the edges of a vertex that moves
// reach no farther, so every edge they could meet is among those of the grown window.
Window withEdgesOf(const std::vector<Outline>& contours, Window window)
{
    double longest = 0.0;
    for (const Outline& c : contours)
        for (std::size_t i = 0; i < c.size(); ++i)
            if (window.holds(c[i]))
                longest = std::max({longest, glm::distance(c[i], c[after(i, c.size())]),
                                    glm::distance(c[i], c[(i + c.size() - 1) % c.size()])});
    return {window.low - Vec2(longest), window.high + Vec2(longest)};
}

} // namespace

std::vector<VertexMove> findSeparations(const std::vector<Outline>& contours, bool singlePrecision,
                                        std::optional<Window> within)
{
    std::vector<VertexMove> moves;
    if (contours.empty())
        return moves;
    const std::vector<double> widths = pinchWidths(contours);
    // Boxes twice as wide: an edge whose ends have moved (a width at most) is still found.
    std::vector<double> reach(widths.size());
    std::transform(widths.begin(), widths.end(), reach.begin(), [](double w) { return 2.0 * w; });
    EdgeGrid::Storage storage;
    const EdgeGrid grid(contours, reach, storage, within ? std::optional(withEdgesOf(contours, *within)) : std::nullopt);
    // Where each vertex would go, from the positions before any move; then, in turn, the moves that
    // stay clean of the contours as moved so far.
    std::vector<VertexMove> wanted;
    for (std::size_t k = 0; k < contours.size(); ++k)
        for (std::size_t i = 0; i < contours[k].size(); ++i) {
            if (within && !within->holds(contours[k][i]))
                continue;
            if (const Vec2 to = storedPosition(separated(contours, grid, widths, k, i), singlePrecision); to != contours[k][i])
                wanted.push_back({std::uint32_t(k), std::uint32_t(i), to});
        }
    if (wanted.empty())
        return moves;
    std::vector<std::vector<Vec2>> moved;
    moved.reserve(contours.size());
    for (const Outline& c : contours)
        moved.emplace_back(c.begin(), c.end());
    for (const VertexMove& m : wanted)
        if (const std::optional<Vec2> to = cleanPartOf(moved, grid, m, singlePrecision)) {
            moved[m.contour][m.vertex] = *to;
            moves.push_back({m.contour, m.vertex, *to});
        }
    return moves;
}

double moveVertex(std::span<Vec2> ring, std::size_t i, Vec2 to)
{
    // The shoelace area changes by ½·d × (v_{i+1} − v_{i−1}) when v_i alone moves by d.
    const std::size_t n = ring.size();
    const Vec2 d = to - ring[i], across = ring[after(i, n)] - ring[(i + n - 1) % n];
    ring[i] = to;
    return 0.5 * (d.x * across.y - d.y * across.x);
}

void moveVertices(std::vector<Contour>& contours, const std::vector<VertexMove>& moves)
{
    for (const VertexMove& m : moves) {
        Contour& c = contours[m.contour];
        c.targetArea += moveVertex(c.positions, m.vertex, m.to);
    }
}

std::size_t separateLayers(std::vector<Contour>& contours, std::optional<Window> within)
{
    const std::vector<VertexMove> moves = findSeparations(outlinesOf(contours), false, within);
    moveVertices(contours, moves);
    return moves.size();
}


} // namespace vf::sim
