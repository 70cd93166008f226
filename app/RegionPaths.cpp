#include "app/RegionPaths.h"

namespace vf::app {

void RegionPaths::setView(std::shared_ptr<const model::Frame> frame, const PixelMapping& toDevice,
                          const QRectF& visible)
{
    if (frame == m_frame && toDevice == m_toDevice && visible == m_visible)
        return;
    const QRectF unshifted = visible.translated(-toDevice.dx, -toDevice.dy);
    const bool pathsKept = frame == m_frame && toDevice.scale == m_toDevice.scale && m_pathArea.contains(unshifted);
    m_frame = std::move(frame);
    m_toDevice = toDevice;
    m_visible = visible;
    if (!pathsKept) {
        m_regions.assign(m_frame ? m_frame->regions.size() : 0, Region{});
        m_pathArea = unshifted.adjusted(-visible.width(), -visible.height(), visible.width(), visible.height());
        return;
    }
    for (Region& region : m_regions) {
        region.verticesBuilt = false;
        region.vertices.reset();
    }
}

const QPainterPath& RegionPaths::region(std::size_t simIndex)
{
    std::optional<QPainterPath>& path = m_regions.at(simIndex).path;
    if (path)
        return *path;
    path.emplace();
    path->setFillRule(Qt::OddEvenFill);
    const PixelMapping unshifted{m_toDevice.scale, 0.0, 0.0};
    QPolygonF kept;
    for (const sim::Polygon& contour : m_frame->regions[simIndex]) {
        decimateContour(contour, unshifted, kLodTolerance, m_pathArea, kept);
        if (kept.size() < 3)
            continue;  // no area to fill
        path->addPolygon(kept);
        path->closeSubpath();
    }
    return *path;
}

const std::optional<QPolygonF>& RegionPaths::vertices(std::size_t simIndex, std::size_t cap)
{
    Region& region = m_regions.at(simIndex);
    if (region.verticesBuilt)
        return region.vertices;
    region.verticesBuilt = true;
    QPolygonF dots;
    for (const sim::Polygon& contour : m_frame->regions[simIndex])
        for (const sim::Vec2& vertex : contour) {
            const QPointF p = m_toDevice.map(vertex);
            if (!m_visible.contains(p))
                continue;
            if (std::size_t(dots.size()) == cap)
                return region.vertices;
            dots.append(p);
        }
    region.vertices = std::move(dots);
    return region.vertices;
}

} // namespace vf::app
