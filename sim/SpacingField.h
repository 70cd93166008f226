#pragma once
// The adaptive vertex spacing d_i of paper §3.3.
#include "sim/Flow.h"
#include "sim/PhaseClock.h"
#include "sim/ProximityGrid.h"
#include "sim/Tracking.h"

namespace vf::sim {

// The normalised Gaussian window of eq. 6 over 2·radius + 1 vertices, σ = radius / 2.
std::vector<double> gaussianWeights(int radius);

// Discrete curvature at vertex i (1/length): the Menger curvature of it and its two neighbours.
double discreteCurvature(Vec2 before, Vec2 at, Vec2 after);

// d_i is kept to this many bits after its significand's binary point (steps of at most 0.1 %). It is
// a length the splits and collapses aim at, and its lower bits are only the smoothing's rounding;
// rounded, neighbouring spacings share their bits, so saved states pack them to a fraction of a byte
// each (docs/project-format.md), where full doubles took about 40 % of a project. Both backends.
constexpr int spacingFractionBits = 10;

// `d` (positive, finite) rounded to the nearest value with spacingFractionBits fraction bits.
double roundedSpacing(double d);

// Fills every contour's `spacing` for the flow at time t:
//   d_i = d_max · exp(-|κ_i|·Lκ) · exp(-|ω(v_i)|/ω_ref) · (1 - exp(-dist_i/Lp)) + ε    (eqs. 3, 4, 5, 7)
// then smooths d_i along the contour with a Gaussian window (eq. 6), and rounds it
// (roundedSpacing). In uniform mode d_i = d_max.
// `grid` is scratch storage reused between calls; `clock`, if any, is charged the proximity search
// and the rest apart.
void computeSpacing(std::vector<Contour>& contours, const Flow& flow, double t,
                    const TrackingSettings& settings, ProximityGrid& grid, PhaseClock* clock = nullptr);

} // namespace vf::sim
