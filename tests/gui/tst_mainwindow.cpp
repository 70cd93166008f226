// The main window, driven as a user drives it: real widgets, QTest mouse and key events, the real
// simulation worker (reference backend, paused, stepped explicitly so that every run is the
// same, but while a stroke is drawn). Each test checks the document, the undo stack and the
// geometry; pixels only for what exists only as pixels (a stroke's trail). Shortcuts are pressed
// on the window, never triggered, and a key Qt finds ambiguous fails any test.
// One file past 500 lines: the cases share the window fixture below; docks and dialogs with their
// own state are tested in files of their own.
#include "FindChild.h"
#include "WindowTest.h"
#include "app/AnimationDialog.h"
#include "app/ExportDialog.h"
#include "app/Folders.h"
#include "app/KernelWarmUp.h"
#include "app/MainWindow.h"
#include "app/Recovery.h"
#include "model/ProjectFile.h"
#include "model/SceneFile.h"
#include "render/Exporter.h"

#include <glm/geometric.hpp>

#include <QAction>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFontDialog>
#include <QHash>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QXmlStreamReader>

using namespace vf;
using namespace vf::app;

namespace {

using Geometry = std::vector<std::vector<sim::Polygon>>;

model::Scene smallScene()
{
    model::Scene scene;
    scene.flow.gridX = scene.flow.gridY = 32;
    scene.time.dt = 0.01;
    scene.tracking.maxSpacing = 0.01;
    scene.regions.push_back({QStringLiteral("ink"), QColor(0x1d, 0x35, 0x57), true, model::CircleShape{{0.5, 0.5}, 0.2}});
    scene.regions.push_back({QStringLiteral("slab"), QColor(0xe6, 0x39, 0x46), true,
                             model::RectShape{{0.1, 0.1}, {0.3, 0.1}}});
    return scene;
}

Geometry geometry(MainWindow& w)
{
    w.simulation().sync();
    return w.simulation().frame()->regions;
}

double largestMove(const Geometry& a, const Geometry& b)
{
    // Vertex counts change as contours refine, so compare the centroids of each region's area,
    // which a vertex added on the curve or removed from it barely moves.
    double most = 0.0;
    for (std::size_t r = 0; r < std::min(a.size(), b.size()); ++r) {
        auto centroid = [](const std::vector<sim::Polygon>& contours) {
            sim::Vec2 moment(0.0);
            double area = 0.0;
            for (const auto& c : contours) {
                for (std::size_t i = 0; i < c.size(); ++i) {
                    const sim::Vec2 p = c[i], q = c[(i + 1) % c.size()];
                    const double cross = p.x * q.y - q.x * p.y;
                    area += 0.5 * cross;
                    moment += cross / 6.0 * (p + q);
                }
            }
            return area != 0.0 ? moment / area : moment;
        };
        most = std::max(most, glm::length(centroid(a[r]) - centroid(b[r])));
    }
    return most;
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        test::useTestSettings("tst_mainwindow", m_dir);
        // The cases on OpenCL start on the device, as a launch after the first does
        // (tst_kernelwarmup tests the first).
        QCOMPARE(KernelWarmUp::prepare(std::nullopt), QString());
        m_scenePath = m_dir.filePath(QStringLiteral("small.vfscene"));
        QCOMPARE(model::writeSceneFile(smallScene(), m_scenePath), QString());
    }

    void init()
    {
        // Qt says so, and runs neither action, when a key press matches two shortcuts.
        QTest::failOnWarning(QRegularExpression(QStringLiteral("Ambiguous shortcut")));
        m_window = std::make_unique<MainWindow>();
        m_window->setAsk([this](const QString&, const QString& text, QMessageBox::StandardButtons) {
            m_questions << text;
            return m_answer;
        });
        m_window->setReport([this](const QString&, const QString& text) { m_reports << text; });
        QVERIFY(test::showActive(*m_window));
        QVERIFY(m_window->openFile(m_scenePath));
        m_window->simulation().setPlaying(false);
        geometry(*m_window);
        m_reports.clear();
        m_questions.clear();
    }

    void cleanup()
    {
        if (m_window)
            m_window->document().undoStack().setClean();  // no prompt on close
        m_window.reset();
    }

    void dropToolClickAddsARegionShownInTheRegionsView()
    {
        MainWindow& w = *m_window;
        test::child<QAction>(w, "toolDrop")->trigger();
        const QPoint at = w.canvas().mapFromCanvas({0.75, 0.75}).toPoint();
        QTest::mouseClick(&w.canvas(), Qt::LeftButton, {}, at);
        const Geometry g = geometry(w);
        QCOMPARE(g.size(), std::size_t(3));
        QCOMPARE(w.document().regions().size(), std::size_t(3));
        QCOMPARE(w.regionView().model()->rowCount(), 3);
        QCOMPARE(w.regionView().model()->index(0, 0).data().toString(), QStringLiteral("drop"));  // on top
        QCOMPARE(w.document().undoStack().count(), 1);
        // The new ink is a disc around where the click landed.
        sim::Vec2 sum(0.0);
        for (const sim::Vec2& p : g[2][0])
            sum += p;
        const sim::Vec2 centre = sum / double(g[2][0].size());
        QVERIFY2(glm::length(centre - sim::Vec2(0.75, 0.75)) < 0.01, "the drop landed where the click was");
    }

    void aSceneTheDeviceCannotHoldRunsOnTheReferenceBackend()
    {
        MainWindow& w = *m_window;
        QSignalSpy notices(&w.simulation(), &SimulationController::notice);
        qputenv("VF_OPENCL_MAX_VERTICES", "64");  // a device too small for the scene's two hundred vertices
        w.document().openScene(smallScene(), QStringLiteral("opencl"));
        const Geometry g = geometry(w);
        qunsetenv("VF_OPENCL_MAX_VERTICES");
        QCOMPARE(QString::fromStdString(w.simulation().frame()->backend), QStringLiteral("reference"));
        QCOMPARE(g.size(), std::size_t(2));
        QTRY_VERIFY(!notices.isEmpty());
        QVERIFY2(notices.front().front().toString().contains(QStringLiteral("reference backend")),
                 qPrintable(notices.front().front().toString()));
    }

