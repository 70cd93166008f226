#pragma once
// Level of detail for the canvas: each contour cut down to the vertices the screen's pixels can
// show, so a scene of millions of vertices draws as fast as one of the vertices it visibly needs.
#include "sim/Geometry.h"

#include <QPointF>
#include <QPolygonF>
#include <QRectF>

namespace vf::app {

// Canvas units to device pixels: the canvas view only zooms (the same on both axes) and pans.
struct PixelMapping {
    double scale = 1.0;  // device pixels per canvas unit, > 0
    double dx = 0.0;     // where the canvas origin lands, device pixels
    double dy = 0.0;

    QPointF map(sim::Vec2 p) const { return {p.x * scale + dx, p.y * scale + dy}; }
    friend bool operator==(const PixelMapping&, const PixelMapping&) = default;
};

// How far a drawn contour may stray from the true one, device pixels (see decimateContour).
inline constexpr double kLodTolerance = 0.5;

// Writes to `out` (device pixels, closed: the last vertex joins the first) a subset of the
// contour's vertices that stays within tolerance·√2 of the contour, or nothing when the contour's
// bounding box misses `visible`.
//
// Greedy, one pass: from the last kept vertex (the anchor) each following vertex narrows the cone
// of directions whose ray passes within `tolerance` of it; the run ends before the first vertex
// outside that cone or one coming back toward the anchor by more than `tolerance` (so a thin
// filament folding back on itself is never cut off at its base). Every run but the few that end at
// a forced vertex covers more than `tolerance` of contour length, so at most
// perimeter/tolerance + 4 vertices are kept, and far fewer on smooth curves: a circle of radius R
// needs about π/acos(1 − tolerance/R). The four extreme vertices (leftmost, rightmost, top,
// bottom) are always kept, so a contour's bounding box never shrinks and one smaller than a pixel
// collapses to at most four vertices instead of vanishing.
void decimateContour(const sim::Polygon& contour, const PixelMapping& toDevice, double tolerance,
                     const QRectF& visible, QPolygonF& out);

} // namespace vf::app
