#include "model/SceneRunner.h"

#include <cmath>

namespace vf::model {

sim::SimulationSettings simulationSettings(const Scene& scene)
{
    sim::SimulationSettings s;
    s.flow = scene.flow.type == FlowSpec::Type::Analytic ? sim::SimulationSettings::FlowType::Analytic
                                                         : sim::SimulationSettings::FlowType::Fluid;
    s.fluid.nx = scene.flow.gridX;
    s.fluid.ny = scene.flow.gridY;
    s.fluid.width = scene.canvas.width;
    s.fluid.height = scene.canvas.height;
    s.fluid.viscosity = scene.flow.viscosity;
    s.fluid.stylusResponse = scene.flow.stylusResponse;
    s.fluid.advection = scene.flow.maccormack ? sim::Advection::MacCormack : sim::Advection::SemiLagrangian;
    s.u = scene.flow.u.toStdString();
    s.v = scene.flow.v.toStdString();
    s.tracking.maxSpacing = scene.tracking.maxSpacing;
    s.tracking.adaptive = scene.tracking.adaptive;
    s.tracking.proximity = scene.tracking.proximity;
    s.tracking.areaCorrection = scene.tracking.areaCorrection;
    s.tracking.maxVertices = std::size_t(scene.tracking.maxVertices);
    return s;
}

SceneRunner::SceneRunner(Scene scene, const SimulationFactory& factory)
    : m_scene(std::move(scene))
    , m_script(m_scene)
    , m_simulation(factory(simulationSettings(m_scene)))
{
    for (const RegionSpec& r : m_scene.regions)
        for (const StartingRegion& start : startingRegions(r, m_scene.tracking.maxSpacing))
            m_simulation->addRegion(start.contours);
    // Drops and exact maps at t = 0 are part of the starting picture.
    m_vertexLimitReached = m_script.applyTools(*m_simulation, -INFINITY, 0.0);
}

sim::StepReport SceneRunner::step(double dt)
{
    // The scene's own clock, one addition per step: the simulation's time sums substeps and may
    // land a few ulps off, which could let a drop fall between two steps' windows.
    const double t = m_clock;
    m_clock += dt;
    sim::StepReport report = m_script.step(*m_simulation, t, dt);
    report.vertexLimitReached = report.vertexLimitReached || m_vertexLimitReached;
    m_vertexLimitReached = report.vertexLimitReached;
    ++m_steps;
    return report;
}

Drawing SceneRunner::drawing() const
{
    const auto geometry = m_simulation->regions();
    const RegionTable landed(m_script.looks().begin(), m_script.looks().begin() + std::ptrdiff_t(geometry.size()));
    return drawingOf(m_scene.canvas, landed, geometry);
}

QString SceneRunner::regionName(int index) const
{
    for (const RegionLook& look : m_script.looks())
        if (look.simIndex == index)
            return look.name;
    return QStringLiteral("region %1").arg(index);
}

} // namespace vf::model
