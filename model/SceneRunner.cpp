#include "model/SceneRunner.h"

#include <algorithm>
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
    , m_simulation(factory(simulationSettings(m_scene)))
    , m_dropDone(m_scene.strokes.size(), false)
{
    for (const RegionSpec& r : m_scene.regions) {
        m_simulation->addRegion(shapeContours(r.shape, m_scene.tracking.maxSpacing));
        m_looks.push_back({r.name, r.color, r.visible});
        m_takenNames.insert(r.name);
    }
    for (const Stroke& s : m_scene.strokes)
        if (const auto* d = std::get_if<DropStroke>(&s); d && !d->name.isEmpty())
            m_takenNames.insert(d->name);
    applyDrops(-INFINITY, 0.0);  // drops at t = 0 are part of the starting picture
}

void SceneRunner::applyDrops(double from, double to)
{
    // Drops land in the order of their times (stable for equal times, as listed).
    std::vector<std::size_t> due;
    for (std::size_t i = 0; i < m_scene.strokes.size(); ++i) {
        const auto* drop = std::get_if<DropStroke>(&m_scene.strokes[i]);
        if (drop && !m_dropDone[i] && drop->time > from && drop->time <= to)
            due.push_back(i);
    }
    std::stable_sort(due.begin(), due.end(), [this](std::size_t a, std::size_t b) {
        return std::get<DropStroke>(m_scene.strokes[a]).time < std::get<DropStroke>(m_scene.strokes[b]).time;
    });
    for (std::size_t i : due) {
        const auto& drop = std::get<DropStroke>(m_scene.strokes[i]);
        m_vertexLimitReached = m_simulation->drop(drop.center, drop.radius).vertexLimitReached || m_vertexLimitReached;
        ++m_dropsLanded;
        const QString name = drop.name.isEmpty() ? unusedDropName() : drop.name;
        m_takenNames.insert(name);
        m_looks.push_back({name, drop.color, true});
        m_dropDone[i] = true;
    }
}

QString SceneRunner::unusedDropName() const
{
    // "drop N" after the drops landed so far, skipping names a region or a named drop already
    // has: region names become SVG ids and layer labels, so they stay unique.
    for (int n = m_dropsLanded;; ++n)
        if (const QString name = QStringLiteral("drop %1").arg(n); !m_takenNames.contains(name))
            return name;
}

void SceneRunner::applyStylus(double from, double to)
{
    // Each pair of consecutive timed points is one straight piece of the pen's path; every piece
    // that overlaps [from, to] contributes the part of it inside the interval.
    for (const Stroke& stroke : m_scene.strokes) {
        const auto* stylus = std::get_if<StylusStroke>(&stroke);
        if (!stylus)
            continue;
        for (std::size_t k = 0; k + 1 < stylus->points.size(); ++k) {
            const double t0 = stylus->times[k], t1 = stylus->times[k + 1];
            const double a = std::max(from, t0), b = std::min(to, t1);
            if (b <= a || t1 <= t0)
                continue;
            auto at = [&](double t) { return stylus->points[k] + (t - t0) / (t1 - t0) * (stylus->points[k + 1] - stylus->points[k]); };
            m_simulation->stylus(at(a), at(b), stylus->radius, b - a);
        }
    }
}

sim::StepReport SceneRunner::step(double dt)
{
    // The scene's own clock, one addition per step: the simulation's time sums substeps and may
    // land a few ulps off, which could let a drop fall between two steps' windows.
    const double t = m_clock;
    m_clock += dt;
    applyDrops(t, m_clock);
    applyStylus(t, m_clock);
    sim::StepReport report = m_simulation->step(dt);
    report.vertexLimitReached = report.vertexLimitReached || m_vertexLimitReached;
    m_vertexLimitReached = report.vertexLimitReached;
    ++m_steps;
    return report;
}

Drawing SceneRunner::drawing() const
{
    Drawing d;
    d.width = m_scene.canvas.width;
    d.height = m_scene.canvas.height;
    d.background = m_scene.canvas.background;
    auto geometry = m_simulation->regions();
    for (std::size_t i = 0; i < geometry.size(); ++i)
        d.regions.push_back({m_looks[i].name, m_looks[i].color, m_looks[i].visible, std::move(geometry[i])});
    return d;
}

} // namespace vf::model
