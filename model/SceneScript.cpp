#include "model/SceneScript.h"

#include "model/Patterns.h"

#include <limits>

#include <QSet>

#include <algorithm>

namespace vf::model {

SceneScript::SceneScript(const Scene& scene)
{
    for (const RegionSpec& r : scene.regions)
        for (const StartingRegion& look : startingLooks(r))
            m_looks.push_back({look.name, look.color, look.visible, int(m_looks.size())});
    m_startingRegions = int(m_looks.size());

    for (const Stroke& s : scene.strokes)
        add(s, scene.canvas);
    // Only the grid of the fluid matters to a drive: where it rasterises ink and target.
    const sim::FluidSettings grid{scene.flow.gridX, scene.flow.gridY, scene.canvas.width, scene.canvas.height};
    for (const Stroke& s : scene.strokes)
        if (const auto* gather = std::get_if<GatherStroke>(&s))
            m_drives.push_back({gather->time, gather->time + gather->duration,
                                std::make_shared<const sim::TargetDrive>(std::vector<std::vector<sim::Polygon>>{gather->contours}, grid,
                                                                       gather->drive)});
    std::stable_sort(m_drops.begin(), m_drops.end(), [](const DropStroke& a, const DropStroke& b) { return a.time < b.time; });

    QSet<QString> taken;
    for (const RegionLook& look : m_looks)
        taken.insert(look.name);
    for (const DropStroke& d : m_drops)
        if (!d.name.isEmpty())
            taken.insert(d.name);
    auto unusedDropName = [&taken](int ordinal) {
        // "drop N" for the N-th drop to land (counting from 1), skipping names a region or a named drop
        // already has: region names become SVG ids and layer labels, so they stay unique.
        for (int n = ordinal;; ++n)
            if (const QString name = QStringLiteral("drop %1").arg(n); !taken.contains(name))
                return name;
    };

    for (std::size_t i = 0; i < m_drops.size(); ++i) {
        const QString name = m_drops[i].name.isEmpty() ? unusedDropName(int(i) + 1) : m_drops[i].name;
        taken.insert(name);
        m_looks.push_back({name, m_drops[i].color, true, int(m_looks.size())});
    }
}

void SceneScript::add(const Stroke& s, const Canvas& canvas)
{
    if (const auto* drop = std::get_if<DropStroke>(&s)) {
        m_drops.push_back(*drop);
    } else if (const auto* stylus = std::get_if<StylusStroke>(&s)) {
        m_strokes.push_back(*stylus);
    } else if (const auto* spatter = std::get_if<SpatterStroke>(&s)) {
        const std::vector<DropStroke> drops = spatter->drops();
        m_drops.insert(m_drops.end(), drops.begin(), drops.end());
    } else if (const auto* pattern = std::get_if<PatternStroke>(&s)) {
        for (const Stroke& tool : patternStrokes(*pattern, canvas))
            add(tool, canvas);
    } else if (const auto* swirl = std::get_if<SwirlStroke>(&s)) {
        if (swirl->mode == CombStroke::Mode::Exact)
            m_maps.push_back({swirl->time, swirl->map()});
        else
            for (int k = 0; k < swirl->rings; ++k)
                for (StylusStroke& stroke : swirl->ringStrokes(k))
                    m_strokes.push_back(std::move(stroke));
    } else if (const auto* comb = std::get_if<CombStroke>(&s)) {
        addComb(*comb);
    } else if (std::holds_alternative<GatherStroke>(s)) {
        // A drive, built once the grid is known (the constructor).
    } else {
        addComb(std::get<CircularCombStroke>(s));
    }
}

double SceneScript::lastDropTime() const
{
    return m_drops.empty() ? -std::numeric_limits<double>::infinity() : m_drops.back().time;
}

bool SceneScript::applyTools(sim::Simulation& simulation, double from, double to) const
{
    const bool dropsReachedLimit = applyDrops(simulation, from, to);
    return applyMaps(simulation, from, to) || dropsReachedLimit;
}

bool SceneScript::applyDrops(sim::Simulation& simulation, double from, double to) const
{
    bool limitReached = false;
    for (const DropStroke& drop : m_drops)
        if (drop.time > from && drop.time <= to)
            limitReached = simulation.drop(drop.center, drop.radius).vertexLimitReached || limitReached;
    return limitReached;
}

template <typename AnyComb>
void SceneScript::addComb(const AnyComb& comb)
{
    if (comb.mode == CombStroke::Mode::Exact)
        m_maps.push_back({comb.time, comb.map()});
    else
        for (int k = 0; k < comb.tines; ++k)
            m_strokes.push_back(comb.tineStroke(k));
}

bool SceneScript::applyMaps(sim::Simulation& simulation, double from, double to) const
{
    bool limitReached = false;
    for (const TimedMap& timed : m_maps)
        if (timed.time > from && timed.time <= to)
            limitReached = !simulation.applyMap(timed.map) || limitReached;
    return limitReached;
}

void SceneScript::applyStylus(sim::Simulation& simulation, double from, double to) const
{
    for (const StylusStroke& stylus : m_strokes) {
        for (std::size_t k = 0; k + 1 < stylus.points.size(); ++k) {
            const double t0 = stylus.times[k], t1 = stylus.times[k + 1];
            const double a = std::max(from, t0), b = std::min(to, t1);
            if (b <= a || t1 <= t0)
                continue;
            auto at = [&](double t) { return stylus.points[k] + (t - t0) / (t1 - t0) * (stylus.points[k + 1] - stylus.points[k]); };
            simulation.stylus(at(a), at(b), stylus.radius, b - a);
        }
    }
}

void SceneScript::applyGather(sim::Simulation& simulation, double from) const
{
    for (auto drive = m_drives.rbegin(); drive != m_drives.rend(); ++drive)
        if (from >= drive->start && from < drive->end) {
            simulation.drive(drive->drive->force(simulation.regions()));
            return;
        }
}

sim::StepReport SceneScript::step(sim::Simulation& simulation, double from, double dt, const LiveInputs& live) const
{
    const bool limit = applyTools(simulation, from, from + dt);
    applyStylus(simulation, from, from + dt);
    if (live.drive)
        simulation.drive(live.drive->force(simulation.regions()));
    else
        applyGather(simulation, from);
    for (const sim::StylusSegment& part : live.pens)
        simulation.stylus(part.from, part.to, part.radius, part.duration);
    sim::StepReport report = simulation.step(dt);
    report.vertexLimitReached = report.vertexLimitReached || limit;
    return report;
}

} // namespace vf::model
