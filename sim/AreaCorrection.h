#pragma once
// Optional exact area preservation of a contour (past the paper; docs/method.md, "Area correction").
#include "sim/Geometry.h"

namespace vf::sim {

// Moves every vertex along the gradient of the polygon's area with respect to that vertex,
// g_i = ½·J·(v_{i+1} − v_{i−1}) (J a quarter turn), by the same factor λ:  v_i ← v_i + λ·g_i.
// The area is quadratic in λ, A(λ) = A + λ·Σ|g_i|² + λ²·A(g), so λ is solved for exactly and the
// contour meets `targetArea` to rounding. The displacement is normal to the contour and scales
// with the local edge length, so it is a uniform offset of the curve that moves no feature.
void correctArea(Polygon& polygon, double targetArea);

} // namespace vf::sim