    void stylusDragMovesInk()
    {
        MainWindow& w = *m_window;
        const Geometry before = geometry(w);
        test::child<QAction>(w, "toolStylus")->trigger();
        Canvas& canvas = w.canvas();
        QTest::mousePress(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({0.2, 0.5}).toPoint());
        for (int i = 1; i <= 6; ++i) {
            QTest::mouseMove(&canvas, canvas.mapFromCanvas({0.2 + 0.1 * i, 0.5}).toPoint(), 15);
        }
        QTest::mouseRelease(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({0.8, 0.5}).toPoint(), 15);
        for (int i = 0; i < 10; ++i)
            w.simulation().stepOnce();
        const Geometry after = geometry(w);
        QCOMPARE(w.document().undoStack().count(), 1);
        QCOMPARE(w.document().undoStack().text(0), QStringLiteral("Stylus stroke"));
        QVERIFY2(largestMove(before, after) > 0.005, "the stroke pushed the ink along");
    }

    // Paused, a stroke still shows what it does: its trail while the pen is down, and the water
    // running under it; the simulation pauses again when the pen lifts.
    void strokeWhilePausedShowsItsTrailAndMovesTheWater()
    {
        MainWindow& w = *m_window;
        Canvas& canvas = w.canvas();
        const QAction* play = test::child<QAction>(w, "play");
        QTest::keyClick(&w, Qt::Key_S);
        QCOMPARE(canvas.tool(), Tool::Stylus);
        const Geometry before = geometry(w);
        const std::int64_t stepsBefore = w.simulation().frame()->steps;
        const QPoint onTrail = canvas.mapFromCanvas({0.2, 0.5}).toPoint();  // bare water, behind the pen
        const QColor water = canvas.grab().toImage().pixelColor(onTrail);

        QTest::mousePress(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({0.15, 0.5}).toPoint());
        for (int i = 1; i <= 10; ++i) {
            QTest::qWait(20);  // time for the worker to step while the pen is down
            QTest::mouseMove(&canvas, canvas.mapFromCanvas({0.15 + 0.05 * i, 0.5}).toPoint(), 20);
        }
        QVERIFY2(canvas.grab().toImage().pixelColor(onTrail) != water, "the trail shows behind the pen");
        QTRY_VERIFY2(w.simulation().frame()->steps > stepsBefore, "the water runs while the pen is down");
        // A slow build (sanitisers) may have stepped only once by now; the water keeps running
        // while the pen rests, so wait for the ink to show the stroke rather than racing the worker.
        QTRY_VERIFY2(largestMove(before, geometry(w)) > 0.001, "the ink moved without Play");
        QVERIFY(!play->isChecked());
        QTest::mouseRelease(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({0.65, 0.5}).toPoint(), 20);

        QCOMPARE(canvas.grab().toImage().pixelColor(onTrail), water);  // the trail goes with the pen
        const Geometry atRelease = geometry(w);
        const std::int64_t stepsAtRelease = w.simulation().frame()->steps;
        QTest::qWait(100);
        QVERIFY(geometry(w) == atRelease);
        QCOMPARE(w.simulation().frame()->steps, stepsAtRelease);  // paused again
        QVERIFY(!play->isChecked());
    }

    // The status bar gives the simulated time: a single step (the . key) advances it by one dt.
    void statusBarShowsTheSimulatedTime()
    {
        MainWindow& w = *m_window;
        const QLabel* time = test::child<QLabel>(w, "simulatedTime");
        w.document().openScene(smallScene(), QStringLiteral("reference"));  // dt 0.01
        QTRY_COMPARE(time->text(), QStringLiteral("0.00 s"));
        QTest::keyClick(&w, Qt::Key_Period);
        QTRY_COMPARE(time->text(), QStringLiteral("0.01 s"));
    }

    void velocityOverlayGetsTheField()
    {
        MainWindow& w = *m_window;
        w.simulation().sync();
        QVERIFY(!w.simulation().frame()->velocity);  // not read back while nobody shows it
        test::child<QAction>(w, "showVelocity")->trigger();
        w.document().beginStroke();
        w.document().stroke({{{0.2, 0.5}, {0.8, 0.5}, 0.05, 0.1}});
        w.simulation().stepOnce();
        w.simulation().sync();
        const auto& field = w.simulation().frame()->velocity;
        QVERIFY(field);
        QCOMPARE(field->nx, 32);
        QVERIFY(glm::length(field->sample({0.5, 0.5})) > 0.0);
    }

    void undoAndRedoRestoreExactGeometry_data()
    {
        QTest::addColumn<QString>("backend");
        QTest::newRow("reference") << QStringLiteral("reference");
        QTest::newRow("opencl") << QStringLiteral("opencl");
    }

    void undoAndRedoRestoreExactGeometry()
    {
        QFETCH(QString, backend);
        MainWindow& w = *m_window;
        w.document().openScene(smallScene(), backend);
        w.simulation().sync();
        if (!QString::fromStdString(w.simulation().frame()->backend).startsWith(backend))
            QSKIP("no OpenCL device here: the app fell back to the reference backend");
        for (int i = 0; i < 3; ++i)
            w.simulation().stepOnce();
        const Geometry start = geometry(w);
        test::child<QAction>(w, "toolDrop")->trigger();
        QTest::mouseClick(&w.canvas(), Qt::LeftButton, {}, w.canvas().mapFromCanvas({0.5, 0.45}).toPoint());
        for (int i = 0; i < 5; ++i)
            w.simulation().stepOnce();
        const Geometry end = geometry(w);
        QVERIFY(end != start);

        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(geometry(w) == start);
        QCOMPARE(w.document().regions().size(), std::size_t(2));
        w.simulation().stepOnce();  // flow after the undo is not part of any command
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(geometry(w) == end);
        QCOMPARE(w.document().regions().size(), std::size_t(3));
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(geometry(w) == start);
    }

