#pragma once
// Contour surgery where a layer of ink has thinned below what positions resolve (past the paper;
// docs/method.md, "Topology"). Flow toward a free-slip wall thins a layer exponentially, and
// once its two sides come within a few single-precision spacings of each other, rounding alone can
// make them cross. Such a layer is far thinner than anything a picture shows, so it is cut there
// instead: the contour is split into two loops at the pinch, and a loop too thin to show is dropped.
#include "sim/Tracking.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vf::sim {

// How close, in single-precision spacings of its contour's largest coordinate, a vertex must come to
// an edge of its own contour (other than its own two) to be a pinch: 64 spacings is 7.6e-6 where
// the largest coordinate is 1, a sixteenth of a pixel at 8000 pixels across a unit canvas.
inline constexpr double pinchSpacings = 64.0;

// A pinch is looked for once in every this much simulated time (seconds): a check costs a pass
// over every vertex (on a device, after reading the positions back), and a layer must thin some
// 250-fold from the pinch width (7.6e-6) to where layers crossed without the cut (about 3e-8).
// Checked this often, no session of the benchmarks has crossed (docs/BENCHMARKS.md, "Topology").
inline constexpr double pinchCheckPeriod = 0.1;
// Whether a step from t0 to t1 is due a check: it passes a multiple of the period (so a restored
// snapshot checks where the original run did).
bool pinchCheckDue(double t0, double t1);

using Outline = std::span<const Vec2>;

// One contour's loops after its cuts: the indices of their vertices, in order, and their areas.
struct Loop {
    std::vector<std::uint32_t> vertices;
    double area = 0.0;
};
struct ContourCut {
    std::size_t contour = 0;  // its index among the contours searched
    std::size_t cuts = 0;
    std::vector<Loop> kept;   // the loops thick enough to keep
};

// The cuts to make, in one pass over every vertex: contour by contour (those with a cut only, in
// order), at each of its pinches (a vertex within the pinch width, pinchSpacings single-precision
// spacings of the contour's largest coordinate, of an edge of its own contour other than its own
// two), the one leaving the largest smaller loop first (a layer's root before its length), each
// where its vertex and edge still lie in one loop and where the cut's two new edges would cross no
// edge. A loop whose mean width (twice its area over its perimeter) is under twice the pinch width,
// or with fewer than three vertices, is dropped and takes no more cuts.
std::vector<ContourCut> findCuts(const std::vector<Outline>& contours);

// The area targets of a cut contour's kept loops: what the contour's target asks beyond their
// present areas goes to each in proportion to its size, so the region keeps its ink.
std::vector<double> sharedTargets(double target, const std::vector<Loop>& kept);

// findCuts on `contours`, each cut contour replaced by its kept loops, which keep their vertices'
// previous positions and spacing. Returns how many cuts were made.
std::size_t cutPinches(std::vector<Contour>& contours);

// Layers between two contours: where a vertex comes within the pinch width of an edge of another
// contour, it is moved straight away from that edge to the width (at most one width in all), if its
// two edges, so moved, meet no other edge (exact predicates). Such a layer cannot be cut (its two
// sides bound different regions), and left thinner than positions resolve, a later push presses
// it until its sides cross; at the width it is still far thinner than a picture shows.
struct VertexMove {
    std::uint32_t contour = 0, vertex = 0;
    Vec2 to{0.0};
};
// With `singlePrecision` the moves are to positions a float holds (a device's), checked as such.
std::vector<VertexMove> findSeparations(const std::vector<Outline>& contours, bool singlePrecision = false);
// The moves made, in order, each contour's area target following its area: the ink pressed out of
// a layer thinner than the width is given up, so the area correction does not move the contour
// back (it would move all of it, toward other ink too).
void moveVertices(std::vector<Contour>& contours, const std::vector<VertexMove>& moves);
// findSeparations on `contours`, the moves made by moveVertices. Returns how many vertices moved.
std::size_t separateLayers(std::vector<Contour>& contours);

} // namespace vf::sim
