#include "app/MarblingDrag.h"

#include <QPainter>
#include <QPolygonF>
#include <QTransform>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vf::app {

namespace {

constexpr double kMaxDegrees = 3600.0;  // a scene's tools turn at most ten times round
constexpr double kArrowPixels = 10.0;

double degrees(double radians) { return std::clamp(radians * 180.0 / std::numbers::pi, -kMaxDegrees, kMaxDegrees); }

// The points of `path` turned about `centre` by `turn` radians, the way sim/Whirl.h turns them:
// the model's arcs start on the ray toward +x, the drag's where the pointer first went.
std::vector<sim::Vec2> turned(const model::StylusStroke& path, sim::Vec2 centre, double turn)
{
    const double c = std::cos(turn), s = std::sin(turn);
    std::vector<sim::Vec2> points;
    for (const sim::Vec2& p : path.points) {
        const sim::Vec2 d = p - centre;
        points.push_back(centre + sim::Vec2(c * d.x - s * d.y, s * d.x + c * d.y));
    }
    return points;
}

// The pieces of `path` turned by `turn` as pens, each taking its share of the path's time.
void addPens(std::vector<sim::StylusSegment>& pens, const model::StylusStroke& path, sim::Vec2 centre, double turn)
{
    const std::vector<sim::Vec2> points = turned(path, centre, turn);
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        pens.push_back({points[i], points[i + 1], path.radius, path.times[i + 1] - path.times[i]});
}

QPolygonF polygon(const std::vector<sim::Vec2>& points, const QTransform& toWidget)
{
    QPolygonF polygon;
    for (const sim::Vec2& p : points)
        polygon << toWidget.map(QPointF(p.x, p.y));
    return polygon;
}

// One tine's arc: the circular comb's path for a single circle of radius `radius`.
model::StylusStroke arc(sim::Vec2 centre, double radius, double angleDegrees)
{
    model::CircularCombStroke one;
    one.center = centre;
    one.innerRadius = radius;
    one.angle = angleDegrees;
    return one.tineStroke(0);
}

} // namespace

void MarblingDrag::setOptions(const model::Stroke& options)
{
    if (const auto* comb = std::get_if<model::CombStroke>(&options))
        m_comb = *comb;
    else if (const auto* circularComb = std::get_if<model::CircularCombStroke>(&options))
        m_circularComb = *circularComb;
    else
        m_swirl = std::get<model::SwirlStroke>(options);
}

void MarblingDrag::begin(Tool tool, QPointF at, double still)
{
    m_tool = tool;
    m_press = m_at = {at.x(), at.y()};
    m_still = still;
    m_moved = false;
    m_start = m_swept = m_sweptByPens = 0.0;
    m_direction.reset();
    m_combPens.clear();
}

void MarblingDrag::moveTo(QPointF at)
{
    m_at = {at.x(), at.y()};
    const sim::Vec2 d = m_at - m_press;
    if (glm::length(d) <= m_still) {
        m_direction.reset();  // about the press itself every direction is noise
        return;
    }
    const double direction = std::atan2(d.y, d.x);
    if (!m_moved)
        m_start = direction;
    m_moved = true;
    if (m_direction)
        m_swept += std::remainder(direction - *m_direction, 2.0 * std::numbers::pi);
    m_direction = direction;
}

bool MarblingDrag::inWater() const
{
    const model::CombStroke::Mode mode = m_tool == Tool::Comb           ? m_comb.mode
                                       : m_tool == Tool::CircularComb ? m_circularComb.mode
                                                                        : m_swirl.mode;
    return mode == model::CombStroke::Mode::Water;
}

model::CombStroke MarblingDrag::combAsDragged() const
{
    model::CombStroke comb = m_comb;
    comb.from = m_press;
    comb.to = m_at;
    return comb;
}

model::Stroke MarblingDrag::tool() const
{
    if (m_tool == Tool::Comb) {
        model::CombStroke comb = combAsDragged();
        if (comb.mode == model::CombStroke::Mode::Exact) {
            // The ink at the tines moves as far as the pointer did: the map moves it by the
            // stroke's length times every tine's pull there, so the stroke is that much shorter
            // (about its middle, where a wavy comb's wave is set).
            const sim::Vec2 middle = 0.5 * (m_press + m_at), half = 0.5 * (m_at - m_press) / comb.map().mostPull();
            comb.from = middle - half;
            comb.to = middle + half;
        }
        return comb;
    }
    if (m_tool == Tool::CircularComb) {
        model::CircularCombStroke comb = m_circularComb;
        comb.center = m_press;
        comb.angle = degrees(m_swept);
        return comb;
    }
    model::SwirlStroke swirl = m_swirl;
    swirl.center = m_press;
    swirl.radius = std::max(glm::distance(m_at, m_press), model::limits::minLength);
    swirl.angle = degrees(m_swept);
    return swirl;
}

