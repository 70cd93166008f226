#pragma once
// Optional exact area preservation of a contour (past the paper; docs/method.md, "Area correction").
#include "sim/Geometry.h"

#include <vector>

namespace vf::sim {

// Offsets the contour uniformly along its normals by the distance λ that makes its area `targetArea`:
// v_i ← v_i + λ·u_i, u_i = g_i / max(|g_i|, shortEdge), g_i = ½·J·(v_{i+1} − v_{i−1}) the gradient of
// the polygon's area with respect to v_i (J a quarter turn), so u_i is the unit normal but where the
// neighbours are closer than `shortEdge`, and u_i = 0 where `held[i]` (other ink lies near v_i) and
// at sharp turns (below).
// The area is quadratic in λ for any u, A(λ) = A + λ·Σ g_i·u_i + λ²·A(u), so λ is solved for
// exactly; the contour meets its target to rounding unless λ would pass `maxOffset`, when it
// moves by that and the rest waits for the next correction.
// - A uniform offset is, of all normal moves that make up an area, the one whose largest move is
//   smallest, and that move is how close other ink may come before the correction crosses it
//   (moving along g_i itself moves the vertices of long edges most, a hundred times the offset
//   where spacing varies a hundredfold).
// - Vertices between edges shorter than `shortEdge` (at a crease, a tip) move in proportion to
//   their edges instead, so an offset larger than such an edge does not fold it over.
// - A vertex where the contour turns by more than a right angle, and its two neighbours, do not
//   move (u_i = 0): there g_i is no normal of the curve. At the tip of a V that a comb's crease
//   folds, two vertices may lie a hair apart with the V's sides closer than the offset near them,
//   and moving them folds one side over the other (the two edges beside the tip cross).
void correctArea(Polygon& polygon, double targetArea, double shortEdge, const std::vector<bool>& held, double maxOffset);

} // namespace vf::sim
