#include "sim/ReferenceSimulation.h"

#include "sim/AnalyticFlow.h"
#include "sim/FluidFlow.h"
#include "sim/Pinches.h"


#include <limits>
#include <utility>

namespace vf::sim {

namespace {

std::unique_ptr<Flow> makeFlow(const SimulationSettings& s, FluidFlow*& fluid)
{
    if (s.flow == SimulationSettings::FlowType::Analytic)
        return std::make_unique<AnalyticFlow>(s.u, s.v);
    auto made = std::make_unique<FluidFlow>(s.fluid);
    fluid = made.get();
    return made;
}

} // namespace

ReferenceSimulation::ReferenceSimulation(const SimulationSettings& settings)
    : m_settings((validateSettings(settings), settings))
    , m_flow(makeFlow(settings, m_fluid))
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

bool ReferenceSimulation::mapContours(const ExactMap& map)
{
    return m_tracker.applyMap(map, *m_flow, time());
}

void ReferenceSimulation::separateLayers(std::optional<Window> within)
{
    const PhaseClock::Scope timing(&m_phases, Phase::Pinches);
    m_tracker.separateLayers(within);
}

bool ReferenceSimulation::pushOutward(Vec2 center, double radius)
{
    return m_tracker.drop({center, radius}, *m_flow, time());
}

void ReferenceSimulation::stylus(Vec2 from, Vec2 to, double radius, double duration)
{
    if (m_fluid)
        m_pendingStylus.push_back({from, to, radius, duration});
}

SimulationState ReferenceSimulation::snapshot() const
{
    SimulationState state;
    state.time = time();
    state.regionCount = m_regionCount;
    state.contours = settledContours(m_tracker.contours());
    if (m_fluid)
        state.fluid = m_fluid->state();
    state.pendingStylus = m_pendingStylus;
    return state;
}

void ReferenceSimulation::restore(const SimulationState& state)
{
    validateState(state, std::numeric_limits<std::size_t>::max());  // host memory is the limit
    m_layersPressed = 0.0;
    if (m_fluid) {
        m_fluid->setState(fluidOnGrid(state, m_settings.fluid));
        m_pendingStylus = state.pendingStylus;
    } else {
        m_pendingStylus.clear();
    }
    m_flow->setTime(state.time);
    m_pendingForce.reset();
    m_tracker.setContours(state.contours);
    m_regionCount = state.regionCount;
    m_regionsCopy.reset();
}

std::uint64_t ReferenceSimulation::requestRegions()
{
    m_regionsCopy = RegionsCopy{++m_regionsRequests, regions()};
    return m_regionsRequests;
}

std::optional<RegionsCopy> ReferenceSimulation::takeRegions(bool)
{
    return std::exchange(m_regionsCopy, std::nullopt);
}

void ReferenceSimulation::enablePhaseTiming()
{
    m_phases.enable();
    m_tracker.setPhaseClock(&m_phases);
}

StepReport ReferenceSimulation::step(double dt)
{
    StepReport report;
    {
        const PhaseClock::Scope timing(&m_phases, Phase::Advect);  // the strain samples the flow
        report.substeps = substepCount(m_tracker.strainInSpacings(*m_flow, time(), dt), m_settings.tracking);
    }
    const double h = dt / report.substeps, start = time();
    for (int k = 0; k < report.substeps; ++k) {
        // Each substep gets its share of the pen's path, so the force follows the pen.
        for (const StylusSegment& s : m_pendingStylus) {
            const StylusSegment p = s.part(k, report.substeps);
            m_fluid->solver().addStylus(p.from, p.to, p.radius, p.duration);
        }
        if (m_pendingForce)
            m_fluid->solver().addForce(*m_pendingForce);
        const double t = time();
        {
            const PhaseClock::Scope timing(&m_phases, Phase::Fluid);
            m_flow->advance(h);
        }
        if (!m_tracker.advect(*m_flow, t, h)) {
            report.vertexLimitReached = true;
            break;
        }
    }
    m_pendingStylus.clear();
    m_pendingForce.reset();
    if (pinchCheckDue(start, time())) {
        const PhaseClock::Scope timing(&m_phases, Phase::Pinches);
        report.pinchesCut = m_tracker.cutPinches();
    }
    return report;
}

std::optional<MacVelocity> ReferenceSimulation::velocity() const
{
    if (!m_fluid)
        return std::nullopt;
    return m_fluid->solver().velocity();
}

} // namespace vf::sim
