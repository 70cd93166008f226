#pragma once
// Filled shapes of an SVG file as ink regions (docs/svg-import.md).
//
// Read: <path> (all of SVG 1.1's path commands), <polygon>, <rect> (with rounded corners),
// <circle> and <ellipse>, inside nested <g> and <a>, with the transform attribute on every element
// and the fill colour from attributes or style="", inherited through groups. <defs>, <clipPath>,
// <mask>, <symbol> and the like are not drawn, so their content is not imported either. Open shapes
// (<polyline>, <line>), <use>, <text>, <image> and fill="none" elements are skipped with a warning.
//
// Mapping: the document's viewBox (or, without one, 0 0 width height in px) is scaled uniformly to
// fit the canvas [0, width] x [0, height] and centred there (preserveAspectRatio is ignored: always
// "xMidYMid meet"). Curves are flattened in canvas units so that no edge is longer than `spacing`,
// with every vertex on the true curve.
//
// Each element becomes one shape: one contour per subpath (open subpaths are closed, as SVG fills
// them), filled together even-odd like every region, each contour with positive sim::signedArea.
// Subpaths with fewer than 3 distinct points or no area are dropped. A shape whose contours cross
// themselves or each other is refused: the engine starts from simple contours only.
#include "sim/Geometry.h"

#include <QByteArray>
#include <QColor>
#include <QString>
#include <QStringList>

#include <vector>

namespace vf::model {

struct ImportedShape {
    QString name;  // the element's id, else "<tag> N" (the N-th such element of the file)
    QColor color;  // with fill-opacity and opacity in the alpha
    std::vector<sim::Polygon> contours;
};

struct SvgImport {
    std::vector<ImportedShape> shapes;  // in document order: bottom to top
    QStringList warnings;               // one line each, what was skipped and why
    QString error;                      // one line "<source>: [line:col: ]what is wrong"; then no shapes
    bool ok() const { return error.isEmpty(); }
};

// sourceName prefixes messages (a file name). canvasWidth, canvasHeight and spacing must be positive.
SvgImport importSvg(const QByteArray& svg, const QString& sourceName, double canvasWidth, double canvasHeight, double spacing);
// The same from a file, named in messages by its file name without the folder.
SvgImport importSvgFile(const QString& path, double canvasWidth, double canvasHeight, double spacing);

} // namespace vf::model
