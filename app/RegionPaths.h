#pragma once
// The frame's regions as device-pixel paths for one view of the canvas, decimated to the pixels
// (ContourLod.h) and kept until the frame or the zoom changes, so a repaint without a change (an
// overlay toggled, a colour edited, a preview circle dragged) rebuilds nothing, and neither does
// panning: the paths are built without the view's shift, over the view and one view's width and
// height around it, and drawn shifted (decimation does not depend on where the canvas sits, only
// on its scale), so a pan rebuilds them only when it leaves that area.
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
    // Drops the paths when the frame or the scale differ from the last call, or the view leaves
    // the area they were built for; the vertices whenever any of the three differ.
    void setView(std::shared_ptr<const model::Frame> frame, const PixelMapping& toDevice,
                 const QRectF& visible);

    // One even-odd path of all the region's contours, in device pixels less shift(); built on
    // first use. simIndex must be valid.
    const QPainterPath& region(std::size_t simIndex);
    // What to add to region()'s points: the view's shift, device pixels.
    QPointF shift() const { return {m_toDevice.dx, m_toDevice.dy}; }

    // The region's vertices inside the view (device pixels), or nothing when there are more
    // than `cap` of them; built on first use.
    const std::optional<QPolygonF>& vertices(std::size_t simIndex, std::size_t cap);

private:
    std::shared_ptr<const model::Frame> m_frame;
    PixelMapping m_toDevice;
    QRectF m_visible;
    QRectF m_pathArea;  // what the paths were built for, device pixels less the shift
    // By simulation region. Built vertices left empty: over the cap.
    struct Region {
        std::optional<QPainterPath> path;
        bool verticesBuilt = false;
        std::optional<QPolygonF> vertices;
    };
    std::vector<Region> m_regions;
};

} // namespace vf::app
