#include "app/ContourLod.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace vf::app {
namespace {

double cross(QPointF a, QPointF b) { return a.x() * b.y() - a.y() * b.x(); }
double dot(QPointF a, QPointF b) { return a.x() * b.x() + a.y() * b.y(); }

// The directions (from the anchor) of rays that pass within the tolerance of every vertex seen
// since the anchor: the intersection of each vertex's tangent cone, narrower than π throughout.
class Cone {
public:
    explicit Cone(double tolerance) : m_tolerance(tolerance) {}

    void reset()
    {
        m_constrained = false;
        m_reach = 0.0;
    }

    // Whether the run from the anchor may end at `offset` (that vertex minus the anchor).
    bool admits(QPointF offset, double distance) const
    {
        if (distance < m_reach - m_tolerance)
            return false;  // folding back toward the anchor: the run would cut the fold off
        if (!m_constrained)
            return true;
        return cross(m_right, offset) >= 0.0 && cross(offset, m_left) >= 0.0
            && dot(offset, m_left + m_right) > 0.0;
    }

    // Narrows the cone to the rays passing within the tolerance of the vertex at `offset`.
    void include(QPointF offset, double distance)
    {
        m_reach = std::max(m_reach, distance);
        if (distance <= m_tolerance)
            return;  // every ray from the anchor passes close enough
        const QPointF u = offset / distance;
        const double s = m_tolerance / distance;  // sine of the tangent cone's half angle
        const double c = std::sqrt(1.0 - s * s);
        const QPointF left(u.x() * c - u.y() * s, u.x() * s + u.y() * c);
        const QPointF right(u.x() * c + u.y() * s, u.y() * c - u.x() * s);
        if (!m_constrained) {
            m_left = left;
            m_right = right;
            m_constrained = true;
            return;
        }
        if (cross(m_left, left) < 0.0)
            m_left = left;
        if (cross(m_right, right) > 0.0)
            m_right = right;
    }

private:
    double m_tolerance;
    bool m_constrained = false;
    double m_reach = 0.0;  // the farthest any vertex of the run got from the anchor
    QPointF m_left, m_right;
};

} // namespace

void decimateContour(const sim::Polygon& contour, const PixelMapping& toDevice, double tolerance,
                     const QRectF& visible, QPolygonF& out)
{
    out.clear();
    const std::size_t n = contour.size();
    if (n == 0)
        return;
    // The mapping only scales (by a positive factor) and shifts, so canvas extremes stay extremes.
    std::array<std::size_t, 4> extremes{};  // min x, max x, min y, max y
    for (std::size_t i = 1; i < n; ++i) {
        const sim::Vec2 p = contour[i];
        if (p.x < contour[extremes[0]].x) extremes[0] = i;
        if (p.x > contour[extremes[1]].x) extremes[1] = i;
        if (p.y < contour[extremes[2]].y) extremes[2] = i;
        if (p.y > contour[extremes[3]].y) extremes[3] = i;
    }
    const QPointF low = toDevice.map({contour[extremes[0]].x, contour[extremes[2]].y});
    const QPointF high = toDevice.map({contour[extremes[1]].x, contour[extremes[3]].y});
    if (high.x() < visible.left() || low.x() > visible.right() || high.y() < visible.top()
        || low.y() > visible.bottom())
        return;

    // Walk once round from the leftmost vertex; step n is that vertex again, closing the contour.
    const std::size_t start = extremes[0];
    Cone cone(tolerance);
    QPointF anchor = toDevice.map(contour[start]);
    QPointF previous = anchor;
    out.append(anchor);
    std::size_t i = start;
    for (std::size_t step = 1; step <= n; ++step) {
        if (++i == n)
            i = 0;
        const QPointF p = toDevice.map(contour[i]);
        QPointF offset = p - anchor;
        double distance = std::sqrt(dot(offset, offset));
        if (!cone.admits(offset, distance)) {
            // The run ends at the previous vertex, which the cone admitted one vertex ago.
            anchor = previous;
            out.append(anchor);
            cone.reset();
            offset = p - anchor;
            distance = std::sqrt(dot(offset, offset));
        }
        if (step == n)
            break;
        if (i == extremes[1] || i == extremes[2] || i == extremes[3]) {
            anchor = p;
            out.append(anchor);
            cone.reset();
        } else {
            cone.include(offset, distance);
        }
        previous = p;
    }
}

} // namespace vf::app
