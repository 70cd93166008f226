#include "sim/ReferenceSimulation.h"

#include "sim/AnalyticFlow.h"
#include "sim/FluidFlow.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace vf::sim {

namespace {

std::unique_ptr<Flow> makeFlow(const SimulationSettings& s)
{
    if (s.flow == SimulationSettings::FlowType::Analytic)
        return std::make_unique<AnalyticFlow>(s.u, s.v);
    return std::make_unique<FluidFlow>(s.fluid);
}

} // namespace

ReferenceSimulation::ReferenceSimulation(const SimulationSettings& settings)
    : m_settings((validateSettings(settings), settings))
    , m_flow(makeFlow(settings))
    , m_fluid(dynamic_cast<FluidFlow*>(m_flow.get()))
    , m_tracker(settings.tracking)
{
}

ReferenceSimulation::~ReferenceSimulation() = default;

int ReferenceSimulation::addRegion(const std::vector<Polygon>& contours)
{
    for (const Polygon& p : contours)
        m_tracker.addContour(m_regionCount, p);
    return m_regionCount++;
}

DropReport ReferenceSimulation::drop(Vec2 center, double radius)
{
    const double r2 = radius * radius;
    const MotionMap push = [center, radius, r2](Vec2 p) {
        const Vec2 d = p - center;
        const double l2 = glm::dot(d, d);
        if (l2 == 0.0)
            return center + Vec2(radius, 0.0);  // the centre itself: any direction is as good
        return center + d * std::sqrt(1.0 + r2 / l2);
    };
    // A contour around the centre ends up enclosing the new drop too: π r² more, counted as the
    // drop's own polygon so that the ring it leaves keeps exactly the area it had.
    const Polygon dropped = circle(center, radius, m_settings.tracking.maxSpacing);
    m_tracker.growTargetAreasAround(center, signedArea(dropped));
    const bool refined = m_tracker.applyMotion(push, *m_flow, time());
    DropReport report;
    report.region = addRegion({dropped});
    report.vertexLimitReached = !refined || vertexCount() > m_settings.tracking.maxVertices;
    return report;
}

void ReferenceSimulation::stylus(Vec2 from, Vec2 to, double radius, double duration)
{
    if (m_fluid)
        m_pendingStylus.push_back({from, to, radius, duration});
}

StepReport ReferenceSimulation::step(double dt)
{
    StepReport report;
    report.substeps = substepCount(m_tracker.strainInSpacings(*m_flow, time(), dt), m_settings.tracking);
    const double h = dt / report.substeps;
    for (int k = 0; k < report.substeps; ++k) {
        // Each substep gets its share of the pen's path, so the force follows the pen.
        for (const StylusSegment& s : m_pendingStylus) {
            const StylusSegment p = s.part(k, report.substeps);
            m_fluid->solver().addStylus(p.from, p.to, p.radius, p.duration);
        }
        const double t = time();
        m_flow->advance(h);
        if (!m_tracker.advect(*m_flow, t, h)) {
            report.vertexLimitReached = true;
            break;
        }
    }
    m_pendingStylus.clear();
    return report;
}

} // namespace vf::sim
