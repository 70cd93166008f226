#pragma once
// An ink drop's push, the exact map of a marbling drop (Lu, Jaffer et al., "Mathematical
// Marbling", IEEE CG&A 2012): every point P outside the drop moves to C + (P − C)·√(1 + r²/|P − C|²),
// which makes room for a disc of radius r at C and keeps every area outside it.
#include "sim/Geometry.h"

namespace vf::sim {

struct DropPush {
    Vec2 centre{0.0};
    double radius = 0.0;

    Vec2 operator()(Vec2 p) const;
};

} // namespace vf::sim
