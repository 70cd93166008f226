#pragma once
// A piece of the pen's path, as both backends queue and share it out over substeps.
#include "sim/Geometry.h"

namespace vf::sim {

struct StylusSegment {
    Vec2 from, to;
    double radius = 0.0;
    double duration = 0.0;

    // The k-th of n equal parts along the path and in time, for substep k of n.
    StylusSegment part(int k, int n) const
    {
        const double a = double(k) / n, b = double(k + 1) / n;
        return {from + a * (to - from), from + b * (to - from), radius, duration / n};
    }

    friend bool operator==(const StylusSegment&, const StylusSegment&) = default;
};

} // namespace vf::sim
