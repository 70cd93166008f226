#pragma once
// Text as ink: the outlines of a string's glyphs as closed contours for a region (the Text tool).
#include "sim/Geometry.h"

#include <QFont>
#include <QString>

#include <vector>

namespace vf::model {

// The glyph outlines of `text` set in `font` (its family, weight and style; its size is replaced),
// with the baseline starting at baselineStart and an em square emHeight canvas units tall. Canvas
// units, y down. Overlapping glyphs are merged, so the contours neither cross themselves nor each
// other; each has positive sim::signedArea and no edge longer than spacing, and they are meant to
// be filled together even-odd (a letter's counter is a contour of its own). Empty or blank text
// gives no contours. emHeight and spacing must be positive.
std::vector<sim::Polygon> textContours(const QString& text, const QFont& font, sim::Vec2 baselineStart, double emHeight, double spacing);

} // namespace vf::model
