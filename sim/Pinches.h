#pragma once
// Contour surgery where a layer of ink has thinned below what positions resolve (past the paper;
// docs/method.md, "Topology"). Flow toward a free-slip wall thins a layer exponentially, and
// once its two sides come within a few single-precision spacings of each other, rounding alone can
// make them cross. Such a layer is far thinner than anything a picture shows, so it is cut there
// instead: the contour is split into two loops at the pinch, and a loop too thin to show is dropped.
#include "sim/EdgeGrid.h"
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

// The contours' positions, as the searches take them.
std::vector<Outline> outlinesOf(const std::vector<Contour>& contours);

// Each contour's pinch width: pinchSpacings single-precision spacings of its largest coordinate.
std::vector<double> pinchWidths(const std::vector<Outline>& contours);

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
// or with fewer than three vertices, is dropped and takes no more cuts. The search's grid lives in
// `scratch`, which a caller checking again and again keeps.
std::vector<ContourCut> findCuts(const std::vector<Outline>& contours, EdgeGrid::Storage& scratch);

// The area targets of a cut contour's kept loops: what the contour's target asks beyond their
// present areas goes to each in proportion to its size, so the region keeps its ink.
std::vector<double> sharedTargets(double target, const std::vector<Loop>& kept);

// findCuts on `contours`, each cut contour replaced by its kept loops, which keep their vertices'
// previous positions and spacing. Returns how many cuts were made.
std::size_t cutPinches(std::vector<Contour>& contours, EdgeGrid::Storage& scratch);

} // namespace vf::sim
