#pragma once
// How SVG path data rounds coordinates: to the power of ten nearest below a millionth of the
// canvas's larger side (1e-6 on the unit canvas, 0.0006 pt on a 576 pt page), so that a polyline
// vertex takes about 18 bytes instead of the 39 of an exact double, and the outline never changes
// its topology: a vertex that rounds onto its predecessor is dropped, and a region whose rounded
// contours would cross is written exactly.
#include "model/Drawing.h"

namespace vf::render {

// 10^k for the largest integer k with 10^k <= 1e-6 * max(width, height).
double svgCoordinateStep(const model::Drawing& drawing);

// 10^k for the largest integer k with 10^k <= length (a positive length).
double decimalStepBelow(double length);

// `value` moved to the nearest multiple of `step` (a power of ten), as the double nearest that
// decimal, so its shortest text has no more decimals than the step; values coarser than the step
// (beyond 2^53 steps) stay as they are.
double roundedToStep(double value, double step);

struct RoundedRegion {
    model::DrawnRegion region;
    bool exact = false;  // the rounded contours would cross or touch: `region` is the input, unrounded
};

// Every vertex moved to the nearest multiple of `step` (the double nearest the decimal, so its
// shortest text has no more digits than the step needs), a vertex equal to its predecessor dropped
// (the last one too when it equals the first), a contour left with fewer than three vertices
// dropped. If the rounded contours cross or touch anywhere (sim::isSimple, exact), the region is
// returned as it was, with `exact` set.
RoundedRegion roundedRegion(const model::DrawnRegion& region, double step);

} // namespace vf::render