    void redoAnswersBothKeys()
    {
        MainWindow& w = *m_window;
        test::child<QAction>(w, "toolDrop")->trigger();
        QTest::mouseClick(&w.canvas(), Qt::LeftButton, {}, w.canvas().mapFromCanvas({0.7, 0.7}).toPoint());
        QCOMPARE(w.document().regions().size(), std::size_t(3));
        const QKeySequence redoKeys[] = {QKeySequence(Qt::CTRL | Qt::Key_Y), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)};
        for (const QKeySequence& redo : redoKeys) {
            QTest::keySequence(&w, QKeySequence::Undo);
            QCOMPARE(w.document().regions().size(), std::size_t(2));
            QTest::keySequence(&w, redo);
            QVERIFY2(w.document().regions().size() == 3, qPrintable(redo.toString() + " redid nothing"));
        }
    }

    // Each tool's key, pressed on the window, picks the tool.
    void toolsAnswerTheirKeys()
    {
        MainWindow& w = *m_window;
        const struct {
            Qt::Key key;
            Tool tool;
            const char* action;
        } tools[] = {{Qt::Key_V, Tool::Select, "toolSelect"}, {Qt::Key_S, Tool::Stylus, "toolStylus"},
                     {Qt::Key_T, Tool::Text, "toolText"},     {Qt::Key_H, Tool::Pan, "toolPan"},
                     {Qt::Key_B, Tool::Spatter, "toolSpatter"}, {Qt::Key_C, Tool::Comb, "toolComb"},
                     {Qt::Key_O, Tool::CircularComb, "toolCircularComb"}, {Qt::Key_W, Tool::Swirl, "toolSwirl"},
                     {Qt::Key_D, Tool::Drop, "toolDrop"}};
        for (const auto& t : tools) {
            QTest::keyClick(&w, t.key);
            QVERIFY2(w.canvas().tool() == t.tool, qPrintable(QKeySequence(t.key).toString() + " picked no tool"));
            QVERIFY(test::child<QAction>(w, t.action)->isChecked());
        }
    }

    // Space plays and pauses, the full stop steps once while paused, Ctrl+R resets.
    void playStepAndResetAnswerTheirKeys()
    {
        MainWindow& w = *m_window;
        const QAction* play = test::child<QAction>(w, "play");
        w.simulation().sync();
        const std::int64_t steps = w.simulation().frame()->steps;
        QTest::keyClick(&w, Qt::Key_Period);
        w.simulation().sync();
        QCOMPARE(w.simulation().frame()->steps, steps + 1);

        QTest::keyClick(&w, Qt::Key_Space);
        QVERIFY(play->isChecked() && w.simulation().isPlaying());
        QTRY_VERIFY(w.simulation().frame()->steps > steps + 2);
        QTest::keyClick(&w, Qt::Key_Space);
        QVERIFY(!play->isChecked() && !w.simulation().isPlaying());

        QTest::keySequence(&w, QKeySequence(Qt::CTRL | Qt::Key_R));
        QCOMPARE(w.document().undoStack().text(w.document().undoStack().index() - 1), QStringLiteral("Reset"));
        w.simulation().sync();
        QCOMPARE(w.simulation().frame()->steps, std::int64_t(0));
    }

    // Zoom in and out by the platform's keys, Ctrl+1 for the export size, Ctrl+0 to fit again.
    void zoomAnswersItsKeys()
    {
        MainWindow& w = *m_window;
        const Canvas& canvas = w.canvas();
        const double fitted = canvas.zoom();
        QTest::keySequence(&w, QKeySequence(QKeySequence::ZoomIn));
        QVERIFY(canvas.zoom() > fitted * 1.1);
        QTest::keySequence(&w, QKeySequence(QKeySequence::ZoomOut));
        QTest::keySequence(&w, QKeySequence(QKeySequence::ZoomOut));
        QVERIFY(canvas.zoom() < fitted / 1.1);
        QTest::keySequence(&w, QKeySequence(Qt::CTRL | Qt::Key_1));
        QVERIFY(std::abs(canvas.zoom() - fitted) > 1e-6 * fitted);
        const double actual = canvas.zoom();
        QTest::keySequence(&w, QKeySequence(Qt::CTRL | Qt::Key_0));
        QCOMPARE(canvas.zoom(), fitted);
        QTest::keySequence(&w, QKeySequence(Qt::CTRL | Qt::Key_1));
        QCOMPARE(canvas.zoom(), actual);
    }

    // Save As by its key opens the dialog (answered with Cancel here: nothing is written).
    void saveAsAnswersItsKey()
    {
        MainWindow& w = *m_window;
        bool asked = false;
        test::whenModal<QFileDialog>([&asked](QFileDialog* dialog) {
            asked = true;
            dialog->reject();
        });
        QTest::keySequence(&w, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
        QVERIFY(asked);
    }

    // A key given to two actions, or twice to one, is ambiguous: Qt then runs neither. Every
    // action the window holds and every one its menus and tool bars show, whoever owns it.
    void noShortcutIsAmbiguous()
    {
        const QList<QAction*> children = m_window->findChildren<QAction*>();
        QSet<QAction*> actions(children.begin(), children.end());
        QList<QWidget*> holders{m_window->menuBar()};
        for (QToolBar* bar : m_window->findChildren<QToolBar*>())
            holders << bar;
        while (!holders.isEmpty()) {
            for (QAction* action : holders.takeLast()->actions()) {
                actions.insert(action);
                if (action->menu())
                    holders << action->menu();
            }
        }
        QHash<QKeySequence, QString> owner;
        for (const QAction* action : actions) {
            if (action->shortcutContext() == Qt::WidgetShortcut)
                continue;
            for (const QKeySequence& key : action->shortcuts()) {
                const QString name = action->text().remove(QLatin1Char('&'));
                QVERIFY2(!owner.contains(key), qPrintable(key.toString() + " is given to both " + owner.value(key) +
                                                             " and " + name));
                owner.insert(key, name);
            }
        }
        QVERIFY(owner.size() > 10);
    }

    void recolourRenameAndReorderThroughTheViewAreUndoable()
    {
        MainWindow& w = *m_window;
        QListView& view = w.regionView();
        QAbstractItemModel& model = *view.model();
        // Rename in place: select the top row, F2, type, Enter.
        view.setCurrentIndex(model.index(0, 0));
        view.setFocus();
        QTest::keyClick(&view, Qt::Key_F2);
        auto* editor = qobject_cast<QLineEdit*>(QApplication::focusWidget());
        QVERIFY(editor);
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("header"));
        QTest::keyClick(editor, Qt::Key_Return);
        // The delegate commits on Return through a queued call.
        QTRY_COMPARE(w.document().regions()[1].name, QStringLiteral("header"));
        // Recolour through the model the view shows (the colour dialog itself is Qt's).
        QVERIFY(model.setData(model.index(1, 0), QColor(Qt::darkGreen), model::RegionListModel::ColorRole));
        QCOMPARE(w.document().regions()[0].color, QColor(Qt::darkGreen));
        // Reorder with the dock's Lower button: the top region goes under.
        view.setCurrentIndex(model.index(0, 0));
        QTest::mouseClick(test::child<QPushButton>(w, "lower"), Qt::LeftButton);
        QCOMPARE(w.document().regions()[0].name, QStringLiteral("header"));
        QCOMPARE(model.index(1, 0).data().toString(), QStringLiteral("header"));
        QCOMPARE(view.currentIndex().data().toString(), QStringLiteral("header"));  // the selection moved with it
        QCOMPARE(w.document().undoStack().count(), 3);

        w.document().undoStack().undo();
        QCOMPARE(w.document().regions()[1].name, QStringLiteral("header"));
        w.document().undoStack().undo();
        QCOMPARE(w.document().regions()[0].color, QColor(0x1d, 0x35, 0x57));
        w.document().undoStack().undo();
        QCOMPARE(w.document().regions()[1].name, QStringLiteral("slab"));
    }

    // The title names the scene the document came from, then the project it was saved as.
    void titleNamesTheDocument()
    {
        MainWindow& w = *m_window;
        QVERIFY2(w.windowTitle().startsWith(QStringLiteral("small[*]")), qPrintable(w.windowTitle()));
        QVERIFY(w.saveTo(m_dir.filePath(QStringLiteral("named.vfproj"))));
        QVERIFY2(w.windowTitle().startsWith(QStringLiteral("named.vfproj[*]")), qPrintable(w.windowTitle()));
    }

    void saveAndOpenRoundTripExactly()
    {
        MainWindow& w = *m_window;
        w.document().drop({0.3, 0.7}, 0.08, Qt::magenta);
        for (int i = 0; i < 4; ++i)
            w.simulation().stepOnce();
        QVERIFY(w.document().setRegionName(0, QStringLiteral("base")));
        const Geometry saved = geometry(w);
        const QString path = m_dir.filePath(QStringLiteral("work.vfproj"));
        QVERIFY(w.saveTo(path));
        QVERIFY(!w.document().isModified());
        QCOMPARE(model::readProjectFile(path).project.steps, 4);

        MainWindow other;
        other.setReport([this](const QString&, const QString& text) { m_reports << text; });
        QVERIFY(other.openFile(path));
        other.simulation().setPlaying(false);
        QVERIFY(geometry(other) == saved);
        QVERIFY(other.document().regions() == w.document().regions());
        QCOMPARE(other.document().undoStack().count(), 2);
        QVERIFY(!other.document().isModified());
        // The history came along: undoing both commands reaches the scene's start.
        other.document().undoStack().undo();
        other.document().undoStack().undo();
        QCOMPARE(geometry(other).size(), std::size_t(2));
        QCOMPARE(other.document().regions()[0].name, QStringLiteral("ink"));
        QVERIFY(m_reports.isEmpty());
    }

    void saveShortcutWritesInTheBackground()
    {
        MainWindow& w = *m_window;
        const QString path = m_dir.filePath(QStringLiteral("background.vfproj"));
        QVERIFY(w.saveTo(path));
        w.document().drop({0.4, 0.4}, 0.05, Qt::blue);
        QVERIFY(w.document().isModified());
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier);
        QTRY_VERIFY(!w.document().isModified());
        QCOMPARE(model::readProjectFile(path).project.history.size(), std::size_t(1));
        QVERIFY(m_reports.isEmpty());

        // The history moves on (undo, then a new command at the same index) before the save's
        // result comes back: the document must stay unsaved.
        QTest::keyClick(&w, Qt::Key_S, Qt::ControlModifier);
        w.document().undoStack().undo();
        w.document().drop({0.6, 0.4}, 0.05, Qt::red);
        QTRY_COMPARE(w.statusBar()->currentMessage(), QStringLiteral("Saved background.vfproj"));
        QVERIFY(w.document().isModified());
    }

    void savedWhileTheFlowRunsRedoesToTheSavedState()
    {
        MainWindow& w = *m_window;
        const Geometry start = geometry(w);
        w.document().drop({0.3, 0.7}, 0.08, Qt::magenta);
        for (int i = 0; i < 4; ++i)
            w.simulation().stepOnce();
        const Geometry saved = geometry(w);  // the drop's command is still open: it ends here
        const QString path = m_dir.filePath(QStringLiteral("running.vfproj"));
        QVERIFY(w.saveTo(path));

        MainWindow other;
        QVERIFY(other.openFile(path));
        other.simulation().setPlaying(false);
        QVERIFY(geometry(other) == saved);
        other.document().undoStack().undo();
        QVERIFY(geometry(other) == start);
        other.document().undoStack().redo();
        QVERIFY(geometry(other) == saved);
        QVERIFY(other.document().regions() == w.document().regions());
    }

    void exportDialogWritesFilesThatReadersAccept()
    {
        MainWindow& w = *m_window;
        w.simulation().sync();
        ExportDialog dialog(w.drawing(), &w);
        const QString svg = m_dir.filePath(QStringLiteral("picture.svg"));
        test::child<QLineEdit>(dialog, "path")->setText(svg);
        QTest::mouseClick(test::child<QPushButton>(dialog, "export"), Qt::LeftButton);
        QCOMPARE(dialog.lastError(), QString());
        QFile file(svg);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&file);
        int paths = 0;
        while (!xml.atEnd())
            if (xml.readNext() == QXmlStreamReader::StartElement && xml.name() == QLatin1String("path"))
                ++paths;
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QCOMPARE(paths, 2);
    }

    // Ctrl+E, a path, Export: the status bar names the file written.
    void finishedExportShowsThePathInTheStatusBar()
    {
        MainWindow& w = *m_window;
        const QString svg = m_dir.filePath(QStringLiteral("shown.svg"));
        test::whenModal<ExportDialog>([svg](ExportDialog* dialog) {
            test::child<QLineEdit>(*dialog, "path")->setText(svg);
            QTest::mouseClick(test::child<QPushButton>(*dialog, "export"), Qt::LeftButton);
        });
        QTest::keySequence(&w, QKeySequence(Qt::CTRL | Qt::Key_E));
        QVERIFY(QFileInfo::exists(svg));
        QVERIFY2(w.statusBar()->currentMessage().contains(QDir::toNativeSeparators(svg)), qPrintable(w.statusBar()->currentMessage()));
    }

    // File ▸ Export Animation… by mouse: the dialog plays the document's scene in a simulation of
    // its own and the status bar names the file; the window's geometry and undo history stay as
    // they were.
    void exportAnimationByMenuLeavesTheDocument()
    {
        MainWindow& w = *m_window;
        const Geometry before = geometry(w);
        const int commands = w.document().undoStack().count();
        const QString json = m_dir.filePath(QStringLiteral("animation.json"));
        test::whenModal<AnimationDialog>([json](AnimationDialog* dialog) {
            test::child<QLineEdit>(*dialog, "path")->setText(json);
            test::child<QDoubleSpinBox>(*dialog, "end")->setValue(0.1);
            QTest::mouseClick(test::child<QPushButton>(*dialog, "export"), Qt::LeftButton);
            static_cast<void>(QTest::qWaitFor([dialog] { return !dialog->running(); }, 30000));  // checked below
            QTest::mouseClick(test::child<QPushButton>(*dialog, "close"), Qt::LeftButton);  // closes it, done or not
        });
        test::clickFileMenuItem(w, QStringLiteral("Export &Animation"));
        QVERIFY(QFileInfo::exists(json));
        QVERIFY2(w.statusBar()->currentMessage().contains(QDir::toNativeSeparators(json)), qPrintable(w.statusBar()->currentMessage()));
        QVERIFY(geometry(w) == before);
        QCOMPARE(w.document().undoStack().count(), commands);
    }

    // File ▸ Save As… by mouse: the dialog offers the scene's name in the documents folder (or
    // home); after a save there, the next Save As starts in that folder.
    void saveAsSuggestsTheSceneNameInTheLastFolder()
    {
        MainWindow& w = *m_window;
        QSettings().remove(QStringLiteral("files/saveFolder"));
        QString offered;
        const auto saveAsByMouse = [&w, &offered](const QString& typed) {
            test::whenModal<QFileDialog>([&offered, typed](QFileDialog* dialog) {
                offered = dialog->selectedFiles().value(0);
                if (typed.isEmpty())
                    return dialog->reject();
                auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
                if (!name)
                    return dialog->reject();  // fails the comparisons below rather than hanging
                // Set, not typed: typing opens the name's completer, which under a slow (sanitizer)
                // build can still be up to take the Return, leaving the dialog open.
                name->setText(typed);
                QTest::keyClick(name, Qt::Key_Return);
            });
            test::clickFileMenuItem(w, QStringLiteral("Save &As"));
        };
        saveAsByMouse({});
        QCOMPARE(offered, QDir(documentsFolder()).filePath(QStringLiteral("small.vfproj")));
        QVERIFY(QFileInfo(offered).absoluteDir().exists());

        const QString folder = m_dir.filePath(QStringLiteral("projects"));
        QVERIFY(QDir().mkpath(folder));
        saveAsByMouse(QDir(folder).filePath(QStringLiteral("first.vfproj")));
        QTRY_VERIFY(QFileInfo::exists(QDir(folder).filePath(QStringLiteral("first.vfproj"))));
        w.newDocument();
        saveAsByMouse({});
        QCOMPARE(offered, QDir(folder).filePath(QStringLiteral("Untitled.vfproj")));
    }

    void switchingModesSetsThePreset()
    {
        MainWindow& w = *m_window;
        QCOMPARE(w.document().settings().flow.viscosity, model::marblingPreset.viscosity);
        test::child<QAction>(w, "modeShapeDesign")->trigger();
        QVERIFY(model::isPreset(w.document().settings().flow, model::FluidMode::ShapeDesign));
        QCOMPARE(w.document().undoStack().count(), 1);
        // Shape design: motion dies within half a second of a stroke (paper §5.2; 100 steps of 5 ms).
        w.document().beginStroke();
        w.document().stroke({{{0.2, 0.5}, {0.8, 0.5}, model::shapeDesignPreset.stylusRadius, 0.1}});
        w.simulation().stepOnce();
        const Geometry a = geometry(w);
        for (int i = 0; i < 100; ++i)
            w.simulation().stepOnce();
        const Geometry b = geometry(w);
        for (int i = 0; i < 5; ++i)
            w.simulation().stepOnce();
        QVERIFY2(largestMove(b, geometry(w)) < 0.05 * std::max(largestMove(a, b), 1e-9),
                 "in shape design the ink stops soon after the stroke");
        w.document().undoStack().undo();  // the stroke
        w.document().undoStack().undo();  // the mode
        QCOMPARE(w.document().settings().flow.viscosity, model::marblingPreset.viscosity);
        QVERIFY(test::child<QAction>(w, "modeMarbling")->isChecked());
    }

    // Holding a spin box's arrow key down is one undo step; another control starts a new one.
    void stepsOfOneSpinBoxAreOneUndoStep()
    {
        MainWindow& w = *m_window;
        const double viscosity = w.document().settings().flow.viscosity;
        auto* box = test::child<QDoubleSpinBox>(w, "viscosity");
        box->setFocus();
        for (int i = 0; i < 5; ++i)
            QTest::keyClick(box, Qt::Key_Up);
        QCOMPARE_GT(w.document().settings().flow.viscosity, viscosity);
        QCOMPARE(w.document().undoStack().count(), 1);
        auto* grid = test::child<QSpinBox>(w, "gridX");
        const int columns = grid->value();
        QTest::keyClick(grid, Qt::Key_Up);
        QCOMPARE(w.document().undoStack().count(), 2);
        QTest::keyClick(box, Qt::Key_Up);  // the viscosity again, after another command: a new step
        QCOMPARE(w.document().undoStack().count(), 3);
        w.document().undoStack().undo();
        w.document().undoStack().undo();
        QCOMPARE(w.document().settings().flow.gridX, columns);
        w.document().undoStack().undo();
        QCOMPARE(w.document().settings().flow.viscosity, viscosity);
        QCOMPARE(box->value(), viscosity);
    }

    // The mode's promise through the window: a stroke by mouse at half a canvas width per second
    // carries the ink under the pen at least half the stroke's length (the pointer's events, 40 ms
    // apart, reach the water over the steps they span, not all in one).
    void shapeDesignStrokeByMouseCarriesTheInk()
    {
        MainWindow& w = *m_window;
        model::Scene scene;
        model::applyPreset(scene.flow, model::FluidMode::ShapeDesign);
        scene.time.dt = 0.005;
        scene.regions.push_back({QStringLiteral("ink"), Qt::black, true, model::CircleShape{{0.35, 0.5}, 0.035}});
        const QString path = m_dir.filePath(QStringLiteral("shape.vfscene"));
        QCOMPARE(model::writeSceneFile(scene, path), QString());
        QVERIFY(w.openFile(path));
        w.simulation().setPlaying(false);
        const Geometry before = geometry(w);

        Canvas& canvas = w.canvas();
        QTest::keyClick(&w, Qt::Key_S);
        QTest::mousePress(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({0.35, 0.5}).toPoint());
        for (int i = 1; i <= 15; ++i) {
            QTest::qWait(40);  // the events' time stamps step by 40 ms; the worker runs meanwhile
            QTest::mouseMove(&canvas, canvas.mapFromCanvas({0.35 + 0.02 * i, 0.5}).toPoint(), 40);
        }
        QTest::qWait(40);
        QTest::mouseRelease(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({0.65, 0.5}).toPoint(), 40);
        // Paused, the water runs only while the pen is down, as fast as the machine allows; what the
        // pen did that it has not caught up with waits for steps. 160 steps of 5 ms cover the whole
        // stroke (0.64 s) however little ran meanwhile (a sanitizer build), and the water's coming
        // to rest.
        for (int i = 0; i < 160; ++i)
            QTest::keyClick(&w, Qt::Key_Period);
        const double carried = largestMove(before, geometry(w)) / 0.3;
        QVERIFY2(carried >= 0.5, qPrintable(QStringLiteral("the ink went %1 of the stroke").arg(carried)));
    }

    void autosaveRecoversAfterACrash()
    {
        MainWindow& w = *m_window;
        w.document().drop({0.6, 0.3}, 0.07, Qt::darkCyan);
        w.simulation().stepOnce();
        const Geometry lost = geometry(w);
        const model::RegionTable looks = w.document().regions();
        QSignalSpy saved(&w.recovery(), &Recovery::saved);
        w.recovery().saveNow();
        QVERIFY(saved.wait(10000));
        QCOMPARE(saved.front().front().toString(), QString());
        const QString recoveryFile = w.recovery().filePath();
        m_window.reset();  // a crash: no close, no clean exit, the file stays
        QVERIFY(QFile::exists(recoveryFile));

        MainWindow next;
        next.setAsk([this](const QString&, const QString& text, QMessageBox::StandardButtons) {
            m_questions << text;
            return QMessageBox::Discard;
        });
        QVERIFY(next.recovery().hasCrashedSession());
        QVERIFY(next.recover());
        next.simulation().setPlaying(false);
        QVERIFY(geometry(next) == lost);
        QVERIFY(next.document().regions() == looks);
        QCOMPARE(next.document().undoStack().count(), 1);
        // Recovered work is unsaved and has no file: a save must not go into the recovery file.
        QVERIFY(next.document().isModified());
        QVERIFY(next.document().filePath().isEmpty());
        QVERIFY(next.close());  // asks (discarded here), then a clean exit removes the recovery file
        QCOMPARE(m_questions.size(), 1);
        QVERIFY(!QFile::exists(recoveryFile));
    }

    void brokenFilesLeaveTheDocumentAlone()
    {
        MainWindow& w = *m_window;
        w.document().drop({0.6, 0.6}, 0.05, Qt::red);
        const Geometry before = geometry(w);
        const model::RegionTable looks = w.document().regions();

        const QString badJson = m_dir.filePath(QStringLiteral("bad.vfscene"));
        QFile f(badJson);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\"vectorfluid\": 1, \"canvas\": ");
        f.close();
        const QString badProject = m_dir.filePath(QStringLiteral("bad.vfproj"));
        QFile p(badProject);
        QVERIFY(p.open(QIODevice::WriteOnly));
        p.write("VFPROJ 9\n");
        p.close();
        const QString badSvg = m_dir.filePath(QStringLiteral("bad.svg"));
        QFile s(badSvg);
        QVERIFY(s.open(QIODevice::WriteOnly));
        s.write("<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"M 0 0 L 10\"/></svg>");
        s.close();

        QVERIFY(!w.openFile(badJson));
        QVERIFY(!w.openFile(badProject));
        QVERIFY(!w.importSvg(badSvg));
        QCOMPARE(m_reports.size(), 3);
        QVERIFY2(m_reports[0].contains(QStringLiteral("bad.vfscene")), qPrintable(m_reports[0]));
        QVERIFY2(m_reports[1].contains(QStringLiteral("bad.vfproj")), qPrintable(m_reports[1]));
        QVERIFY2(m_reports[2].contains(QStringLiteral("bad.svg")), qPrintable(m_reports[2]));
        for (const QString& line : m_reports)
            QVERIFY2(!line.contains('\n'), qPrintable(line));
        QVERIFY(geometry(w) == before);
        QVERIFY(w.document().regions() == looks);
        QCOMPARE(w.document().undoStack().count(), 1);
    }

    // A scene may start from an SVG file: its shapes are the regions, and a project saved from it
    // resets to them without the file. A broken SVG is refused with the reader's one line.
    void sceneStartingFromAnSvgFile()
    {
        const QDir folder(m_dir.filePath(QStringLiteral("svgscene")));
        QVERIFY(folder.mkpath(QStringLiteral(".")));
        auto write = [&folder](const QString& name, const QByteArray& content) {
            QFile f(folder.filePath(name));
            QVERIFY(f.open(QIODevice::WriteOnly) && f.write(content) == content.size());
        };
        write(QStringLiteral("logo.vfscene"), "{\"vectorfluid\": 1, \"tracking\": {\"max_spacing\": 0.01}, \"flow\": {\"grid\": [32, 32]},"
                                              " \"regions\": [{\"name\": \"logo\", \"shape\": {\"svg\": \"logo.svg\"}}]}");
        write(QStringLiteral("logo.svg"), "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 10 10'>"
                                          "<circle id='a' cx='3' cy='3' r='2' fill='#ff0000'/><circle id='b' cx='7' cy='7' r='2'/></svg>");
        MainWindow& w = *m_window;
        QVERIFY(w.openFile(folder.filePath(QStringLiteral("logo.vfscene"))));
        w.simulation().setPlaying(false);
        QCOMPARE(w.document().regions().size(), std::size_t(2));
        QCOMPARE(w.document().regions()[0].name, QStringLiteral("logo/a"));
        QCOMPARE(w.document().regions()[1].name, QStringLiteral("logo/b"));
        const Geometry start = geometry(w);
        QCOMPARE(start.size(), std::size_t(2));

        const QString project = m_dir.filePath(QStringLiteral("fromsvg.vfproj"));
        QVERIFY(w.saveTo(project));
        QVERIFY(QFile::remove(folder.filePath(QStringLiteral("logo.svg"))));
        MainWindow other;
        other.setReport([this](const QString&, const QString& text) { m_reports << text; });
        QVERIFY(other.openFile(project));
        other.simulation().setPlaying(false);
        other.simulation().stepOnce();
        other.document().reset();
        QVERIFY(geometry(other) == start);

        write(QStringLiteral("logo.svg"), "<svg xmlns='http://www.w3.org/2000/svg'><path d='M 0 0 L 10'/></svg>");
        const QString broken = folder.filePath(QStringLiteral("logo.vfscene"));
        QVERIFY(!w.openFile(broken));
        QCOMPARE(m_reports, QStringList{model::readSceneFile(broken).error});
        QVERIFY(m_reports[0].contains(QStringLiteral("regions[0].shape.svg: logo.svg: ")));
    }

    // T, a click, typing (letters that are shortcuts too) with the outlines shown as they are
    // typed, at the size set in the text options in canvas units; Enter sets it as one undo step,
    // Esc drops it.
    void textIsTypedOnTheCanvas()
    {
        MainWindow& w = *m_window;
        Canvas& canvas = w.canvas();
        QTest::keyClick(&w, Qt::Key_T);
        auto* options = test::child<QToolBar>(w, "textOptions");
        QVERIFY(options->isVisible());
        auto* size = test::child<QDoubleSpinBox>(w, "textSize");
        size->selectAll();
        QTest::keyClicks(size, QStringLiteral("0.2"));
        QTest::keyClick(size, Qt::Key_Return);
        QCOMPARE(size->value(), 0.2);

        QTest::mouseClick(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({0.1, 0.9}).toPoint());
        const QImage before = canvas.grab().toImage();
        QTest::keyClicks(&canvas, QStringLiteral("STVD"));
        QCOMPARE(canvas.tool(), Tool::Text);  // the letters were typed, not taken as tool keys
        QCOMPARE(canvas.textEntry().text(), QStringLiteral("STVD"));
        const QImage typed = canvas.grab().toImage();
        int changed = 0;
        for (int y = 0; y < typed.height(); ++y)
            for (int x = 0; x < typed.width(); ++x)
                changed += typed.pixel(x, y) != before.pixel(x, y);
        QVERIFY2(changed > 500, "the letters' outlines show while typed");
        QCOMPARE(w.document().undoStack().count(), 0);

        QTest::keyClick(&canvas, Qt::Key_Return);
        QCOMPARE(w.document().undoStack().count(), 1);
        QCOMPARE(w.document().regions().back().name, QStringLiteral("STVD"));
        const Geometry g = geometry(w);
        QCOMPARE(g.size(), std::size_t(3));
        double top = 1.0, bottom = 0.0;
        for (const sim::Polygon& contour : g[2])
            for (const sim::Vec2& p : contour) {
                top = std::min(top, p.y);
                bottom = std::max(bottom, p.y);
            }
        QVERIFY2(bottom - top > 0.1 && bottom - top < 0.2, "capitals about 0.7 of a 0.2 em tall");
        QVERIFY(std::abs(bottom - 0.9) < 0.01);  // standing on the baseline clicked

        QTest::mouseClick(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({0.5, 0.3}).toPoint());
        QTest::keyClicks(&canvas, QStringLiteral("gone"));
        QTest::keyClick(&canvas, Qt::Key_Escape);
        QCOMPARE(w.document().undoStack().count(), 1);
        QTest::keySequence(&w, QKeySequence::Undo);
        QCOMPARE(geometry(w).size(), std::size_t(2));
    }

    // The typeface starts upright, and the font dialog opens on it so.
    void textFontStartsUpright()
    {
        MainWindow& w = *m_window;
        QTest::keyClick(&w, Qt::Key_T);
        auto* font = test::child<QPushButton>(w, "textFont");
        QVERIFY2(!font->text().contains(QStringLiteral("Oblique")) && !font->text().contains(QStringLiteral("Italic")),
                 qPrintable(font->text()));
        QFont offered;
        test::whenModal<QFontDialog>([&offered](QFontDialog* dialog) {
            offered = dialog->currentFont();
            dialog->reject();
        });
        QTest::mouseClick(font, Qt::LeftButton);
        QVERIFY(!offered.family().isEmpty());
        QVERIFY2(offered.style() == QFont::StyleNormal, qPrintable(offered.toString()));
    }

    // Select the top region by clicking its row, press Delete: its ink goes, the other region's
    // stays exactly; undo brings it back exactly. The context menu's Delete does the same.
    void deleteKeyAndContextMenuDeleteRegionsUndoably()
    {
        MainWindow& w = *m_window;
        QListView& view = w.regionView();
        const Geometry before = geometry(w);
        QTest::mouseClick(view.viewport(), Qt::LeftButton, {}, view.visualRect(view.model()->index(0, 0)).center());
        QTest::keyClick(&view, Qt::Key_Delete);
        QCOMPARE(w.document().regions().size(), std::size_t(1));
        QCOMPARE(w.document().regions()[0].name, QStringLiteral("ink"));
        QCOMPARE(geometry(w), Geometry{before[0]});
        QCOMPARE(w.document().undoStack().undoText(), QStringLiteral("Delete slab"));
        QTest::keySequence(&w, QKeySequence::Undo);
        QCOMPARE(w.document().regions().size(), std::size_t(2));
        QCOMPARE(geometry(w), before);

        // Right-click the bottom row ("ink") and choose Delete Region in the menu.
        const QPoint inkRow = view.visualRect(view.model()->index(1, 0)).center();
        QContextMenuEvent rightClick(QContextMenuEvent::Mouse, inkRow, view.viewport()->mapToGlobal(inkRow));
        QApplication::sendEvent(view.viewport(), &rightClick);
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        QVERIFY(menu);
        QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(test::child<QAction>(w, "deleteRegion")).center());
        QCOMPARE(w.document().regions().size(), std::size_t(1));
        QCOMPARE(w.document().regions()[0].name, QStringLiteral("slab"));
        QCOMPARE(w.document().regions()[0].simIndex, 0);
        QCOMPARE(geometry(w), Geometry{before[1]});
        // The offscreen platform leaves the closed menu the active window; a user's next click in
        // the window would make it active again.
        QApplication::setActiveWindow(&w);
        QTest::keySequence(&w, QKeySequence::Undo);
        QCOMPARE(geometry(w), before);
        QTest::keySequence(&w, QKeySequence(Qt::CTRL | Qt::Key_Y));
        QCOMPARE(geometry(w), Geometry{before[1]});
    }

    // Ctrl+D copies the selected region's ink, a little right of and below it, just above it in
    // the paint order; undo takes the copy away.
    void duplicateCopiesTheInkJustAboveTheOriginal()
    {
        MainWindow& w = *m_window;
        QListView& view = w.regionView();
        const Geometry before = geometry(w);
        QTest::mouseClick(view.viewport(), Qt::LeftButton, {}, view.visualRect(view.model()->index(1, 0)).center());
        QTest::keySequence(&w, QKeySequence(Qt::CTRL | Qt::Key_D));
        const Geometry after = geometry(w);
        QCOMPARE(after.size(), std::size_t(3));
        const model::RegionTable& regions = w.document().regions();
        QCOMPARE(regions.size(), std::size_t(3));
        QCOMPARE(regions[1].name, QStringLiteral("ink copy"));
        QCOMPARE(regions[1].color, regions[0].color);
        QCOMPARE(regions[1].simIndex, 2);
        QCOMPARE(view.currentIndex().data().toString(), QStringLiteral("ink copy"));  // the copy is selected
        QCOMPARE(w.canvas().selectedRegion(), 2);
        QVERIFY(std::abs(largestMove({before[0]}, {after[2]}) - 0.02 * std::sqrt(2.0)) < 1e-3);
        QCOMPARE(w.document().undoStack().undoText(), QStringLiteral("Duplicate ink"));
        QTest::keySequence(&w, QKeySequence::Undo);
        QCOMPARE(geometry(w), before);
    }

    // V picks the Select tool; clicking ink selects its region in the dock and outlines it on the
    // canvas; clicking bare water selects nothing.
    void selectToolClickSelectsAndOutlinesTheRegion()
    {
        MainWindow& w = *m_window;
        Canvas& canvas = w.canvas();
        geometry(w);
        canvas.setFocus();
        QTest::keyClick(&w, Qt::Key_V);
        QCOMPARE(canvas.tool(), Tool::Select);
        const QPoint edge = canvas.mapFromCanvas({0.7, 0.5}).toPoint();  // on the ink disc's rim
        const QImage unselected = canvas.grab().toImage();
        QTest::mouseClick(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({0.5, 0.5}).toPoint());
        QCOMPARE(w.regionView().currentIndex().data().toString(), QStringLiteral("ink"));
        QCOMPARE(canvas.selectedRegion(), 0);
        const QImage selected = canvas.grab().toImage();
        bool outlined = false;
        for (int dx = -2; dx <= 2; ++dx)
            outlined |= selected.pixel(edge + QPoint(dx, 0)) != unselected.pixel(edge + QPoint(dx, 0));
        QVERIFY2(outlined, "nothing drawn on the selected region's edge");
        QTest::mouseClick(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({0.9, 0.9}).toPoint());
        QVERIFY(!w.regionView().currentIndex().isValid());
        QCOMPARE(canvas.selectedRegion(), -1);
    }

    void regionsDockShowsEightRows()
    {
        MainWindow& w = *m_window;
        for (int i = 0; i < 8; ++i)
            w.document().drop({0.1 + 0.1 * i, 0.9}, 0.02, Qt::red);
        QListView& view = w.regionView();
        QTRY_VERIFY(view.model()->rowCount() == 10);
        QVERIFY2(view.viewport()->height() >= 8 * view.sizeHintForRow(0),
                 qPrintable(QStringLiteral("%1 px for rows of %2").arg(view.viewport()->height()).arg(view.sizeHintForRow(0))));
    }

    void closingWithChangesAsks()
    {
        MainWindow& w = *m_window;
        w.document().drop({0.6, 0.6}, 0.05, Qt::red);
        m_answer = QMessageBox::Cancel;
        QVERIFY(!w.close());
        QCOMPARE(m_questions.size(), 1);
        m_answer = QMessageBox::Discard;
        QVERIFY(w.close());
    }

private:
    QTemporaryDir m_dir;
    QString m_scenePath;
    std::unique_ptr<MainWindow> m_window;
    QStringList m_reports;
    QStringList m_questions;
    QMessageBox::StandardButton m_answer = QMessageBox::Discard;
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
