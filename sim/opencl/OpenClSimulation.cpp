#include "sim/opencl/OpenClSimulation.h"

#include "sim/Pinches.h"
#include "sim/opencl/AnalyticSource.h"
#include "sim/opencl/KernelSources.h"

namespace vf::sim::opencl {

namespace {

bool isFluid(const SimulationSettings& s)
{
    return s.flow == SimulationSettings::FlowType::Fluid;
}

std::string flowSource(const SimulationSettings& s)
{
    if (isFluid(s))
        return joinedKernelSources({"flow_fluid.cl"});
    try {
        return analyticFlowSource(s.u, s.v);
    } catch (const UnsupportedExpression& e) {
        throw DeviceError(e.what());
    }
}

} // namespace

OpenClSimulation::OpenClSimulation(const SimulationSettings& settings, std::optional<int> deviceIndex,
                                   FluidPlacement fluidPlacement)
    : m_settings((validateSettings(settings), settings))
    , m_device(Device::open(deviceIndex))
{
    if (isFluid(settings)) {
        m_fluid = makeFluid(m_device, settings.fluid, fluidPlacement);
    } else {
        m_placeholders.field = cl::Buffer(m_device.context(), CL_MEM_READ_ONLY, sizeof(float));
    }
    m_contours = std::make_unique<DeviceContours>(m_device, settings.tracking,
                                                  Vec2(settings.fluid.width, settings.fluid.height),
                                                  flowSource(settings));
}

OpenClSimulation::~OpenClSimulation() = default;

FlowBinding OpenClSimulation::binding(double t0, double t1) const
{
    if (m_fluid)
        return m_fluid->binding(t0, t1);
    FlowBinding b = m_placeholders;
    b.t0 = t0;
    b.t1 = t1;
    return b;
}

int OpenClSimulation::addRegion(const std::vector<Polygon>& contours)
{
    m_contours->addRegion(m_regionCount, contours);
    return m_regionCount++;
}

bool OpenClSimulation::mapContours(const ExactMap& map)
{
    return m_contours->applyMap(map, binding(m_time, m_time));
}

void OpenClSimulation::separateLayers(std::optional<Window> within)
{
    const PhaseClock::Scope timing(&m_phases, Phase::Pinches);
    m_contours->separateLayers(within);
}

bool OpenClSimulation::pushOutward(Vec2 center, double radius)
{
    return m_contours->drop(center, radius, binding(m_time, m_time));
}

void OpenClSimulation::stylus(Vec2 from, Vec2 to, double radius, double duration)
{
    if (m_fluid)
        m_pendingStylus.push_back({from, to, radius, duration});
}

void OpenClSimulation::enablePhaseTiming()
{
    m_phases.enable([this] { m_device.queue().finish(); });
    m_contours->setPhaseClock(&m_phases);
}

StepReport OpenClSimulation::step(double dt)
{
    StepReport report;
    {
        const PhaseClock::Scope timing(&m_phases, Phase::Advect);  // the strain samples the flow
        report.substeps = substepCount(m_contours->strainInSpacings(binding(m_time, m_time), dt),
                                       m_settings.tracking);
    }
    const double h = dt / report.substeps, start = m_time;
    for (int k = 0; k < report.substeps && !report.vertexLimitReached; ++k) {
        if (m_fluid) {
            for (const StylusSegment& s : m_pendingStylus) {
                const StylusSegment p = s.part(k, report.substeps);
                m_fluid->addStylus(p.from, p.to, p.radius, p.duration);
            }
            if (m_pendingForce)
                m_fluid->addForce(*m_pendingForce);
            const PhaseClock::Scope timing(&m_phases, Phase::Fluid);
            m_fluid->step(h);
        }
        // The first substep starts where the strain check sampled: at m_time, the fluid's start field
        // being a copy of the field it saw.
        report.vertexLimitReached = !m_contours->advect(binding(m_time, m_time + h), k == 0);
        m_time += h;
    }
    m_pendingStylus.clear();
    m_pendingForce.reset();
    if (pinchCheckDue(start, m_time)) {
        const PhaseClock::Scope timing(&m_phases, Phase::Pinches);
        report.pinchesCut = m_contours->cutPinches();
    }
    return report;
}

SimulationState OpenClSimulation::snapshot() const
{
    SimulationState state;
    state.time = m_time;
    state.regionCount = m_regionCount;
    state.contours = settledContours(m_contours->read());
    if (m_fluid)
        state.fluid = FluidState{m_fluid->readVelocity(), m_fluid->readPressure()};
    state.pendingStylus = m_pendingStylus;
    return state;
}

void OpenClSimulation::restore(const SimulationState& state)
{
    validateState(state, m_contours->deviceVertexLimit());
    m_layersPressed = 0.0;
    m_contours->write(state.contours);
    if (m_fluid) {
        const FluidState* fluid = fluidOnGrid(state, m_settings.fluid);
        m_fluid->writeVelocity(fluid ? fluid->velocity : FluidSolver::atRest(m_settings.fluid));
        if (fluid)
            m_fluid->writePressure(fluid->pressure);
        m_pendingStylus = state.pendingStylus;
    } else {
        m_pendingStylus.clear();
    }
    m_pendingForce.reset();
    m_regionCount = state.regionCount;
    m_time = state.time;
}

std::optional<MacVelocity> OpenClSimulation::velocity() const
{
    if (!m_fluid)
        return std::nullopt;
    return m_fluid->readVelocity();
}

std::unique_ptr<Simulation> makeSimulation(const SimulationSettings& settings, const std::string& backend,
                                           std::optional<int> deviceIndex)
{
    if (backend == "opencl")
        return std::make_unique<OpenClSimulation>(settings, deviceIndex);
    return makeReferenceSimulation(settings);
}

} // namespace vf::sim::opencl
