#pragma once
// Layers between two contours thinner than positions resolve, widened (past the paper;
// docs/method.md, "Topology"). Such a layer cannot be cut as one contour's is (sim/Pinches): its two
// sides bound different regions. Left thinner than chords and positions resolve, a later push or
// area correction carries one side across the other; at the pinch width it is still far thinner
// than a picture shows.
#include "sim/EdgeGrid.h"
#include "sim/Tracking.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vf::sim {

// Where a vertex comes within the pinch width (sim/Pinches.h) of an edge of another contour, it is
// moved straight away from that edge to the width (at most one width in all), if no other part of its
// own contour is that near, as far along that move (all of it, half, a quarter…) as its two edges,
// so moved, meet no other edge (exact predicates) and it comes no nearer other ink.
struct VertexMove {
    std::uint32_t contour = 0, vertex = 0;
    Vec2 to{0.0};
};
// With `singlePrecision` the moves are to positions a float holds (a device's), checked as such.
// `within`: only the vertices inside that window move (checked against every edge they could meet).
std::vector<VertexMove> findSeparations(const std::vector<Outline>& contours, bool singlePrecision = false,
                                        std::optional<Window> within = std::nullopt);
// Moves vertex i of the ring to `to`; returns how much the ring's shoelace area changed.
double moveVertex(std::span<Vec2> ring, std::size_t i, Vec2 to);
// The moves made, in order, each contour's area target following its area: the ink pressed out of
// a layer thinner than the width is given up, so the area correction does not move the contour
// back (it would move all of it, toward other ink too).
void moveVertices(std::vector<Contour>& contours, const std::vector<VertexMove>& moves);
// findSeparations on `contours`, the moves made by moveVertices. Returns how many vertices moved.
std::size_t separateLayers(std::vector<Contour>& contours, std::optional<Window> within = std::nullopt);

} // namespace vf::sim