std::vector<sim::StylusSegment> MarblingDrag::pens(double seconds, double radius)
{
    std::vector<sim::StylusSegment> pens;
    if (!m_moved)
        return pens;
    if (m_tool == Tool::Comb) {
        // The tines across the line from the press to the pointer, following the pointer.
        const sim::Comb comb = combAsDragged().map();
        std::vector<sim::Vec2> now;
        for (int k = 0; k < comb.tines; ++k)
            now.push_back(comb.tineStart(k) + (m_at - m_press));
        if (m_combPens.empty())
            for (int k = 0; k < comb.tines; ++k)
                m_combPens.push_back(comb.tineStart(k));
        for (std::size_t k = 0; k < now.size(); ++k)
            pens.push_back({m_combPens[k], now[k], radius, seconds});
        m_combPens = now;
        return pens;
    }
    if (m_swept == m_sweptByPens)
        return pens;
    // The tool turned by the angle swept since the pens last moved, in `seconds`.
    const double turn = m_swept - m_sweptByPens;
    if (m_tool == Tool::CircularComb) {
        model::CircularCombStroke step = std::get<model::CircularCombStroke>(tool());
        step.angle = turn * 180.0 / std::numbers::pi;
        step.time = 0.0;
        step.duration = seconds;
        step.radius = radius;
        for (int k = 0; k < step.tines; ++k)
            addPens(pens, step.tineStroke(k), m_press, m_start + m_sweptByPens);
    } else {
        model::SwirlStroke step = std::get<model::SwirlStroke>(tool());
        const sim::Swirl before{m_press, step.radius, m_sweptByPens};  // how far each ring has turned
        step.angle = turn * 180.0 / std::numbers::pi;
        step.time = 0.0;
        step.duration = seconds;
        for (int k = 0; k < step.rings; ++k)
            for (const model::StylusStroke& ring : step.ringStrokes(k))
                addPens(pens, ring, m_press, before.angleAt(glm::distance(ring.points.front(), m_press)));
    }
    m_sweptByPens = m_swept;
    return pens;
}

void MarblingDrag::paint(QPainter& painter, const QTransform& toWidget, const QColor& colour) const
{
    if (!m_moved)
        return;
    const QPen dashed(colour, 1.5, Qt::DashLine), solid(colour, 1.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    painter.setBrush(Qt::NoBrush);
    const double scale = toWidget.m11();
    const QPointF centre = toWidget.map(QPointF(m_press.x, m_press.y));
    if (m_tool == Tool::Comb) {
        const model::CombStroke comb = combAsDragged();
        painter.setPen(dashed);
        for (int k = 0; k < comb.tines; ++k)
            painter.drawPolyline(polygon(comb.tineStroke(k).points, toWidget));
        return;
    }
    const model::Stroke dragged = tool();
    if (const auto* comb = std::get_if<model::CircularCombStroke>(&dragged)) {
        for (int k = 0; k < comb->tines; ++k) {
            const double r = comb->innerRadius + k * comb->spacing;
            painter.setPen(dashed);
            painter.drawEllipse(centre, r * scale, r * scale);
            painter.setPen(solid);
            painter.drawPolyline(polygon(turned(comb->tineStroke(k), m_press, m_start), toWidget));
        }
        return;
    }
    const auto& swirl = std::get<model::SwirlStroke>(dragged);
    painter.setPen(dashed);
    painter.drawEllipse(centre, swirl.radius * scale, swirl.radius * scale);
    const QPolygonF swept = polygon(turned(arc(m_press, swirl.radius, swirl.angle), m_press, m_start), toWidget);
    painter.setPen(solid);
    painter.drawPolyline(swept);
    const QPointF tip = swept.back(), back = swept[swept.size() - 2] - tip;
    const double along = std::hypot(back.x(), back.y());
    if (along == 0.0)
        return;
    // The arrow's head: two barbs back along the arc's last piece, turned ±30° from it.
    const QPointF unit = back / along * kArrowPixels;
    for (const double barb : {-std::numbers::pi / 6.0, std::numbers::pi / 6.0})
        painter.drawLine(tip, tip + QPointF(std::cos(barb) * unit.x() - std::sin(barb) * unit.y(),
                                            std::sin(barb) * unit.x() + std::cos(barb) * unit.y()));
}

} // namespace vf::app
