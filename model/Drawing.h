#pragma once
// What the exporters draw: a finished picture, decoupled from how it was computed.
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

} // namespace vf::model
