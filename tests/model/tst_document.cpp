// Document: every action is one command; undo and redo hand the port the exact states taken at a
// command's start and end, and the region table with them; region edits, settings, the scene's
// own drops, the history budget and the Regions model. The simulation here is a stand-in that
// runs requests at once and whose state is a few numbers, so every request can be checked.
#include "model/Document.h"
#include "model/RegionRemoval.h"
#include "model/RegionListModel.h"

#include <QAbstractItemModelTester>
#include <QMimeData>
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace vf;
using namespace vf::model;

namespace {

// Its state: the time stands for "how far the flow has run", one contour per region, each with
// `verticesPerRegion` vertices so that states weigh what a test needs.
class FakePort final : public SimulationPort {
public:
    sim::SimulationState state;
    EngineSettings configured;
    std::size_t verticesPerRegion = 3;
    int loads = 0, maps = 0;
    std::shared_ptr<const sim::TargetDrive> gathering;
    double gatherSeconds = 0.0;
    std::uint64_t requests = 0;

    void load(const Scene& scene, const EngineSettings& settings, const StateSlotPtr& start) override
    {
        ++requests;
        ++loads;
        configured = settings;
        state = {};
        if (start) {
            state = *start->state();
            return;
        }
        for (std::size_t i = 0; i < scene.regions.size(); ++i)
            addContour();
    }
    void configure(const EngineSettings& settings) override { ++requests, configured = settings; }
    void snapshot(const StateSlotPtr& into) override
    {
        ++requests;
        into->fill(std::make_shared<const sim::SimulationState>(state));
    }
    void restore(const StateSlotPtr& from) override
    {
        ++requests;
        state = *from->state();
    }
    void addRegion(const std::vector<sim::Polygon>&) override { ++requests, addContour(); }
    void removeRegion(int region) override { ++requests, state = withoutRegion(state, region); }
    void drop(sim::Vec2, double) override { ++requests, addContour(); }
    void applyMap(const sim::ExactMap&) override { ++requests, ++maps; }
    void stylus(const std::vector<sim::StylusSegment>& pens) override { ++requests, state.time += pens.front().duration; }
    void gather(const std::shared_ptr<const sim::TargetDrive>& drive, double duration) override
    {
        ++requests, gathering = drive, gatherSeconds = duration;
    }
    std::uint64_t requestCount() const override { return requests; }

    void flow(double seconds) { state.time += seconds; }  // what playing does between requests
    Frame frame() const
    {
        Frame f;
        f.serial = requests;
        f.time = state.time;
        f.regions.resize(std::size_t(state.regionCount));
        return f;
    }

private:
    void addContour()
    {
        sim::Contour c;
        c.region = state.regionCount++;
        c.positions.assign(verticesPerRegion, sim::Vec2(0.5, 0.5));
        c.previous = c.positions;
        c.spacing.assign(verticesPerRegion, 0.004);
        state.contours.push_back(std::move(c));
    }
};

Scene sceneWithRegions(int n)
{
    Scene scene;
    for (int i = 0; i < n; ++i)
        scene.regions.push_back({QStringLiteral("r%1").arg(i), QColor(10 * i, 0, 0), true, CircleShape{{0.5, 0.5}, 0.1}});
    return scene;
}

QStringList names(const RegionTable& table)
{
    QStringList out;
    for (const RegionLook& r : table)
        out << r.name;
    return out;
}

} // namespace

