#pragma once
// Exact tests of whether contours cross: the topology the engine promises to keep (contours never
// cross themselves or each other) and what a scene or an imported shape may start from.
#include "sim/Geometry.h"

#include <cstddef>
#include <limits>
#include <vector>

namespace vf::sim {

// The sign of the turn a → b → c: +1 counter-clockwise in raw coordinates, −1 clockwise, 0 when the
// three points are collinear. Exact for every finite double input (a floating-point filter, and
// exact expansion arithmetic when the filter cannot decide), so a crossing is never missed or
// invented by rounding.
int orientation(Vec2 a, Vec2 b, Vec2 c);
// Whether segments a–b and c–d properly cross: at one point, each end of either strictly on one
// side of the other (exact, through orientation).
bool properlyCross(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

// Two edges whose interiors cross at one point, each on either side of the other (touching and
// collinear overlaps are not proper crossings).
struct EdgeCrossing {
    std::size_t polygonA = 0, edgeA = 0;  // edge i runs from vertex i to vertex i + 1 (wrapping)
    std::size_t polygonB = 0, edgeB = 0;
    Vec2 point{0.0};                      // where they cross (rounded)
};

// Every pair of edges that properly cross, over all given polygons together (edges of one polygon
// count too, except neighbours sharing a vertex), at most `limit` of them, ordered by polygon and
// edge. Uses a uniform segment grid: about linear in the number of edges where they are spread
// out, quadratic where thousands lie within one cell (isSimple does not share that limit).
std::vector<EdgeCrossing> findCrossings(const std::vector<const Polygon*>& polygons,
                                        std::size_t limit = std::numeric_limits<std::size_t>::max());
// The same over outlines where they lie (no copy of the vertices).
std::vector<EdgeCrossing> findOutlineCrossings(const std::vector<Outline>& outlines,
                                               std::size_t limit = std::numeric_limits<std::size_t>::max());
std::size_t countCrossings(const std::vector<const Polygon*>& polygons);

// No two edges cross or touch: besides proper crossings, no vertex lies on a non-neighbouring
// edge (a figure eight pinched at a point, a repeated vertex) and no edge folds back onto its
// neighbour. What a scene may start from.
bool isSimple(const Polygon& polygon);
// The same over several polygons together: each simple, and no two of them touching or crossing,
// as the contours of one imported shape must be. A sweep line (sim/Simplicity.cpp): n log n in the
// edges whatever their layout, and it stops at the first contact.
bool isSimple(const std::vector<const Polygon*>& polygons);

} // namespace vf::sim
