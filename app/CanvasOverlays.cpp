#include "app/CanvasOverlays.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace vf::app {
namespace {

constexpr double kMinCellPixels = 4.0;     // logical pixels; closer grid lines are a grey wash
constexpr double kArrowSpacing = 32.0;     // logical pixels between arrow feet
constexpr double kArrowHead = 0.25;        // head length as a fraction of the arrow
const QColor kOverlayColor(40, 40, 40, 160);

QPen overlayPen(double devicePixelRatio)
{
    QPen pen(kOverlayColor, devicePixelRatio);
    pen.setCosmetic(true);
    return pen;
}

// The canvas (its fluid field's extent) on screen, cut to what is visible.
QRectF fieldOnScreen(const sim::MacVelocity& field, const PixelMapping& toDevice, const QRectF& visible)
{
    return QRectF(toDevice.map({0.0, 0.0}), toDevice.map({field.nx * field.hx, field.ny * field.hy}))
        .intersected(visible);
}

} // namespace

void paintGrid(QPainter& painter, const sim::MacVelocity& field, const PixelMapping& toDevice,
               const QRectF& visible, double devicePixelRatio)
{
    const double minCell = kMinCellPixels * devicePixelRatio;
    if (field.hx * toDevice.scale < minCell || field.hy * toDevice.scale < minCell)
        return;
    const QRectF area = fieldOnScreen(field, toDevice, visible);
    QPainterPath lines;
    for (int i = 0; i <= field.nx; ++i) {
        const double x = toDevice.map({i * field.hx, 0.0}).x();
        if (x >= area.left() && x <= area.right()) {
            lines.moveTo(x, area.top());
            lines.lineTo(x, area.bottom());
        }
    }
    for (int j = 0; j <= field.ny; ++j) {
        const double y = toDevice.map({0.0, j * field.hy}).y();
        if (y >= area.top() && y <= area.bottom()) {
            lines.moveTo(area.left(), y);
            lines.lineTo(area.right(), y);
        }
    }
    painter.strokePath(lines, overlayPen(devicePixelRatio));
}

void paintVelocity(QPainter& painter, const sim::MacVelocity& field, const PixelMapping& toDevice,
                   const QRectF& visible, double devicePixelRatio)
{
    const QRectF area = fieldOnScreen(field, toDevice, visible);
    const double spacing = kArrowSpacing * devicePixelRatio;
    struct Arrow {
        QPointF foot;
        sim::Vec2 velocity;
    };
    std::vector<Arrow> arrows;
    double fastest = 0.0;
    for (double y = area.top() + spacing / 2; y < area.bottom(); y += spacing)
        for (double x = area.left() + spacing / 2; x < area.right(); x += spacing) {
            const sim::Vec2 canvas((x - toDevice.dx) / toDevice.scale, (y - toDevice.dy) / toDevice.scale);
            const sim::Vec2 velocity = field.sample(canvas);
            fastest = std::max(fastest, std::hypot(velocity.x, velocity.y));
            arrows.push_back({{x, y}, velocity});
        }
    if (fastest <= 0.0)
        return;  // still fluid: nothing to point at
    QPainterPath path;
    for (const Arrow& arrow : arrows) {
        const QPointF shaft = QPointF(arrow.velocity.x, arrow.velocity.y) * (spacing / fastest);
        const QPointF tip = arrow.foot + shaft;
        path.moveTo(arrow.foot);
        path.lineTo(tip);
        // The head: the shaft turned back by ±30°, shortened.
        const QPointF back = -shaft * kArrowHead;
        const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
        path.moveTo(tip + QPointF(back.x() * c - back.y() * s, back.x() * s + back.y() * c));
        path.lineTo(tip);
        path.lineTo(tip + QPointF(back.x() * c + back.y() * s, back.y() * c - back.x() * s));
    }
    painter.strokePath(path, overlayPen(devicePixelRatio));
}

void paintVertexDots(QPainter& painter, const QPolygonF& dots, double devicePixelRatio)
{
    QPen pen(kOverlayColor.darker(), 3.0 * devicePixelRatio, Qt::SolidLine, Qt::RoundCap);
    pen.setCosmetic(true);
    painter.setPen(pen);
    painter.drawPoints(dots);
    painter.setPen(Qt::NoPen);
}

} // namespace vf::app
