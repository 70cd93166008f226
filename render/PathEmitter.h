#pragma once
// One walk over a region's outline, shared by every writer: the Bézier fit (or the plain polyline)
// is computed here once and each writer only translates the calls into its own path syntax.
#include "model/Drawing.h"
#include "render/Exporter.h"

namespace vf::render {

class PathSink {
public:
    virtual ~PathSink() = default;
    virtual void moveTo(sim::Vec2 point) = 0;
    virtual void lineTo(sim::Vec2 point) = 0;
    virtual void cubicTo(sim::Vec2 control1, sim::Vec2 control2, sim::Vec2 end) = 0;
    virtual void closePath() = 0;
};

struct PathStyle {
    bool bezier = true;
    double tolerance = 0;  // canvas units, already resolved (never 0 when bezier is set)
};

// 1e-4 of the canvas diagonal: on the default unit canvas 1.4e-4, about 3.5% of the default
// vertex spacing 0.004 and 0.06 pt on a 576 pt page, so the fit is invisible at any print size.
double defaultBezierTolerance(const model::Drawing& drawing);

PathStyle pathStyle(const model::Drawing& drawing, const ExportOptions& options);

// Emits every non-empty contour of the region as one closed subpath, in order.
void emitRegion(const model::DrawnRegion& region, const PathStyle& style, PathSink& sink);

} // namespace vf::render
