// Playing the history again (model/Journal, model/HistoryReplay): the journal's segments give the
// inputs between two states of one line of work and nothing across lines; a replay given the
// inputs a live simulation had, at the steps it had them, ends in that simulation's state exactly
// (the reference backend is deterministic), over one span or two, through a change of settings;
// and past its end the picture holds.
#include "model/HistoryReplay.h"
#include "model/RegionRemoval.h"

#include <QTest>

using namespace vf;
using namespace vf::model;

namespace {

Scene water()
{
    Scene scene;
    scene.flow.gridX = scene.flow.gridY = 32;
    scene.flow.viscosity = 0.001;
    scene.time.dt = 0.01;
    scene.tracking.maxSpacing = 0.01;
    return scene;
}

std::shared_ptr<const JournalSegment> segment(std::vector<JournalEntry> entries, std::shared_ptr<const JournalSegment> previous)
{
    return std::make_shared<const JournalSegment>(JournalSegment{std::move(entries), std::move(previous)});
}

EngineSettings settingsOf(const Scene& scene)
{
    return {scene.flow, scene.tracking, QStringLiteral("reference"), -1};
}

// A live session, as the app's worker drives it: what it does at which step, recorded as the
// worker records it, and done to a simulation of its own.
class Live {
public:
    explicit Live(const Scene& scene) : m_scene(scene), m_script(scene), m_simulation(sim::makeReferenceSimulation(simulationSettings(scene)))
    {
        m_simulation->addRegion({sim::circle({0.4, 0.5}, 0.12, 0.01)});
    }

    sim::Simulation& simulation() { return *m_simulation; }
    std::int64_t steps() const { return m_steps; }
    const std::vector<JournalEntry>& entries() const { return m_entries; }

    void drop(sim::Vec2 centre, double radius)
    {
        m_entries.push_back({m_steps, journal::Drop{centre, radius}});
        m_simulation->drop(centre, radius);
    }
    void map(const sim::ExactMap& map)
    {
        m_entries.push_back({m_steps, journal::Map{std::make_shared<const sim::ExactMap>(map)}});
        m_simulation->applyMap(map);
    }
    void removeRegion(int region)
    {
        m_entries.push_back({m_steps, journal::RemoveRegion{region}});
        m_simulation->restore(withoutRegion(m_simulation->snapshot(), region));
    }
    void configure(const EngineSettings& settings)
    {
        m_entries.push_back({m_steps, journal::Configure{std::make_shared<const EngineSettings>(settings)}});
        Scene scene = m_scene;
        scene.flow = settings.flow;
        scene.tracking = settings.tracking;
        const sim::SimulationState state = m_simulation->snapshot();
        m_simulation = sim::makeReferenceSimulation(simulationSettings(scene));
        m_simulation->restore(state);
    }
    void step(const std::vector<sim::StylusSegment>& pens = {}, const std::shared_ptr<const sim::TargetDrive>& drive = {})
    {
        if (drive)
            m_entries.push_back({m_steps, journal::Drive{drive}});
        for (const sim::StylusSegment& pen : pens)
            m_entries.push_back({m_steps, journal::Pen{pen}});
        m_script.step(*m_simulation, m_simulation->time(), m_scene.time.dt, {drive.get(), pens});
        ++m_steps;
    }

private:
    Scene m_scene;
    SceneScript m_script;
    std::unique_ptr<sim::Simulation> m_simulation;
    std::vector<JournalEntry> m_entries;
    std::int64_t m_steps = 0;
};

sim::StylusSegment pen(double x0, double x1)
{
    return {{x0, 0.5}, {x1, 0.5}, 0.05, 0.01};
}

RegionTable looks(int regions)
{
    RegionTable table;
    for (int r = 0; r < regions; ++r)
        table.push_back({QStringLiteral("ink %1").arg(r), QColor(40 * r, 80, 120), true, r});
    return table;
}

// Everything `live` did after `from` (its state then, and its entries and steps then), as a span.
ReplaySpan spanSince(const Live& live, sim::SimulationState from, std::size_t firstEntry, std::int64_t fromStep,
                     const EngineSettings& settings)
{
    ReplaySpan span{std::make_shared<const sim::SimulationState>(std::move(from)), {}, live.steps() - fromStep, looks(3), settings};
    for (std::size_t k = firstEntry; k < live.entries().size(); ++k) {
        JournalEntry entry = live.entries()[k];
        entry.step -= fromStep;
        span.entries.push_back(std::move(entry));
    }
    return span;
}

} // namespace