class TestDocument : public QObject {
    Q_OBJECT

private slots:
    void dropUndoRedoGiveExactStates()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(1), QStringLiteral("reference"));
        port.flow(0.5);
        const sim::SimulationState start = port.state;
        doc.drop({0.3, 0.3}, 0.05, Qt::red);
        QCOMPARE(doc.undoStack().count(), 1);
        QCOMPARE(names(doc.regions()), QStringList({"r0", "drop"}));
        QCOMPARE(doc.regions().back().simIndex, 1);
        port.flow(0.25);  // the drop's flow runs on until undo
        const sim::SimulationState end = port.state;

        doc.undoStack().undo();
        QVERIFY(port.state == start);
        QCOMPARE(names(doc.regions()), QStringList({"r0"}));
        port.flow(1.0);  // playing on after the undo changes nothing recorded
        doc.undoStack().redo();
        QVERIFY(port.state == end);
        QCOMPARE(names(doc.regions()), QStringList({"r0", "drop"}));
        doc.undoStack().undo();
        QVERIFY(port.state == start);
    }

    // Drops by hand go on from the highest "drop N" a region has (a scene's drops), and start at
    // "drop" in a document that has none.
    void dropsGoOnNumbering()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(2), QStringLiteral("reference"));
        QVERIFY(doc.setRegionName(0, QStringLiteral("drop 5")));
        QVERIFY(doc.setRegionName(1, QStringLiteral("drop 12b")));  // not a number: no effect
        doc.drop({0.3, 0.3}, 0.05, Qt::red);
        doc.drop({0.6, 0.6}, 0.05, Qt::red);
        QCOMPARE(names(doc.regions()), QStringList({"drop 5", "drop 12b", "drop 6", "drop 7"}));
    }

    // A pattern is one command: its drops become regions named and coloured as drops are, its
    // passes maps; one undo takes all of it back. A pattern the canvas cannot hold does nothing.
    void patternIsOneCommand()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(1), QStringLiteral("reference"));
        const sim::SimulationState start = port.state;
        PatternStroke pattern{PatternStroke::Kind::Chevron, 0.0, CombStroke::Mode::Water, {Qt::red, Qt::blue}, 4, 0.2};
        doc.applyPattern(pattern);
        QCOMPARE(doc.undoStack().count(), 1);
        QCOMPARE(doc.undoStack().text(0), QStringLiteral("Pattern: chevron"));
        const int drops = int(std::ceil(1.0 / (std::numbers::pi * 0.04)));
        QCOMPARE(int(doc.regions().size()), 1 + drops);
        QCOMPARE(port.state.regionCount, 1 + drops);
        QCOMPARE(port.maps, 3);
        QCOMPARE(doc.regions()[1].name, QStringLiteral("drop"));
        QCOMPARE(doc.regions().back().simIndex, drops);
        for (std::size_t r = 1; r < doc.regions().size(); ++r)
            QVERIFY(doc.regions()[r].color == QColor(Qt::red) || doc.regions()[r].color == QColor(Qt::blue));

        doc.undoStack().undo();
        QVERIFY(port.state == start);
        QCOMPARE(names(doc.regions()), QStringList({"r0"}));
        doc.undoStack().redo();
        QCOMPARE(int(doc.regions().size()), 1 + drops);

        pattern.dropRadius = 1e-3;  // over 300,000 drops
        doc.applyPattern(pattern);
        QCOMPARE(doc.undoStack().count(), 1);
    }

    // A spatter is one command of its drops, in its colours.
    void spatterIsOneCommand()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(1), QStringLiteral("reference"));
        doc.spatter(SpatterStroke{0.0, {0.5, 0.5}, 0.2, 12, 0.01, 0.02, {Qt::green}, 3});
        QCOMPARE(doc.undoStack().count(), 1);
        QCOMPARE(doc.undoStack().text(0), QStringLiteral("Spatter"));
        QCOMPARE(int(doc.regions().size()), 13);
        QCOMPARE(port.state.regionCount, 13);
        QCOMPARE(doc.regions().back().color, QColor(Qt::green));
        doc.undoStack().undo();
        QCOMPARE(names(doc.regions()), QStringList({"r0"}));
    }

    // Gathering hands the drive to the simulation and is one command, holding what the steps after
    // it do until the next command; undo goes back to before it.
    void gatherIsOneCommandOverTheStepsItDrives()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(1), QStringLiteral("reference"));
        const sim::SimulationState before = port.state;
        const auto drive = std::make_shared<const sim::TargetDrive>(
            std::vector<std::vector<sim::Polygon>>{{sim::circle({0.5, 0.5}, 0.2, 0.01)}}, sim::FluidSettings{}, sim::TargetDriveSettings{});
        doc.gather(QStringLiteral("Gather into INK"), drive, 4.0);
        QCOMPARE(port.gathering, drive);
        QCOMPARE(port.gatherSeconds, 4.0);
        port.flow(2.0);
        const sim::SimulationState gathered = port.state;
        doc.drop({0.5, 0.5}, 0.1, Qt::blue);
        QCOMPARE(doc.undoStack().count(), 2);
        QCOMPARE(doc.undoStack().text(0), QStringLiteral("Gather into INK"));
        doc.undoStack().undo();
        QVERIFY(port.state == gathered);
        doc.undoStack().undo();
        QVERIFY(port.state == before);
    }

    void aCommandEndsWhereTheNextStarts()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(1), QStringLiteral("reference"));
        doc.beginStroke();
        doc.stroke({{{0.1, 0.1}, {0.2, 0.2}, 0.03, 0.1}});
        port.flow(0.4);
        const sim::SimulationState strokeEnd = port.state;
        doc.drop({0.5, 0.5}, 0.1, Qt::blue);
        port.flow(0.3);
        QCOMPARE(doc.undoStack().count(), 2);
        doc.undoStack().undo();  // the drop: back to where the stroke ended
        QVERIFY(port.state == strokeEnd);
        doc.undoStack().undo();
        doc.undoStack().redo();  // the stroke again: its end, not the state after the drop
        QVERIFY(port.state == strokeEnd);
    }

    void regionEditsAreCommandsAndBadEditsAreRefused()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(3), QStringLiteral("reference"));
        const RegionTable original = doc.regions();
        const std::uint64_t requestsBefore = port.requests;
        QVERIFY(doc.setRegionColor(0, Qt::green));
        QVERIFY(doc.setRegionName(1, QStringLiteral("  sky ")));
        QVERIFY(doc.setRegionVisible(2, false));
        QVERIFY(doc.moveRegion(0, 2));
        QCOMPARE(names(doc.regions()), QStringList({"sky", "r2", "r0"}));
        QCOMPARE(doc.regions()[2].color, QColor(Qt::green));
        QCOMPARE(doc.undoStack().count(), 4);
        QCOMPARE(port.requests, requestsBefore);  // looks only: the simulation is not involved

        QVERIFY(!doc.setRegionName(0, QStringLiteral("r2")));  // taken
        QVERIFY(!doc.setRegionName(0, QStringLiteral("   ")));
        QVERIFY(!doc.setRegionColor(5, Qt::red));
        QVERIFY(!doc.setRegionVisible(0, true));  // no change
        QVERIFY(!doc.moveRegion(1, 1));
        QCOMPARE(doc.undoStack().count(), 4);

        while (doc.undoStack().canUndo())
            doc.undoStack().undo();
        QVERIFY(doc.regions() == original);
    }

    void settingsChangeReconfiguresAndUndoesExactly()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(1), QStringLiteral("reference"));
        QSignalSpy changed(&doc, &Document::settingsChanged);
        EngineSettings s = doc.settings();
        s.flow.viscosity = shapeDesignPreset.viscosity;
        const sim::SimulationState start = port.state;
        doc.setSettings(s);
        QCOMPARE(port.configured.flow.viscosity, shapeDesignPreset.viscosity);
        QCOMPARE(changed.count(), 1);
        doc.setSettings(s);  // unchanged: no command
        QCOMPARE(doc.undoStack().count(), 1);
        port.flow(0.2);
        doc.undoStack().undo();
        QCOMPARE(port.configured.flow.viscosity, marblingPreset.viscosity);
        QCOMPARE(doc.settings().flow.viscosity, marblingPreset.viscosity);
        QVERIFY(port.state == start);
    }

    void theScenesOwnDropsGetTheirLooksFromFrames()
    {
        FakePort port;
        Document doc(port);
        Scene scene = sceneWithRegions(1);
        scene.strokes.push_back(DropStroke{0.1, {0.5, 0.5}, 0.05, QColor(1, 2, 3), QStringLiteral("late")});
        doc.openScene(scene, QStringLiteral("reference"));
        QVERIFY(!doc.canAddRegions());
        doc.drop({0.2, 0.2}, 0.05, Qt::red);  // refused: "late" is due to take index 1
        QCOMPARE(doc.undoStack().count(), 0);

        Frame stale = port.frame();
        port.flow(0.1);
        port.drop({0.5, 0.5}, 0.05);  // the worker lands the script's drop while playing
        Frame landed = port.frame();
        landed.serial = stale.serial;  // no request of the document's came in between
        doc.takeFrame(landed);
        QCOMPARE(names(doc.regions()), QStringList({"r0", "late"}));
        QCOMPARE(doc.regions()[1].color, QColor(1, 2, 3));
        QVERIFY(doc.canAddRegions());
        doc.drop({0.2, 0.2}, 0.05, Qt::red);
        QCOMPARE(doc.regions().back().simIndex, 2);
        // Deleting regions leaves fewer than the scene has looks: drops still go in.
        QVERIFY(doc.deleteRegion(0));
        QVERIFY(doc.deleteRegion(0));
        QCOMPARE(names(doc.regions()), QStringList({"drop"}));
        QCOMPARE(doc.regions()[0].simIndex, 0);
        QVERIFY(doc.canAddRegions());
        doc.undoStack().undo();
        doc.undoStack().undo();

        // A frame made before the document's last restore shows a replaced state: ignored.
        doc.undoStack().undo();
        Frame old = landed;
        old.regions.resize(3);
        doc.takeFrame(old);
        QCOMPARE(doc.regions().size(), std::size_t(2));
    }

    void undoInMidStrokeEndsTheStroke()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(1), QStringLiteral("reference"));
        const sim::SimulationState start = port.state;
        doc.beginStroke();
        doc.stroke({{{0.1, 0.1}, {0.2, 0.1}, 0.03, 0.05}});
        doc.undoStack().undo();
        QVERIFY(port.state == start);
        doc.stroke({{{0.2, 0.1}, {0.3, 0.1}, 0.03, 0.05}});  // the pen is still down
        QVERIFY2(port.state == start, "the rest of an undone stroke is dropped");
    }

    void lookUndoKeepsRegionsTheSceneLandedSince()
    {
        FakePort port;
        Document doc(port);
        Scene scene = sceneWithRegions(1);
        scene.strokes.push_back(DropStroke{1.0, {0.5, 0.5}, 0.05, QColor(1, 2, 3), QStringLiteral("late")});
        doc.openScene(scene, QStringLiteral("reference"));
        QVERIFY(doc.setRegionColor(0, Qt::green));
        port.drop({0.5, 0.5}, 0.05);  // the script's drop lands while playing
        doc.takeFrame(port.frame());
        QCOMPARE(doc.regions().size(), std::size_t(2));
        doc.undoStack().undo();
        QCOMPARE(names(doc.regions()), QStringList({"r0", "late"}));
        QCOMPARE(doc.regions()[0].color, QColor(0, 0, 0));
        doc.undoStack().redo();
        QCOMPARE(names(doc.regions()), QStringList({"r0", "late"}));
        QCOMPARE(doc.regions()[0].color, QColor(Qt::green));
    }

    void trimmingAfterASaveLeavesTheNewestCommandOpen()
    {
        FakePort port;
        port.verticesPerRegion = 1000;
        Document doc(port);
        doc.openScene(sceneWithRegions(10), QStringLiteral("reference"));
        doc.drop({0.5, 0.5}, 0.01, Qt::red);
        doc.undoStack().setClean();  // saved here
        doc.setHistoryBudget(4 * port.state.bytes());
        for (int i = 0; i < 6; ++i)
            doc.drop({0.5, 0.5}, 0.01, Qt::red);
        QSignalSpy trimmed(&doc, &Document::historyTrimmed);
        doc.beginStroke();  // trims: the saved state goes, the stroke stays open
        QVERIFY(!trimmed.isEmpty());
        QVERIFY(doc.isModified());
        const sim::SimulationState start = port.state;
        doc.stroke({{{0.1, 0.1}, {0.2, 0.1}, 0.03, 0.05}});
        QVERIFY2(!(port.state == start), "the stroke still moves the fluid");
        const sim::SimulationState end = port.state;
        doc.undoStack().undo();
        QVERIFY(port.state == start);
        doc.undoStack().redo();
        QVERIFY(port.state == end);
    }

    void historyKeepsToItsBudget()
    {
        FakePort port;
        port.verticesPerRegion = 1000;
        Document doc(port);
        doc.openScene(sceneWithRegions(10), QStringLiteral("reference"));  // states grow slowly with drops
        QSignalSpy trimmed(&doc, &Document::historyTrimmed);
        const std::size_t oneState = port.state.bytes();
        doc.setHistoryBudget(8 * oneState);
        std::vector<sim::SimulationState> starts;
        for (int i = 0; i < 12; ++i) {
            port.flow(0.1);
            starts.push_back(port.state);
            doc.drop({0.5, 0.5}, 0.01, Qt::red);
        }
        QVERIFY(!trimmed.isEmpty());
        QVERIFY(doc.historyBytes() <= doc.historyBudget());
        QVERIFY(doc.undoStack().count() > 1 && doc.undoStack().count() < 12);
        QVERIFY(!doc.undoStack().isClean());
        // What is left undoes to exactly the states it started from, newest first.
        const int kept = doc.undoStack().count();
        for (int i = 0; i < kept; ++i) {
            doc.undoStack().undo();
            QVERIFY(port.state == starts[starts.size() - 1 - i]);
        }
        QVERIFY(!doc.undoStack().canUndo());
        QCOMPARE(int(doc.regions().size()), 10 + 12 - kept);
    }

    void savingWhileACommandRunsRecordsItsEndAsNow()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(1), QStringLiteral("reference"));
        EngineSettings s = doc.settings();
        s.flow.viscosity = shapeDesignPreset.viscosity;
        doc.setSettings(s);
        doc.drop({0.5, 0.5}, 0.1, Qt::red);
        port.flow(0.5);
        const Project project = doc.draftProject().finish();  // the drop is still running
        QVERIFY(*project.history[1].after == project.state);
        QVERIFY(project.history[1].regionsAfter == doc.regions());
        QCOMPARE(project.history[1].flowAfter.viscosity, shapeDesignPreset.viscosity);
        QVERIFY(doc.undoStack().command(1) && doc.isModified());

        FakePort port2;
        Document reopened(port2);
        reopened.openProject(project, QStringLiteral("reference"));
        reopened.undoStack().undo();
        reopened.undoStack().redo();
        QVERIFY(port2.state == project.state);
        QVERIFY(reopened.regions() == doc.regions());
        QCOMPARE(port2.configured.flow.viscosity, shapeDesignPreset.viscosity);
    }

    void projectReopensWithItsHistory()
    {
        FakePort port;
        Document doc(port);
        doc.openScene(sceneWithRegions(2), QStringLiteral("reference"));
        doc.drop({0.5, 0.5}, 0.1, Qt::red);
        port.flow(0.5);
        QVERIFY(doc.setRegionColor(0, Qt::yellow));
        doc.drop({0.2, 0.5}, 0.1, Qt::blue);
        doc.undoStack().undo();
        const Project project = doc.draftProject().finish();
        QCOMPARE(project.history.size(), std::size_t(3));
        QCOMPARE(project.historyIndex, 2);
        QVERIFY(project.history[0].after);  // closed when the recolour started
        QVERIFY(!project.history[1].before);  // the recolour left the simulation alone

        FakePort port2;
        Document reopened(port2);
        reopened.openProject(project, QStringLiteral("reference"));
        QVERIFY(port2.state == project.state);
        QVERIFY(reopened.regions() == doc.regions());
        QCOMPARE(reopened.undoStack().count(), 3);
        QCOMPARE(reopened.undoStack().index(), 2);
        QVERIFY(reopened.undoStack().isClean());
        reopened.undoStack().redo();
        QVERIFY(port2.state == *project.history[2].after);
        reopened.undoStack().undo();
        reopened.undoStack().undo();
        reopened.undoStack().undo();
        QVERIFY(port2.state == *project.history[0].before);
        QCOMPARE(int(reopened.regions().size()), 2);
    }

    void regionModelFollowsTheDocument()
    {
        FakePort port;
        Document doc(port);
        RegionListModel model(doc);
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        doc.openScene(sceneWithRegions(3), QStringLiteral("reference"));
        QCOMPARE(model.rowCount(), 3);
        QCOMPARE(model.index(0).data().toString(), QStringLiteral("r2"));  // topmost first

        QVERIFY(model.setData(model.index(0), QStringLiteral("top"), Qt::EditRole));
        QVERIFY(model.setData(model.index(1), QColor(Qt::cyan), RegionListModel::ColorRole));
        QVERIFY(model.setData(model.index(2), Qt::Unchecked, Qt::CheckStateRole));
        QCOMPARE(doc.regions()[2].name, QStringLiteral("top"));
        QCOMPARE(doc.regions()[1].color, QColor(Qt::cyan));
        QVERIFY(!doc.regions()[0].visible);
        QVERIFY(!model.setData(model.index(0), QString(), Qt::EditRole));

        // Drag the bottom row to the top, as the view's internal move does.
        std::unique_ptr<QMimeData> mime(model.mimeData({model.index(2)}));
        QVERIFY(!model.dropMimeData(mime.get(), Qt::MoveAction, 0, 0, {}));  // false: nothing for the view to remove
        QCOMPARE(model.index(0).data().toString(), QStringLiteral("r0"));
        QCOMPARE(model.rowCount(), 3);
        QCOMPARE(doc.undoStack().count(), 4);
        doc.undoStack().undo();
        QCOMPARE(model.index(0).data().toString(), QStringLiteral("top"));
    }

    // A reorder, its undo and its redo move one row: no reset, and an index held on the moved row
    // (a view's selection) follows it.
    void regionReorderMovesTheRow_data()
    {
        QTest::addColumn<int>("from");
        QTest::addColumn<int>("to");
        QTest::newRow("bottom to top") << 0 << 3;
        QTest::newRow("top to bottom") << 3 << 0;
        QTest::newRow("one up") << 1 << 2;
    }
    void regionReorderMovesTheRow()
    {
        QFETCH(int, from);
        QFETCH(int, to);
        FakePort port;
        Document doc(port);
        RegionListModel model(doc);
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        doc.openScene(sceneWithRegions(4), QStringLiteral("reference"));
        const QString name = doc.regions()[std::size_t(from)].name;
        const QPersistentModelIndex held(model.index(model.rowOf(from)));
        QSignalSpy resets(&model, &QAbstractItemModel::modelReset);
        QSignalSpy moves(&model, &QAbstractItemModel::rowsMoved);
        QVERIFY(doc.moveRegion(from, to));
        QCOMPARE(doc.regions()[std::size_t(to)].name, name);
        QCOMPARE(held.row(), model.rowOf(to));
        QCOMPARE(held.data().toString(), name);
        doc.undoStack().undo();
        QCOMPARE(held.row(), model.rowOf(from));
        doc.undoStack().redo();
        QCOMPARE(held.row(), model.rowOf(to));
        QCOMPARE(moves.count(), 3);
        QCOMPARE(resets.count(), 0);
    }
};

QTEST_GUILESS_MAIN(TestDocument)
#include "tst_document.moc"
