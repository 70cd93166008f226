#pragma once
// How the document shows the simulation's regions: a name, a colour, visibility and paint order
// per region. The simulation only knows region indices; this table is what the Regions dock edits.
#include <QColor>
#include <QString>

#include <vector>

namespace vf::model {

struct RegionLook {
    QString name;   // unique within a document (it becomes an SVG id and layer label)
    QColor color;
    bool visible = true;
    int simIndex = 0;  // the simulation region whose contours this shows

    friend bool operator==(const RegionLook&, const RegionLook&) = default;
};

// Paint order: bottom to top.
using RegionTable = std::vector<RegionLook>;

} // namespace vf::model
