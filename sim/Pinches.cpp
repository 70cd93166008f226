#include "sim/Pinches.h"

#include "sim/Crossings.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>

namespace vf::sim {

namespace {

// The vertex after i on a ring of n (no division: this runs for every vertex and edge).
std::size_t after(std::size_t i, std::size_t n)
{
    return i + 1 == n ? 0 : i + 1;
}

// Every edge of every contour in the cells its box, widened by its contour's pinch width, overlaps:
// the edges of a contour within that width of a point are among those of the point's cell.
// Counting sort, as ProximityGrid.
class EdgeGrid {
public:
    struct Edge {
        std::uint32_t contour, from;  // from vertex `from` to the next
    };

    EdgeGrid(const std::vector<Outline>& contours, const std::vector<double>& widths) : m_widths(widths)
    {
        Vec2 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
        double edgeLength = 0.0;
        std::size_t edges = 0;
        for (const Outline& c : contours) {
            for (std::size_t i = 0; i < c.size(); ++i) {
                low = glm::min(low, c[i]);
                high = glm::max(high, c[i]);
                edgeLength += glm::distance(c[i], c[after(i, c.size())]);
            }
            edges += c.size();
        }
        if (edges == 0)
            return;
        // Cells about twice the mean edge long, at most 1024 across the extent.
        const Vec2 extent = high - low;
        const double widest = *std::max_element(widths.begin(), widths.end());
        m_cell = std::max({2.0 * edgeLength / double(edges), std::max(extent.x, extent.y) / 1024.0,
                           std::numeric_limits<double>::min()});
        m_origin = low - Vec2(widest);
        m_columns = int(extent.x / m_cell) + 2;
        m_rows = int(extent.y / m_cell) + 2;
        m_start.assign(std::size_t(m_columns) * std::size_t(m_rows) + 1, 0);
        forEveryEdgeCell(contours, [this](std::size_t cell, Edge) { ++m_start[cell + 1]; });
        for (std::size_t k = 1; k < m_start.size(); ++k)
            m_start[k] += m_start[k - 1];
        m_entries.resize(m_start.back());
        std::vector<std::uint32_t> fill(m_start.begin(), m_start.end() - 1);
        forEveryEdgeCell(contours, [&](std::size_t cell, Edge e) { m_entries[fill[cell]++] = e; });
    }

    // f(edge) for every edge whose widened box overlaps the box of a and b.
    template <class F>
    void forEdgesNear(Vec2 a, Vec2 b, F f) const
    {
        if (m_entries.empty())
            return;
        const auto [c0, r0] = cellOf(glm::min(a, b));
        const auto [c1, r1] = cellOf(glm::max(a, b));
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) {
                const std::size_t cell = std::size_t(r) * std::size_t(m_columns) + std::size_t(c);
                for (std::uint32_t k = m_start[cell]; k < m_start[cell + 1]; ++k)
                    f(m_entries[k]);
            }
    }

private:
    std::pair<int, int> cellOf(Vec2 p) const
    {
        const Vec2 q = (p - m_origin) / m_cell;
        return {std::clamp(int(q.x), 0, m_columns - 1), std::clamp(int(q.y), 0, m_rows - 1)};
    }

    template <class F>
    void forEveryEdgeCell(const std::vector<Outline>& contours, F f) const
    {
        for (std::size_t k = 0; k < contours.size(); ++k) {
            const Outline& p = contours[k];
            for (std::size_t i = 0; i < p.size(); ++i) {
                const Vec2 a = p[i], b = p[after(i, p.size())];
                const auto [c0, r0] = cellOf(glm::min(a, b) - Vec2(m_widths[k]));
                const auto [c1, r1] = cellOf(glm::max(a, b) + Vec2(m_widths[k]));
                for (int r = r0; r <= r1; ++r)
                    for (int c = c0; c <= c1; ++c)
                        f(std::size_t(r) * std::size_t(m_columns) + std::size_t(c),
                          Edge{std::uint32_t(k), std::uint32_t(i)});
            }
        }
    }

