// Playing the history again (model/Journal, model/HistoryReplay): the journal's segments give the
// inputs between two states of one line of work and nothing across lines; a replay given the
// inputs a live simulation had, at the steps it had them, ends in that simulation's state exactly
// (the reference backend is deterministic), over one span or two, through a change of settings;
// and past its end the picture holds. A project file keeps the journal: the history read back from
// it plays again to the same end.
#include "../LiveSession.h"
#include "model/HistoryReplay.h"
#include "model/ProjectFile.h"

#include <QTest>

using namespace vf;
using namespace vf::model;
using namespace vf::test;

namespace {

std::shared_ptr<const JournalSegment> segment(std::vector<JournalEntry> entries, std::shared_ptr<const JournalSegment> previous)
{
    return std::make_shared<const JournalSegment>(JournalSegment{std::move(entries), std::move(previous)});
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

    // Every kind of entry, written into a project file and read back: the spans from the origin
    // through the command to now are those written, and played again they end in the live state.
    void projectFileKeepsTheJournal()
    {
        const Scene scene = water();
        Live live(scene);
        live.step({pen(0.2, 0.25)});
        const Live::Kept origin = live.keep();
        live.drop({0.7, 0.5}, 0.08);
        live.step({pen(0.25, 0.3)});
        const Live::Kept before = live.keep();
        live.map(sim::Comb{{0.5, 0.2}, {0.5, 0.4}, 2, 0.2, 0.05, 0.03, 0.3, 0.5});
        live.map(sim::CircularComb{{0.5, 0.5}, 0.1, 2, 0.05, 0.02, 0.4});
        live.map(sim::Swirl{{0.4, 0.5}, 0.2, -0.7});
        live.addRegion({sim::circle({0.2, 0.2}, 0.05, 0.01), sim::circle({0.2, 0.2}, 0.02, 0.01)});
        live.removeRegion(1);
        const auto drive = std::make_shared<const sim::TargetDrive>(
            std::vector<std::vector<sim::Polygon>>{{sim::circle({0.5, 0.5}, 0.2, 0.01)}, {sim::circle({0.1, 0.1}, 0.05, 0.01)}},
            simulationSettings(scene).fluid, sim::TargetDriveSettings{300, 4, 0.02, 2});
        for (int k = 0; k < 3; ++k)
            live.step({pen(0.3, 0.32), pen(0.6, 0.58)}, drive);
        const Live::Kept after = live.keep();
        EngineSettings thicker = settingsOf(scene);
        thicker.flow.viscosity = 0.05;
        thicker.tracking.maxSpacing = 0.008;
        live.configure(thicker);
        live.step();
        live.step({pen(0.35, 0.4)});
        const Live::Kept now = live.keep();

        const Project written = live.project(origin, before, after, now);
        const ProjectReadResult read = parseProject(projectToBytes(written), u"journal.vfproj"_qs);
        QVERIFY2(read.ok(), qPrintable(read.error));
        int unrecorded = -1;
        const std::vector<ReplaySpan> spans = replaySpans(read.project, &unrecorded);
        QCOMPARE(unrecorded, 0);
        const std::vector<ReplaySpan> expected = replaySpans(written);
        QCOMPARE(spans.size(), std::size_t(3));  // origin to the command, the command, to now
        QCOMPARE(spans.size(), expected.size());
        for (std::size_t k = 0; k < spans.size(); ++k) {
            QCOMPARE(spans[k].steps, expected[k].steps);
            QCOMPARE(spans[k].entries.size(), expected[k].entries.size());
            QVERIFY(*spans[k].start == *expected[k].start);
        }
        const auto& drop = std::get<journal::Drop>(spans[0].entries.front().action);
        QCOMPARE(drop.center, sim::Vec2(0.7, 0.5));
        const auto& comb = std::get<sim::Comb>(*std::get<journal::Map>(spans[1].entries.front().action).map);
        QCOMPARE(comb.phase, 0.5);
        const auto& read3 = std::get<journal::Drive>(spans[1].entries[5].action).drive;
        QCOMPARE(read3->target().size(), std::size_t(2));
        QCOMPARE(read3->settings(), drive->settings());

        HistoryReplay replay(scene, spans);
        QCOMPARE(replay.duration(), double(now.steps - origin.steps) * scene.time.dt);
        for (std::int64_t k = origin.steps; k < now.steps; ++k)
            replay.step();
        QVERIFY(replay.simulation().snapshot() == *now.state);
    }
};

QTEST_APPLESS_MAIN(TestHistoryReplay)
#include "tst_historyreplay.moc"
