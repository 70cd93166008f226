#pragma once
// Piecewise cubic Bézier fitting of closed polygons (Schneider, "An Algorithm for Automatically
// Fitting Digitized Curves", Graphics Gems, 1990), with corner detection and a two-sided error
// bound: every vertex lies within `tolerance` of the curve and every point of the curve lies within
// `tolerance` of the polyline, so the fit can be trusted as a compact stand-in for the geometry.
#include "sim/Geometry.h"

#include <vector>

namespace vf::render {

struct PathSegment {
    bool isLine = false;  // a straight piece: only `end` is meaningful
    sim::Vec2 control1{};
    sim::Vec2 control2{};
    sim::Vec2 end{};  // always a vertex of the input polygon
};

struct FittedContour {
    sim::Vec2 start{};
    std::vector<PathSegment> segments;  // consecutive; the last one ends at `start`
};

// Consecutive duplicate vertices are ignored. Polygons with fewer than three distinct vertices come
// back as straight segments; an empty polygon gives no segments.
FittedContour fitClosedPolygon(const sim::Polygon& polygon, double tolerance);

} // namespace vf::render