    const std::vector<double>& m_widths;
    double m_cell = 1.0;
    Vec2 m_origin{0.0};
    int m_columns = 0, m_rows = 0;
    std::vector<std::uint32_t> m_start;
    std::vector<Edge> m_entries;
};

// Vertex `vertex` of a contour within the pinch width of its edge from `edge`; smallerLoop counts
// the vertices of the smaller of the loops a cut there makes.
struct Pinch {
    std::size_t vertex = 0, edge = 0;
    std::size_t smallerLoop = 0;
};


bool properlyCross(Vec2 a, Vec2 b, Vec2 c, Vec2 d)
{
    return orientation(a, b, c) * orientation(a, b, d) < 0 && orientation(c, d, a) * orientation(c, d, b) < 0;
}

// A cut's two new edges, edge → vertex and before → after (before the vertex's and after the edge's
// neighbour in their loop), cross no edge of the contours searched but those with an end among the
// four (the edges the cut removes among them), nor each other, nor the edges of earlier cuts.
bool cutIsClean(const std::vector<Outline>& contours, const EdgeGrid& grid, std::size_t k,
                const std::array<std::size_t, 4>& ends, const std::vector<std::pair<Vec2, Vec2>>& earlierCuts)
{
    const Outline& q = contours[k];
    const auto [vertex, edge, vertexBefore, edgeAfter] = ends;
    const std::array<std::pair<Vec2, Vec2>, 2> made{{{q[edge], q[vertex]}, {q[vertexBefore], q[edgeAfter]}}};
    if (properlyCross(made[0].first, made[0].second, made[1].first, made[1].second))
        return false;
    for (const auto& cut : made) {
        const Vec2 from = cut.first, to = cut.second; // named, not bound: clang 14 cannot capture bindings
        for (const auto& [a, b] : earlierCuts)
            if (properlyCross(from, to, a, b))
                return false;
        bool clean = true;
        grid.forEdgesNear(from, to, [&](EdgeGrid::Edge e) {
            const Outline& other = contours[e.contour];
            const std::size_t next = after(e.from, other.size());
            if (e.contour == k && std::any_of(ends.begin(), ends.end(),
                                              [&](std::size_t v) { return v == e.from || v == next; }))
                return;
            clean = clean && !properlyCross(from, to, other[e.from], other[next]);
        });
        if (!clean)
            return false;
    }
    return true;
}

// Whether the loop of the vertices `loop` of q is thinner on average (twice its area over its
// perimeter) than twice the pinch width, or has fewer than three vertices.
bool tooThinToShow(const Outline& q, const std::vector<std::uint32_t>& loop, double width)
{
    if (loop.size() < 3)
        return true;
    double twiceArea = 0.0, perimeter = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec2 a = q[loop[i]], b = q[loop[(i + 1) % loop.size()]];
        twiceArea += a.x * b.y - b.x * a.y;
        perimeter += glm::distance(a, b);
    }
    return std::abs(twiceArea) < 2.0 * width * perimeter;
}

// Contour k cut at its pinches in turn, as loops of its vertex indices: a pinch is cut where its
// vertex and edge still lie in one loop and the cut is clean.
std::vector<std::vector<std::uint32_t>> loopsAfterCuts(const std::vector<Outline>& contours, const EdgeGrid& grid,
                                                       std::size_t k, const std::vector<Pinch>& pinches, double width)
{
    constexpr std::uint32_t dropped = std::numeric_limits<std::uint32_t>::max();
    const Outline& q = contours[k];
    const std::size_t n = q.size();
    std::vector<std::vector<std::uint32_t>> loops(1);
    std::vector<std::uint32_t> owner(n, 0), at(n);
    for (std::size_t i = 0; i < n; ++i) {
        loops[0].push_back(std::uint32_t(i));
        at[i] = std::uint32_t(i);
    }
    std::vector<std::pair<Vec2, Vec2>> made;
    for (const Pinch& p : pinches) {
        const std::uint32_t l = owner[p.vertex];
        if (l == dropped)
            continue;
        std::vector<std::uint32_t>& loop = loops[l];
        const std::size_t m = loop.size(), a = at[p.vertex], b = at[p.edge];
        // The edge must still be there, and not be one of the vertex's own.
        if (owner[p.edge] != l || loop[(b + 1) % m] != (p.edge + 1) % n || a == b || a == (b + 1) % m)
            continue;
        const std::array<std::size_t, 4> ends{p.vertex, p.edge, loop[(a + m - 1) % m], loop[(b + 1) % m]};
        if (!cutIsClean(contours, grid, k, ends, made))
            continue;
        made.push_back({q[ends[1]], q[ends[0]]});
        made.push_back({q[ends[2]], q[ends[3]]});
        std::vector<std::uint32_t> first, second;  // vertex … edge, edge + 1 … vertex − 1
        for (std::size_t i = a;; i = (i + 1) % m) {
            first.push_back(loop[i]);
            if (i == b)
                break;
        }
        for (std::size_t i = (b + 1) % m; i != a; i = (i + 1) % m)
            second.push_back(loop[i]);
        loops[l] = std::move(first);
        loops.push_back(std::move(second));
        for (std::uint32_t id : {l, std::uint32_t(loops.size() - 1)}) {
            // A loop that will be dropped takes no more cuts: its pinches go with it.
            const std::uint32_t to = tooThinToShow(q, loops[id], width) ? dropped : id;
            for (std::size_t i = 0; i < loops[id].size(); ++i) {
                owner[loops[id][i]] = to;
                at[loops[id][i]] = std::uint32_t(i);
            }
        }
    }
    return loops;
}

