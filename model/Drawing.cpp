#include "model/Drawing.h"

namespace vf::model {

Drawing drawingOf(const Canvas& canvas, const RegionTable& looks, const std::vector<std::vector<sim::Polygon>>& geometry)
{
    Drawing d;
    d.width = canvas.width;
    d.height = canvas.height;
    d.background = canvas.background;
    for (const RegionLook& look : looks) {
        DrawnRegion region{look.name, look.color, look.visible, {}};
        if (look.simIndex >= 0 && std::size_t(look.simIndex) < geometry.size())
            region.contours = geometry[std::size_t(look.simIndex)];
        d.regions.push_back(std::move(region));
    }
    return d;
}

} // namespace vf::model
