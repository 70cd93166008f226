#pragma once
// The geometry of one imported SVG element before flattening: closed subpaths of lines, cubic
// Béziers and elliptical arcs. Every piece is closed under affine maps (an arc stays an arc), so
// transforms and the fit to the canvas are applied exactly and curves are flattened only once, at
// the final scale, where `spacing` is measured. Internal to SvgImport.
#include "sim/Geometry.h"

#include <QTransform>

#include <vector>

namespace vf::model::svg {

using sim::Vec2;

// An elliptical arc as center + u·cos(θ) + v·sin(θ) for θ from theta0 to theta0 + sweep; u and v
// need not be perpendicular, which is what keeps the form exact under skews.
struct Arc {
    Vec2 center, u, v;
    double theta0 = 0.0, sweep = 0.0;
};

// One piece from the previous end point: a line to `end`, a cubic through `control1`, `control2`
// to `end`, or an arc (whose end is arc's own).
struct Segment {
    enum class Kind { Line, Cubic, Arc };
    Kind kind = Kind::Line;
    Vec2 control1, control2, end;
    Arc arc;
};

// Closed, whether or not the source said Z: an open subpath is filled as if closed, as in SVG.
struct Subpath {
    Vec2 start;
    std::vector<Segment> segments;
};

using Outline = std::vector<Subpath>;

void transform(Outline& outline, const QTransform& matrix);

// An upper bound on the vertices flatten() creates (control polygon lengths bound curve lengths).
double vertexBound(const Outline& outline, double spacing);

// One closed polyline per subpath: its corners, and points along each curve at equal arc length
// (at most about spacing apart) evaluated on the true curve. Lines are left whole, and repeated
// points, orientation and degeneracy to startingContour().
std::vector<sim::Polygon> flatten(const Outline& outline, double spacing);

} // namespace vf::model::svg
