#pragma once
// A live session as the app's worker drives it, for the tests of playing the history again: what
// it does at which step, recorded in a journal as the worker records it (model/Journal.h), and done
// to a reference simulation of its own; and the session written as a project, with its journal.
#include "model/Project.h"
#include "model/RegionRemoval.h"
#include "model/SceneRunner.h"
#include "model/SceneScript.h"

namespace vf::test {

inline model::Scene water()
{
    model::Scene scene;
    scene.flow.gridX = scene.flow.gridY = 32;
    scene.flow.viscosity = 0.001;
    scene.time.dt = 0.01;
    scene.tracking.maxSpacing = 0.01;
    return scene;
}

inline model::EngineSettings settingsOf(const model::Scene& scene)
{
    return {scene.flow, scene.tracking, QStringLiteral("reference"), -1};
}

inline model::RegionTable looks(int regions)
{
    model::RegionTable table;
    for (int r = 0; r < regions; ++r)
        table.push_back({QStringLiteral("ink %1").arg(r), QColor(40 * r, 80, 120), true, r});
    return table;
}

inline sim::StylusSegment pen(double x0, double x1)
{
    return {{x0, 0.5}, {x1, 0.5}, 0.05, 0.01};
}

class Live {
public:
    // A state the session passed, with how far its journal and steps had come.
    struct Kept {
        std::shared_ptr<const sim::SimulationState> state;
        std::size_t entries = 0;
        std::int64_t steps = 0;
    };

    explicit Live(const model::Scene& scene)
        : m_scene(scene), m_script(scene), m_simulation(sim::makeReferenceSimulation(model::simulationSettings(scene)))
    {
        m_simulation->addRegion({sim::circle({0.4, 0.5}, 0.12, 0.01)});
    }

    sim::Simulation& simulation() { return *m_simulation; }
    std::int64_t steps() const { return m_steps; }
    const std::vector<model::JournalEntry>& entries() const { return m_entries; }
    Kept keep() const { return {std::make_shared<const sim::SimulationState>(m_simulation->snapshot()), m_entries.size(), m_steps}; }

    void drop(sim::Vec2 centre, double radius)
    {
        m_entries.push_back({m_steps, model::journal::Drop{centre, radius}});
        m_simulation->drop(centre, radius);
    }
    void map(const sim::ExactMap& map)
    {
        m_entries.push_back({m_steps, model::journal::Map{std::make_shared<const sim::ExactMap>(map)}});
        m_simulation->applyMap(map);
    }
    void addRegion(const std::vector<sim::Polygon>& contours)
    {
        m_entries.push_back({m_steps, model::journal::AddRegion{contours}});
        m_simulation->addRegion(contours);
    }
    void removeRegion(int region)
    {
        m_entries.push_back({m_steps, model::journal::RemoveRegion{region}});
        m_simulation->restore(model::withoutRegion(m_simulation->snapshot(), region));
    }
    void configure(const model::EngineSettings& settings)
    {
        m_entries.push_back({m_steps, model::journal::Configure{std::make_shared<const model::EngineSettings>(settings)}});
        model::Scene scene = m_scene;
        scene.flow = settings.flow;
        scene.tracking = settings.tracking;
        const sim::SimulationState state = m_simulation->snapshot();
        m_simulation = sim::makeReferenceSimulation(model::simulationSettings(scene));
        m_simulation->restore(state);
    }
    void step(const std::vector<sim::StylusSegment>& pens = {}, const std::shared_ptr<const sim::TargetDrive>& drive = {})
    {
        if (drive)
            m_entries.push_back({m_steps, model::journal::Drive{drive}});
        for (const sim::StylusSegment& pen : pens)
            m_entries.push_back({m_steps, model::journal::Pen{pen}});
        m_script.step(*m_simulation, m_simulation->time(), m_scene.time.dt, {drive.get(), pens});
        ++m_steps;
    }

    // The session as a project opened at `origin`, with one command from `before` to `after`, and
    // now at `now`: the journal sealed at each of them, as the worker seals it at a snapshot.
    model::Project project(const Kept& origin, const Kept& before, const Kept& after, const Kept& now) const
    {
        std::shared_ptr<const model::JournalSegment> head;
        const auto mark = [&](const Kept& kept, std::size_t from) {
            head = std::make_shared<const model::JournalSegment>(model::JournalSegment{
                {m_entries.begin() + std::ptrdiff_t(from), m_entries.begin() + std::ptrdiff_t(kept.entries)}, head});
            return model::JournalMark{head, kept.steps};
        };
        const auto regions = [](const Kept& kept) { return looks(kept.state->regionCount); };
        model::Project p;
        p.scene = m_scene;
        p.origin = origin.state;
        p.originMark = mark(origin, 0);
        model::HistoryEntry command;
        command.text = QStringLiteral("Stroke");
        command.regionsBefore = regions(before);
        command.regionsAfter = regions(after);
        command.before = before.state;
        command.beforeMark = mark(before, origin.entries);
        command.after = after.state;
        command.afterMark = mark(after, before.entries);
        command.flowBefore = command.flowAfter = m_scene.flow;
        command.trackingBefore = command.trackingAfter = m_scene.tracking;
        p.history.push_back(std::move(command));
        p.historyIndex = 1;
        p.state = *now.state;
        p.stateMark = mark(now, after.entries);
        p.regions = regions(now);
        p.steps = now.steps;
        return p;
    }

private:
    model::Scene m_scene;
    model::SceneScript m_script;
    std::unique_ptr<sim::Simulation> m_simulation;
    std::vector<model::JournalEntry> m_entries;
    std::int64_t m_steps = 0;
};

} // namespace vf::test
