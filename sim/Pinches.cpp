#include "sim/Pinches.h"

#include "sim/Crossings.h"
#include "sim/EdgeGrid.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <thread>
#include <utility>

namespace vf::sim {

namespace {


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

// Contour k's pinches among its vertices [from, to), in their order, appended to `found` with k.
void pinchesOf(const std::vector<Outline>& contours, const EdgeGrid& grid, std::size_t k, double width,
               std::size_t from, std::size_t to, std::vector<std::pair<std::size_t, Pinch>>& found)
{
    const Outline& q = contours[k];
    const std::size_t n = q.size();
    for (std::size_t i = from; i < to; ++i) {
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
            found.push_back({k, {i, j, std::min(loop, n - loop)}});
        });
    }
}

// Every contour's pinches, the one leaving the largest smaller loop first. The search only reads,
// so the vertices of all contours are shared among threads in runs of consecutive ones (a session
// may hold a few contours of a million vertices each); each run's pinches come back in order, so
// the lists are those one thread would find. Fewer vertices than a run are searched on this one.
std::vector<std::vector<Pinch>> pinchesOfEach(const std::vector<Outline>& contours, const EdgeGrid& grid,
                                              const std::vector<double>& widths)
{
    constexpr std::size_t verticesPerRun = std::size_t(1) << 15;
    std::size_t total = 0;
    for (const Outline& q : contours)
        total += q.size();
    const std::size_t threads = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t runs = std::clamp<std::size_t>(total / verticesPerRun, 1, threads);
    std::vector<std::vector<std::pair<std::size_t, Pinch>>> found(runs);
    std::vector<std::exception_ptr> failures(runs);
    const auto search = [&](std::size_t run) {
        try {
            const std::size_t begin = total * run / runs, end = total * (run + 1) / runs;
            std::size_t first = 0;  // the run's index of contour k's vertex 0
            for (std::size_t k = 0; k < contours.size() && first < end; ++k) {
                const std::size_t from = std::max(begin, first), to = std::min(end, first + contours[k].size());
                if (from < to)
                    pinchesOf(contours, grid, k, widths[k], from - first, to - first, found[run]);
                first += contours[k].size();
            }
        } catch (...) {
            failures[run] = std::current_exception();
        }
    };
    {
        std::vector<std::jthread> helpers;
        for (std::size_t run = 1; run < runs; ++run)
            helpers.emplace_back(search, run);
        search(0);
    }
    for (const std::exception_ptr& failure : failures)
        if (failure)
            std::rethrow_exception(failure);
    std::vector<std::vector<Pinch>> pinches(contours.size());
    for (const auto& run : found)
        for (const auto& [k, pinch] : run)
            pinches[k].push_back(pinch);
    for (std::vector<Pinch>& list : pinches)
        std::stable_sort(list.begin(), list.end(),
                         [](const Pinch& a, const Pinch& b) { return a.smallerLoop > b.smallerLoop; });
    return pinches;
}

} // namespace

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


bool pinchCheckDue(double t0, double t1)
{
    return std::floor(t1 / pinchCheckPeriod) > std::floor(t0 / pinchCheckPeriod);
}

std::vector<ContourCut> findCuts(const std::vector<Outline>& contours, EdgeGrid::Storage& scratch)
{
    const std::vector<double> widths = pinchWidths(contours);
    std::vector<ContourCut> cuts;
    if (contours.empty())
        return cuts;
    const EdgeGrid grid(contours, widths, scratch);
    const std::vector<std::vector<Pinch>> pinches = pinchesOfEach(contours, grid, widths);
    for (std::size_t k = 0; k < contours.size(); ++k) {
        const double width = widths[k];
        if (pinches[k].empty())
            continue;
        std::vector<std::vector<std::uint32_t>> loops = loopsAfterCuts(contours, grid, k, pinches[k], width);
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

std::vector<Outline> outlinesOf(const std::vector<Contour>& contours)
{
    std::vector<Outline> outlines;
    outlines.reserve(contours.size());
    for (const Contour& c : contours)
        outlines.emplace_back(c.positions);
    return outlines;
}

std::size_t cutPinches(std::vector<Contour>& contours, EdgeGrid::Storage& scratch)
{
    const std::vector<ContourCut> cuts = findCuts(outlinesOf(contours), scratch);
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


} // namespace vf::sim
