#pragma once
// Outlines from outside the engine (SVG shapes, glyphs) as starting contours, the one cleanup both
// importers share.
#include "sim/Geometry.h"

#include <optional>

namespace vf::model {

// The closed polyline with repeated vertices merged (closer than a tiny fraction of spacing, as
// flattening and transforms leave them), turned to positive sim::signedArea and resampled so that
// no edge is longer than spacing. Nothing when it encloses nothing: fewer than 3 distinct vertices,
// or all of them on one line. A polyline that crosses itself is returned as it is, crossing (a bow
// tie has zero signed area but is no degenerate line), for the caller to refuse by name.
std::optional<sim::Polygon> startingContour(const sim::Polygon& closedPolyline, double spacing);

} // namespace vf::model
