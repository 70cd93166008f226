#pragma once
// A comb (rake) of parallel tines drawn across the tray, as the exact, area-preserving map of
// Lu, Jaffer et al., "Mathematical Marbling" (IEEE CG&A 2012): every point moves along the stroke
// by z·u/(d + u) for each tine, d its distance to the tine's line, z the stroke's length, u the
// sharpness. A shear along the stroke's direction that depends only on the distance across it:
// its Jacobian is 1 (area kept), it moves no point across a tine's line, and the stroke drawn back
// (from and to swapped) undoes it exactly.
#include "sim/Geometry.h"

#include <optional>

namespace vf::sim {

struct Comb {
    Vec2 from{0.0}, to{0.0};
    int tines = 1;
    double spacing = 0.0;    // between neighbouring tines, canvas units
    double sharpness = 0.0;  // u, canvas units: the distance at which a tine's pull has halved

    // M = (to − from)/|to − from| and z = |to − from|; tine k (k = 0 … tines − 1) is the line
    // through from + (k − (tines − 1)/2)·spacing·n along M, n = M turned +90°.
    Vec2 operator()(Vec2 p) const;
    Comb inverse() const { return Comb{to, from, tines, spacing, sharpness}; }
    // Where tine k starts (on the line through `from` across the stroke).
    Vec2 tineStart(int k) const;
    // Where the segment a–b crosses a tine's line, the one crossing nearest its middle, as a
    // fraction along it: the map is not smooth there (d has a corner).
    std::optional<double> tineCrossing(Vec2 a, Vec2 b) const;
};

} // namespace vf::sim
