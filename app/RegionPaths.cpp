#include "app/RegionPaths.h"

namespace vf::app {

void RegionPaths::setView(std::shared_ptr<const model::Frame> frame, const PixelMapping& toDevice,
                          const QRectF& visible)
{
    if (frame == m_frame && toDevice == m_toDevice && visible == m_visible)
        return;
    m_frame = std::move(frame);
    m_toDevice = toDevice;
    m_visible = visible;
    m_regions.assign(m_frame ? m_frame->regions.size() : 0, Region{});
}

const QPainterPath& RegionPaths::region(std::size_t simIndex)
{
    std::optional<QPainterPath>& path = m_regions.at(simIndex).path;
    if (path)
        return *path;
    path.emplace();
    path->setFillRule(Qt::OddEvenFill);
    QPolygonF kept;
    for (const sim::Polygon& contour : m_frame->regions[simIndex]) {
        decimateContour(contour, m_toDevice, kLodTolerance, m_visible, kept);
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