// Every pinch of contour k, the cut leaving the largest smaller loop first.
std::vector<Pinch> pinchesOf(const std::vector<Outline>& contours, const EdgeGrid& grid, std::size_t k, double width)
{
    std::vector<Pinch> pinches;
    const Outline& q = contours[k];
    const std::size_t n = q.size();
    for (std::size_t i = 0; i < n; ++i) {
        grid.forEdgesNear(q[i], q[i], [&](EdgeGrid::Edge e) {
            const std::size_t j = e.from;
            if (e.contour != k || j == i || after(j, n) == i)
                return;
            const Vec2 p = q[i], a = q[j], b = q[after(j, n)];
            // Most edges of the cell are far: their widened boxes leave them out before any distance.
            if (p.x < std::min(a.x, b.x) - width || p.x > std::max(a.x, b.x) + width ||
                p.y < std::min(a.y, b.y) - width || p.y > std::max(a.y, b.y) + width ||
                squaredDistanceToSegment(p, a, b) >= width * width)
                return;
            const std::size_t loop = (j + n - i) % n + 1;
            pinches.push_back({i, j, std::min(loop, n - loop)});
        });
    }
    std::stable_sort(pinches.begin(), pinches.end(),
                     [](const Pinch& a, const Pinch& b) { return a.smallerLoop > b.smallerLoop; });
    return pinches;
}

// Each contour's pinch width: pinchSpacings single-precision spacings of its largest coordinate.
std::vector<double> pinchWidths(const std::vector<Outline>& contours)
{
    std::vector<double> widths;
    for (const Outline& c : contours) {
        double largest = 0.0;
        for (Vec2 p : c)
            largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
        widths.push_back(pinchSpacings * double(FLT_EPSILON) * largest);
    }
    return widths;
}

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

// Where vertex i of contour k goes to stand at least the pinch width off every other contour near
// it: pushed straight away from each such contour's nearest edge by what it lacks (one push per
// contour, however many of its short edges lie within reach), the sum at most one width long.
// Itself where nothing is that near, or where it lies on another contour (which side it belongs on
// is then unknown).
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
    grid.forEdgesNear(p, p, [&](EdgeGrid::Edge e) {
        if (e.contour == k)
            return;
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
        const auto same = std::find_if(near.begin(), near.end(), [&](const Nearest& n) { return n.contour == e.contour; });
        if (same == near.end())
            near.push_back({e.contour, distance, nearest, width});
        else if (distance < same->distance)
            *same = {e.contour, distance, nearest, width};
    });
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

// A position as it will be kept: on a device, in single precision, which is then what is checked.
Vec2 stored(Vec2 p, bool singlePrecision)
{
    return singlePrecision ? Vec2(float(p.x), float(p.y)) : p;
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

} // namespace

bool pinchCheckDue(double t0, double t1)
{
    return std::floor(t1 / pinchCheckPeriod) > std::floor(t0 / pinchCheckPeriod);
}

std::vector<ContourCut> findCuts(const std::vector<Outline>& contours)
{
    const std::vector<double> widths = pinchWidths(contours);
    std::vector<ContourCut> cuts;
    if (contours.empty())
        return cuts;
    const EdgeGrid grid(contours, widths);
    for (std::size_t k = 0; k < contours.size(); ++k) {
        const double width = widths[k];
        const std::vector<Pinch> pinches = pinchesOf(contours, grid, k, width);
        if (pinches.empty())
            continue;
        std::vector<std::vector<std::uint32_t>> loops = loopsAfterCuts(contours, grid, k, pinches, width);
        if (loops.size() == 1)
            continue;
        ContourCut& cut = cuts.emplace_back();
        cut.contour = k;
        cut.cuts = loops.size() - 1;
        for (std::vector<std::uint32_t>& loop : loops)
            if (!tooThinToShow(contours[k], loop, width)) {
                Polygon polygon;
                for (std::uint32_t i : loop)
                    polygon.push_back(contours[k][i]);
                cut.kept.push_back({std::move(loop), signedArea(polygon)});
            }
    }
    return cuts;
}

