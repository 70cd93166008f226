#include "sim/CrossedChords.h"

#include "sim/Crossings.h"

#include <algorithm>

namespace vf::sim {

namespace {

bool preImagesCross(const std::vector<Contour>& contours, const EdgeCrossing& x)
{
    const auto edge = [&](std::size_t k, std::size_t i) {
        const std::vector<Vec2>& p = contours[k].previous;
        return std::pair(p[i], p[(i + 1) % p.size()]);
    };
    const auto [a, b] = edge(x.polygonA, x.edgeA);
    const auto [c, d] = edge(x.polygonB, x.edgeB);
    return properlyCross(a, b, c, d);
}

// Inserts a vertex into each of `edges` (sorted, distinct) of c: at the crease inside the edge's
// pre-image where there is one, else at its middle, moved by the motion.
void splitEdges(Contour& c, const std::vector<std::size_t>& edges, const ExactMotion& motion, bool floatPositions)
{
    const std::size_t n = c.positions.size();
    Contour out;
    out.region = c.region;
    out.targetArea = c.targetArea;
    for (std::vector<Vec2>* v : {&out.positions, &out.previous})
        v->reserve(n + edges.size());
    out.spacing.reserve(n + edges.size());
    auto split = edges.begin();
    for (std::size_t i = 0; i < n; ++i) {
        out.positions.push_back(c.positions[i]);
        out.previous.push_back(c.previous[i]);
        out.spacing.push_back(c.spacing[i]);
        if (split == edges.end() || *split != i)
            continue;
        ++split;
        const std::size_t j = (i + 1) % n;
        const Vec2 a = c.previous[i], b = c.previous[j];
        std::optional<double> s = motion.crease ? motion.crease(a, b) : std::nullopt;
        if (!s || !(*s > 0.0 && *s < 1.0))
            s = 0.5;
        // Only the position is rounded for a device: a pre-image rounded too would, once its chord
        // is a float spacing long, be one of its ends, and the rounds would stop closing in.
        const Vec2 start = a + *s * (b - a);
        out.positions.push_back(storedPosition(motion.map(start), floatPositions));
        out.previous.push_back(start);
        out.spacing.push_back(std::min(c.spacing[i], c.spacing[j]));
    }
    c = std::move(out);
}

} // namespace

std::size_t splitCrossedChords(std::vector<Contour>& contours, const ExactMotion& motion, bool floatPositions)
{
    std::size_t inserted = 0;
    std::vector<const Polygon*> outlines;
    std::vector<std::vector<std::size_t>> edges(contours.size());
    for (int round = 0; round < maxCrossedChordRounds; ++round) {
        outlines.clear();
        for (const Contour& c : contours)
            outlines.push_back(&c.positions);
        bool any = false;
        for (const EdgeCrossing& x : findCrossings(outlines)) {
            if (preImagesCross(contours, x))
                continue;
            edges[x.polygonA].push_back(x.edgeA);
            edges[x.polygonB].push_back(x.edgeB);
            any = true;
        }
        if (!any)
            break;
        for (std::size_t k = 0; k < contours.size(); ++k) {
            std::vector<std::size_t>& e = edges[k];
            if (e.empty())
                continue;
            std::sort(e.begin(), e.end());
            e.erase(std::unique(e.begin(), e.end()), e.end());
            splitEdges(contours[k], e, motion, floatPositions);
            inserted += e.size();
            e.clear();
        }
    }
    return inserted;
}

} // namespace vf::sim
