#include "render/PathEmitter.h"

#include "render/BezierFit.h"

#include <cmath>

namespace vf::render {
namespace {

void emitPolyline(const sim::Polygon& contour, PathSink& sink)
{
    sink.moveTo(contour.front());
    for (std::size_t i = 1; i < contour.size(); ++i)
        sink.lineTo(contour[i]);
    sink.closePath();
}

void emitFitted(const sim::Polygon& contour, double tolerance, PathSink& sink)
{
    const FittedContour fitted = fitClosedPolygon(contour, tolerance);
    sink.moveTo(fitted.start);
    for (const PathSegment& segment : fitted.segments) {
        if (segment.isLine)
            sink.lineTo(segment.end);
        else
            sink.cubicTo(segment.control1, segment.control2, segment.end);
    }
    sink.closePath();
}

} // namespace

double defaultBezierTolerance(const model::Drawing& drawing)
{
    return 1e-4 * std::hypot(drawing.width, drawing.height);
}

PathStyle pathStyle(const model::Drawing& drawing, const ExportOptions& options)
{
    const double tolerance = options.bezierTolerance > 0 ? options.bezierTolerance
                                                         : defaultBezierTolerance(drawing);
    return {options.bezier, tolerance};
}

void emitRegion(const model::DrawnRegion& region, const PathStyle& style, PathSink& sink)
{
    for (const sim::Polygon& contour : region.contours) {
        if (contour.empty())
            continue;
        if (style.bezier)
            emitFitted(contour, style.tolerance, sink);
        else
            emitPolyline(contour, sink);
    }
}

} // namespace vf::render
