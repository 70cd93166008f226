#pragma once
// What the exporters draw: a finished picture, decoupled from how it was computed.
#include "model/Regions.h"
#include "model/Scene.h"
#include "sim/Geometry.h"

#include <QColor>
#include <QString>

#include <vector>

namespace vf::model {

struct DrawnRegion {
    QString name;
    QColor color;
    bool visible = true;
    std::vector<sim::Polygon> contours;  // filled together with the even-odd rule
};

struct Drawing {
    double width = 1.0;   // canvas units
    double height = 1.0;
    QColor background = QColor(255, 255, 255);
    std::vector<DrawnRegion> regions;  // bottom to top
};

// The picture of `geometry` (contours per simulation region) on `canvas`, each region drawn with
// its look, in the table's order; a look whose region the geometry lacks is drawn empty.
Drawing drawingOf(const Canvas& canvas, const RegionTable& looks, const std::vector<std::vector<sim::Polygon>>& geometry);

} // namespace vf::model
