#include "model/TextOutlines.h"

#include "model/StartingContour.h"

#include <QPainterPath>
#include <QTransform>

#include <optional>

namespace vf::model {
namespace {

// Glyphs are outlined at this pixel size and then scaled down: QPainterPath flattens curves to a
// fixed tolerance of about half a unit, so a large em keeps that error far below any spacing.
// 2048 is the em of most TrueType fonts (DejaVu among them): their outlines come out unrounded.
constexpr int kOutlinePixelSize = 2048;

} // namespace

std::vector<sim::Polygon> textContours(const QString& text, const QFont& font, sim::Vec2 baselineStart, double emHeight, double spacing)
{
    QFont outlineFont = font;
    outlineFont.setPixelSize(kOutlinePixelSize);
    outlineFont.setHintingPreference(QFont::PreferNoHinting);

    QPainterPath path;
    path.addText(0.0, 0.0, outlineFont, text);
    // simplified() merges overlapping glyph parts (accents, ligatures, script fonts) into
    // contours that do not cross: the engine starts from simple contours only.
    const QPainterPath merged = path.simplified();

    const double scale = emHeight / kOutlinePixelSize;
    const QTransform toCanvas(scale, 0.0, 0.0, scale, baselineStart.x, baselineStart.y);
    std::vector<sim::Polygon> contours;
    for (const QPolygonF& polygon : merged.toSubpathPolygons(toCanvas)) {
        sim::Polygon polyline;
        polyline.reserve(static_cast<std::size_t>(polygon.size()));
        for (const QPointF& p : polygon)
            polyline.emplace_back(p.x(), p.y());
        if (std::optional<sim::Polygon> contour = startingContour(polyline, spacing))
            contours.push_back(std::move(*contour));
    }
    return contours;
}

} // namespace vf::model
