#pragma once
// The frame's regions as device-pixel paths for one view of the canvas, decimated to the pixels
// (ContourLod.h) and kept until the frame or the view changes, so a repaint without a change
// (an overlay toggled, a colour edited, a preview circle dragged) rebuilds nothing.
#include "app/ContourLod.h"
#include "model/Frame.h"

#include <QPainterPath>
#include <QPolygonF>

#include <memory>
#include <optional>
#include <vector>

namespace vf::app {

class RegionPaths {
public:
    // Drops what was built when any of the three differ from the last call.
    void setView(std::shared_ptr<const model::Frame> frame, const PixelMapping& toDevice,
                 const QRectF& visible);

    // One even-odd path of all the region's contours; built on first use. simIndex must be valid.
    const QPainterPath& region(std::size_t simIndex);

    // The region's vertices inside the view (device pixels), or nothing when there are more
    // than `cap` of them; built on first use.
    const std::optional<QPolygonF>& vertices(std::size_t simIndex, std::size_t cap);

private:
    std::shared_ptr<const model::Frame> m_frame;
    PixelMapping m_toDevice;
    QRectF m_visible;
    // By simulation region. Built vertices left empty: over the cap.
    struct Region {
        std::optional<QPainterPath> path;
        bool verticesBuilt = false;
        std::optional<QPolygonF> vertices;
    };
    std::vector<Region> m_regions;
};

} // namespace vf::app