std::vector<double> sharedTargets(double target, const std::vector<Loop>& kept)
{
    double area = 0.0, size = 0.0;
    for (const Loop& loop : kept) {
        area += loop.area;
        size += std::abs(loop.area);
    }
    std::vector<double> targets;
    for (const Loop& loop : kept)
        targets.push_back(loop.area +
                          (target - area) * (size > 0.0 ? std::abs(loop.area) / size : 1.0 / double(kept.size())));
    return targets;
}

std::size_t cutPinches(std::vector<Contour>& contours)
{
    std::vector<Outline> outlines;
    outlines.reserve(contours.size());
    for (const Contour& c : contours)
        outlines.emplace_back(c.positions);
    const std::vector<ContourCut> cuts = findCuts(outlines);
    if (cuts.empty())
        return 0;
    std::size_t made = 0;
    std::vector<Contour> next;
    next.reserve(contours.size() + cuts.size());
    auto cut = cuts.begin();
    for (std::size_t k = 0; k < contours.size(); ++k) {
        if (cut == cuts.end() || cut->contour != k) {
            next.push_back(std::move(contours[k]));
            continue;
        }
        const Contour& c = contours[k];
        const bool withPrevious = c.previous.size() == c.positions.size();
        const std::vector<double> targets = sharedTargets(c.targetArea, cut->kept);
        for (std::size_t l = 0; l < cut->kept.size(); ++l) {
            Contour& piece = next.emplace_back();
            piece.region = c.region;
            piece.targetArea = targets[l];
            for (std::uint32_t i : cut->kept[l].vertices) {
                piece.positions.push_back(c.positions[i]);
                if (withPrevious)
                    piece.previous.push_back(c.previous[i]);
                piece.spacing.push_back(c.spacing[i]);
            }
        }
        made += cut->cuts;
        ++cut;
    }
    contours = std::move(next);
    return made;
}

std::vector<VertexMove> findSeparations(const std::vector<Outline>& contours, bool singlePrecision)
{
    std::vector<VertexMove> moves;
    if (contours.empty())
        return moves;
    const std::vector<double> widths = pinchWidths(contours);
    // Boxes twice as wide: an edge whose ends have moved (a width at most) is still found.
    std::vector<double> reach(widths.size());
    std::transform(widths.begin(), widths.end(), reach.begin(), [](double w) { return 2.0 * w; });
    const EdgeGrid grid(contours, reach);
    // Where each vertex would go, from the positions before any move; then, in turn, the moves that
    // stay clean of the contours as moved so far.
    std::vector<VertexMove> wanted;
    for (std::size_t k = 0; k < contours.size(); ++k)
        for (std::size_t i = 0; i < contours[k].size(); ++i)
            if (const Vec2 to = stored(separated(contours, grid, widths, k, i), singlePrecision); to != contours[k][i])
                wanted.push_back({std::uint32_t(k), std::uint32_t(i), to});
    if (wanted.empty())
        return moves;
    std::vector<std::vector<Vec2>> moved;
    moved.reserve(contours.size());
    for (const Outline& c : contours)
        moved.emplace_back(c.begin(), c.end());
    for (const VertexMove& m : wanted)
        if (moveIsClean(moved, grid, m.contour, m.vertex, m.to)) {
            moved[m.contour][m.vertex] = m.to;
            moves.push_back(m);
        }
    return moves;
}

void moveVertices(std::vector<Contour>& contours, const std::vector<VertexMove>& moves)
{
    for (const VertexMove& m : moves) {
        Contour& c = contours[m.contour];
        const std::size_t n = c.positions.size();
        // The shoelace area changes by ½·d × (v_{i+1} − v_{i−1}) when v_i alone moves by d.
        const Vec2 d = m.to - c.positions[m.vertex];
        const Vec2 across = c.positions[after(m.vertex, n)] - c.positions[(m.vertex + n - 1) % n];
        c.targetArea += 0.5 * (d.x * across.y - d.y * across.x);
        c.positions[m.vertex] = m.to;
    }
}

std::size_t separateLayers(std::vector<Contour>& contours)
{
    std::vector<Outline> outlines;
    outlines.reserve(contours.size());
    for (const Contour& c : contours)
        outlines.emplace_back(c.positions);
    const std::vector<VertexMove> moves = findSeparations(outlines);
    moveVertices(contours, moves);
    return moves.size();
}

} // namespace vf::sim