class TestHistoryReplay : public QObject {
    Q_OBJECT

private slots:
    void journalGivesTheEntriesBetweenTwoMarks()
    {
        const auto root = segment({}, nullptr);
        const auto first = segment({{0, journal::Drop{{0.5, 0.5}, 0.1}}, {3, journal::RemoveRegion{0}}}, root);
        const auto second = segment({{5, journal::Drop{{0.2, 0.2}, 0.1}}}, first);
        const std::optional<std::vector<JournalEntry>> all = entriesBetween({root, 0}, {second, 7});
        QVERIFY(all);
        QCOMPARE(all->size(), std::size_t(3));
        QCOMPARE((*all)[2].step, std::int64_t(5));
        const std::optional<std::vector<JournalEntry>> later = entriesBetween({first, 4}, {second, 7});
        QVERIFY(later);
        QCOMPARE(later->size(), std::size_t(1));
        QCOMPARE(later->front().step, std::int64_t(1));  // counted from the earlier mark
        QVERIFY(entriesBetween({first, 4}, {first, 4})->empty());
        // Another line of work, a mark without a head (a state from a project file), or backwards.
        QVERIFY(!entriesBetween({segment({}, nullptr), 0}, {second, 7}));
        QVERIFY(!entriesBetween({nullptr, 0}, {second, 7}));
        QVERIFY(!entriesBetween({second, 7}, {first, 4}));
    }

    // Drops, pens, a comb, a region removed and a gather's drive at their steps: the replay ends
    // in the live state, bit for bit, whether as one span or split in two where a command began.
    void replayEndsWhereTheLiveSimulationDid()
    {
        const Scene scene = water();
        Live live(scene);
        const sim::SimulationState start = live.simulation().snapshot();
        live.step();
        live.drop({0.7, 0.5}, 0.08);
        for (int k = 0; k < 4; ++k)
            live.step({pen(0.2 + 0.05 * k, 0.25 + 0.05 * k)});
        const sim::SimulationState middle = live.simulation().snapshot();
        const std::size_t middleEntry = live.entries().size();
        const std::int64_t middleStep = live.steps();
        live.map(sim::Comb{{0.5, 0.2}, {0.5, 0.4}, 2, 0.2, 0.05});
        live.drop({0.3, 0.3}, 0.05);
        live.removeRegion(1);
        const auto drive = std::make_shared<const sim::TargetDrive>(std::vector<std::vector<sim::Polygon>>{{sim::circle({0.5, 0.5}, 0.2, 0.01)}},
                                                                    simulationSettings(scene).fluid, sim::TargetDriveSettings{});
        for (int k = 0; k < 3; ++k)
            live.step({}, drive);
        live.step();
        const sim::SimulationState end = live.simulation().snapshot();

        HistoryReplay whole(scene, {spanSince(live, start, 0, 0, settingsOf(scene))});
        QCOMPARE(whole.duration(), 9 * 0.01);
        for (int k = 0; k < 9; ++k)
            whole.step();
        QVERIFY(whole.simulation().snapshot() == end);
        QCOMPARE(whole.drawing().regions.size(), std::size_t(3));  // the span's looks

        ReplaySpan first = spanSince(live, start, 0, 0, settingsOf(scene));
        first.entries.resize(middleEntry);
        first.steps = middleStep;
        HistoryReplay split(scene, {first, spanSince(live, middle, middleEntry, middleStep, settingsOf(scene))});
        for (int k = 0; k < 5; ++k)
            split.step();
        QVERIFY(split.simulation().snapshot() == middle);
        for (int k = 0; k < 4; ++k)
            split.step();
        QVERIFY(split.simulation().snapshot() == end);
    }

    // Settings changed between steps (another viscosity) are changed again at the same step.
    void settingsChangeAtTheirStep()
    {
        const Scene scene = water();
        Live live(scene);
        const sim::SimulationState start = live.simulation().snapshot();
        live.step({pen(0.3, 0.35)});
        EngineSettings thicker = settingsOf(scene);
        thicker.flow.viscosity = 0.05;
        live.configure(thicker);
        live.step({pen(0.35, 0.4)});
        live.step();
        HistoryReplay replay(scene, {spanSince(live, start, 0, 0, settingsOf(scene))});
        for (int k = 0; k < 3; ++k)
            replay.step();
        QVERIFY(replay.simulation().snapshot() == live.simulation().snapshot());
    }

    // Past the last span the steps count on and the picture stays the last one.
    void pictureHoldsAfterTheEnd()
    {
        const Scene scene = water();
        Live live(scene);
        const sim::SimulationState start = live.simulation().snapshot();
        live.step({pen(0.3, 0.4)});
        HistoryReplay replay(scene, {spanSince(live, start, 0, 0, settingsOf(scene))});
        replay.step();
        const sim::SimulationState last = replay.simulation().snapshot();
        replay.step();
        replay.step();
        QCOMPARE(replay.stepsDone(), std::int64_t(3));
        QVERIFY(replay.simulation().snapshot() == last);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, HistoryReplay(scene, {}));
    }
};

QTEST_APPLESS_MAIN(TestHistoryReplay)
#include "tst_historyreplay.moc"
