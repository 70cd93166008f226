#pragma once
// The `d` attribute of <path>: every command of SVG 1.1 (M L H V C S Q T A Z, absolute and
// relative, implicit repeats) into an Outline in the path's own user units. Internal to SvgImport.
#include "model/SvgOutline.h"

#include <QString>
#include <QStringView>

#include <optional>

namespace vf::model::svg {

// Where SVG would render up to an error, we refuse the whole path: a half-imported logo is worse
// than a clear message. `reason` quotes the offending text.
std::optional<Outline> parsePathData(QStringView d, QString& reason);

// An SVG endpoint-parameterised arc (SVG 1.1 implementation notes F.6.5, F.6.6) from `from` to
// `to`: radii, x-axis rotation in degrees, large-arc and sweep flags. A line when a radius is zero;
// nothing when the end points coincide.
std::optional<Segment> arcSegment(Vec2 from, Vec2 radii, double rotationDegrees, bool largeArc, bool sweep, Vec2 to);

} // namespace vf::model::svg
