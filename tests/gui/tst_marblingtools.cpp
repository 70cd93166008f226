// The marbling tools in the main window, by keys and mouse drags. Tools ▸ Pattern…: the dialog says
// how many drops the pattern makes on this canvas, OK makes it as one step of the history in the
// inks of the palette shown, and the undo and redo keys take it back and bring it again; a pattern
// the canvas cannot hold is refused in the dialog. The Comb (straight or wavy), Circular comb and
// Swirl tools preview their drag and apply their exact map on release, or push the water while
// dragged; each drag is one step of the history, kept in a saved project. A scene's own exact
// tools act in the app as they do in `vectorfluid render`.
#include "FindChild.h"
#include "WindowTest.h"
#include "app/Canvas.h"
#include "app/MainWindow.h"
#include "app/PatternDialog.h"
#include "app/SimulationController.h"
#include "model/Palette.h"
#include "model/SceneFile.h"
#include "model/SceneRunner.h"
#include "sim/Comb.h"
#include "sim/ExactMap.h"
#include "sim/Geometry.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QToolBar>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

using namespace vf;
using namespace vf::app;

namespace {

model::Scene stillScene()
{
    model::Scene scene;
    scene.flow.type = model::FlowSpec::Type::Analytic;
    scene.flow.u = scene.flow.v = QStringLiteral("0");
    scene.tracking.maxSpacing = 0.01;
    scene.regions.push_back({QStringLiteral("ink"), QColor(0x1d, 0x35, 0x57), true, model::CircleShape{{0.5, 0.5}, 0.2}});
    return scene;
}

// Types `text` into the spin box as a user does: select what is there, type over it.
void typeInto(QDoubleSpinBox* box, const QString& text)
{
    box->setFocus();
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, text);
}

using Geometry = std::vector<std::vector<sim::Polygon>>;

Geometry geometry(MainWindow& w)
{
    w.simulation().sync();
    return w.simulation().frame()->regions;
}

// The still scene's ink in water that flows: what the tools in the water can push.
model::Scene waterScene()
{
    model::Scene scene = stillScene();
    scene.flow = model::FlowSpec{};
    scene.time.dt = 0.01;  // a pointer move of 20 ms pushes over two steps
    return scene;
}

// Whether the pixels about `at` (a dashed line's gap is shorter than the square) differ at all.
bool changedNear(const QImage& before, const QImage& after, QPoint at, int reach = 3)
{
    for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx)
            if (before.pixel(at + QPoint(dx, dy)) != after.pixel(at + QPoint(dx, dy)))
                return true;
    return false;
}

// A drag of `moves` moves, 20 ms apart: from `centre` out to `radius` along +x, then round it by
// `degrees` (from +x towards +y, as canvas coordinates go) in equal steps. The pointer's positions
// after the press, in widget pixels.
QList<QPoint> dragRound(Canvas& canvas, sim::Vec2 centre, double radius, double degrees, int moves)
{
    QList<QPoint> path;
    for (int i = 0; i <= moves; ++i) {
        const double a = degrees * std::numbers::pi / 180.0 * i / moves;
        path << canvas.mapFromCanvas(QPointF(centre.x + radius * std::cos(a), centre.y + radius * std::sin(a))).toPoint();
    }
    QTest::mousePress(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({centre.x, centre.y}).toPoint());
    for (const QPoint& p : path)
        QTest::mouseMove(&canvas, p, 20);
    return path;
}

// The angle (radians) the pointer's path sweeps about `centre`, in canvas units as the canvas
// counts it: the pixels the pointer really went through.
double sweptAbout(const Canvas& canvas, QPointF centre, const QList<QPoint>& path)
{
    double swept = 0.0;
    for (int i = 1; i < path.size(); ++i) {
        const QPointF a = canvas.mapToCanvas(QPointF(path[i - 1])) - centre, b = canvas.mapToCanvas(QPointF(path[i])) - centre;
        swept += std::remainder(std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x()), 2.0 * std::numbers::pi);
    }
    return swept;
}

// The largest distance of `before`'s vertices, moved by `map`, from the contour `after`.
double offMap(const sim::ExactMap& map, const sim::Polygon& before, const sim::Polygon& after)
{
    std::vector<sim::Vec2> expected;
    for (const sim::Vec2& p : before)
        expected.push_back(sim::mapped(map, p));
    return sim::directedHausdorffDistance(expected, after);
}

std::size_t simulatedRegions(MainWindow& w)
{
    w.simulation().sync();
    return w.simulation().frame()->regions.size();
}

} // namespace

class TestMarblingTools : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        test::useTestSettings("tst_marblingtools", m_dir);
        m_scenePath = m_dir.filePath(QStringLiteral("still.vfscene"));
        QCOMPARE(model::writeSceneFile(stillScene(), m_scenePath), QString());
    }

    void init()
    {
        QTest::failOnWarning(QRegularExpression(QStringLiteral("Ambiguous shortcut")));
        m_window = std::make_unique<MainWindow>();
        m_window->setReport([this](const QString&, const QString& text) { m_reports << text; });
        QVERIFY(test::showActive(*m_window));
        QVERIFY(m_window->openFile(m_scenePath));
        m_window->simulation().setPlaying(false);
        m_reports.clear();
    }

    void cleanup()
    {
        m_window->document().undoStack().setClean();  // no prompt on close
        m_window.reset();
    }

    void patternIsOneStepInThePalettesInks()
    {
        MainWindow& w = *m_window;
        QString summary;
        test::whenModal<PatternDialog>([&summary](PatternDialog* dialog) {
            auto* kind = test::child<QComboBox>(*dialog, "patternKind");
            kind->setFocus();
            QTest::keyClick(kind, Qt::Key_Down);
            QTest::keyClick(kind, Qt::Key_Down);
            typeInto(test::child<QDoubleSpinBox>(*dialog, "patternDropRadius"), QStringLiteral("0.3"));
            summary = test::child<QLabel>(*dialog, "patternSummary")->text();
            QTest::keyClick(dialog, Qt::Key_Return);
        });
        QTest::keyClick(&w, Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);

        const int drops = int(std::ceil(1.0 / (std::numbers::pi * 0.3 * 0.3)));
        QCOMPARE(summary, QStringLiteral("Drops: %1, in %2 inks; then comb passes: 3. One step of the history.")
                              .arg(drops)
                              .arg(model::builtInPalettes()[0].colours.size()));
        QUndoStack& history = w.document().undoStack();
        QCOMPARE(history.count(), 1);
        QCOMPARE(history.text(0), QStringLiteral("Pattern: chevron"));
        QCOMPARE(int(w.document().regions().size()), 1 + drops);
        QCOMPARE(simulatedRegions(w), std::size_t(1 + drops));
        const model::Palette& inks = model::builtInPalettes()[0];
        for (std::size_t r = 1; r < w.document().regions().size(); ++r) {
            const QColor c = w.document().regions()[r].color;
            QVERIFY(std::any_of(inks.colours.begin(), inks.colours.end(),
                                [&c](const model::PaletteColour& ink) { return ink.colour == c; }));
        }

        w.activateWindow();  // as a window manager does when the dialog closes (offscreen has none)
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(int(w.document().regions().size()), 1);
        QCOMPARE(simulatedRegions(w), std::size_t(1));
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(int(w.document().regions().size()), 1 + drops);
        QCOMPARE(simulatedRegions(w), std::size_t(1 + drops));
    }

    void patternTheCanvasCannotHoldIsRefusedInTheDialog()
    {
        MainWindow& w = *m_window;
        QString summary;
        bool okEnabled = true;
        test::whenModal<PatternDialog>([&](PatternDialog* dialog) {
            typeInto(test::child<QDoubleSpinBox>(*dialog, "patternDropRadius"), QStringLiteral("0.005"));
            summary = test::child<QLabel>(*dialog, "patternSummary")->text();
            okEnabled = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->isEnabled();
            QTest::keyClick(dialog, Qt::Key_Return);  // does nothing: OK is disabled
            QTest::keyClick(dialog, Qt::Key_Escape);
        });
        QTest::keyClick(&w, Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(!okEnabled);
        QVERIFY2(summary.contains(QStringLiteral("more than 10000")), qPrintable(summary));
        QCOMPARE(w.document().undoStack().count(), 0);
        QCOMPARE(int(w.document().regions().size()), 1);
    }

    // B picks the Spatter tool; a click spatters twenty drops about it in the palette's inks, one
    // step of the history; a drag sets how far they spread.
    void spatterClickIsOneStep()
    {
        MainWindow& w = *m_window;
        QTest::keyClick(&w, Qt::Key_B);
        QCOMPARE(w.canvas().tool(), Tool::Spatter);
        QTest::mouseClick(&w.canvas(), Qt::LeftButton, {}, w.canvas().mapFromCanvas({0.5, 0.5}).toPoint());
        QCOMPARE(w.document().undoStack().count(), 1);
        QCOMPARE(w.document().undoStack().text(0), QStringLiteral("Spatter"));
        QCOMPARE(int(w.document().regions().size()), 21);
        QCOMPARE(simulatedRegions(w), std::size_t(21));

        const QPoint from = w.canvas().mapFromCanvas({0.3, 0.3}).toPoint();
        const QPoint to = w.canvas().mapFromCanvas({0.3, 0.32}).toPoint();
        QTest::mousePress(&w.canvas(), Qt::LeftButton, {}, from);
        QTest::mouseMove(&w.canvas(), to);
        QTest::mouseRelease(&w.canvas(), Qt::LeftButton, {}, to);
        QCOMPARE(w.document().undoStack().count(), 2);
        // Spread 0.02, radii up to 0.02: the twenty drops' ink (about 0.01 of area) packs into a
        // disc of radius about 0.06 about the press; a click's spread of 0.15 would reach past 0.1.
        const auto regions = (w.simulation().sync(), w.simulation().frame()->regions);
        for (std::size_t r = 21; r < regions.size(); ++r)
            for (const sim::Vec2& p : regions[r][0])
                QVERIFY2(glm::distance(p, sim::Vec2(0.3, 0.3)) < 0.1, qPrintable(QString::number(glm::distance(p, sim::Vec2(0.3, 0.3)))));
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(int(w.document().regions().size()), 21);
    }

    // C picks the Comb tool and shows its options; a drag shows each tine's path while it lasts,
    // and its release combs the ink exactly, one step of the history, which Ctrl+Z takes back.
    void combDragPreviewsAndCombs()
    {
        MainWindow& w = *m_window;
        QTest::keyClick(&w, Qt::Key_C);
        QCOMPARE(w.canvas().tool(), Tool::Comb);
        QVERIFY(test::child<QToolBar>(w, "combOptions")->isVisible());
        auto* tines = test::child<QSpinBox>(w, "combTines");
        tines->setFocus();
        tines->selectAll();
        QTest::keyClicks(tines, QStringLiteral("3"));
        const Geometry before = geometry(w);

        const QPoint from = w.canvas().mapFromCanvas({0.5, 0.2}).toPoint();
        const QPoint to = w.canvas().mapFromCanvas({0.5, 0.35}).toPoint();
        const QImage still = w.canvas().grab().toImage();
        QTest::mousePress(&w.canvas(), Qt::LeftButton, {}, from);
        QTest::mouseMove(&w.canvas(), to);
        const QImage dragging = w.canvas().grab().toImage();
        // Three tines 0.08 apart: the middle one's path runs down from the press, dashed, so some
        // pixel of its column (a pixel either side for the antialiasing) changes.
        const QPoint between = w.canvas().mapFromCanvas({0.54, 0.27}).toPoint();
        bool pathShown = false;
        for (int y = from.y(); y <= to.y(); ++y)
            for (int x = from.x() - 1; x <= from.x() + 1; ++x)
                pathShown = pathShown || dragging.pixel(x, y) != still.pixel(x, y);
        QVERIFY(pathShown);
        QCOMPARE(dragging.pixel(between), still.pixel(between));
        QCOMPARE(w.document().undoStack().count(), 0);  // nothing until the release
        QTest::mouseRelease(&w.canvas(), Qt::LeftButton, {}, to);

        QCOMPARE(w.document().undoStack().count(), 1);
        QCOMPARE(w.document().undoStack().text(0), QStringLiteral("Comb"));
        const Geometry combed = geometry(w);
        // The comb along the drag from where the pointer was pressed to where it was released (whole
        // pixels mapped back onto the canvas), shortened about its middle so that the ink at the
        // middle tine moves the drag's length: the map moves it by its own pull (1) and by the two
        // tines 0.08 beside it (0.02 / (0.08 + 0.02) each), 1.4 stroke lengths in all.
        const QPointF a = w.canvas().mapToCanvas(QPointF(from)), b = w.canvas().mapToCanvas(QPointF(to));
        const sim::Vec2 middle(0.5 * (a.x() + b.x()), 0.5 * (a.y() + b.y())), drag(b.x() - a.x(), b.y() - a.y());
        const sim::Comb comb{middle - drag / 2.8, middle + drag / 2.8, 3, 0.08, 0.02};
        std::vector<sim::Vec2> expected;
        for (const sim::Vec2& p : before[0][0])
            expected.push_back(comb(p));
        // Every vertex the circle had, moved by the exact comb, lies on the combed contour.
        const double off = sim::directedHausdorffDistance(expected, combed[0][0]);
        QVERIFY2(off < 1e-6, qPrintable(QString::number(off)));
        // Ink on the middle tine's path moves as far as the pointer did.
        const sim::Vec2 onTine = comb.tineStart(1) + 0.3 * drag;
        QVERIFY(std::abs(glm::distance(comb(onTine), onTine) - glm::length(drag)) < 1e-9);
        QVERIFY(sim::hausdorffDistance(combed[0][0], before[0][0]) > 0.05);
        QVERIFY(w.canvas().grab().toImage() != still);
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(sim::hausdorffDistance(geometry(w)[0][0], before[0][0]) < 1e-12);
    }

    // A wavy comb: the Comb bar's wave shows in the tines' paths while dragged, and the release
    // combs the ink by the wavy map.
    void wavyCombPreviewsItsWaves()
    {
        MainWindow& w = *m_window;
        QTest::keyClick(&w, Qt::Key_C);
        auto* tines = test::child<QSpinBox>(w, "combTines");
        tines->setFocus();
        tines->selectAll();
        QTest::keyClicks(tines, QStringLiteral("1"));
        typeInto(test::child<QDoubleSpinBox>(w, "combAmplitude"), QStringLiteral("0.05"));
        const Geometry before = geometry(w);
        const QImage still = w.canvas().grab().toImage();
        const QPoint from = w.canvas().mapFromCanvas({0.5, 0.2}).toPoint(), to = w.canvas().mapFromCanvas({0.5, 0.6}).toPoint();
        QTest::mousePress(&w.canvas(), Qt::LeftButton, {}, from);
        QTest::mouseMove(&w.canvas(), to);
        const QImage dragging = w.canvas().grab().toImage();
        // The wave (wavelength 0.2, its phase 0 at the middle, y = 0.4) is 0.05 to one side a
        // quarter wave below the middle and to the other a quarter above; the straight line is bare.
        const auto near = [&](double x, double y) { return changedNear(still, dragging, w.canvas().mapFromCanvas({x, y}).toPoint()); };
        QVERIFY((near(0.45, 0.45) && near(0.55, 0.35)) || (near(0.55, 0.45) && near(0.45, 0.35)));
        QVERIFY(!near(0.5, 0.45) && !near(0.5, 0.35));
        QTest::mouseRelease(&w.canvas(), Qt::LeftButton, {}, to);

        QCOMPARE(w.document().undoStack().count(), 1);
        const QPointF a = w.canvas().mapToCanvas(QPointF(from)), b = w.canvas().mapToCanvas(QPointF(to));
        const sim::Comb wavy{{a.x(), a.y()}, {b.x(), b.y()}, 1, 0.08, 0.02, 0.05, 0.2, 0.0};
        const Geometry combed = geometry(w);
        const double off = offMap(wavy, before[0][0], combed[0][0]);
        QVERIFY2(off < 1e-6, qPrintable(QString::number(off)));
        sim::Comb straight = wavy;
        straight.amplitude = 0.0;
        QVERIFY(offMap(straight, before[0][0], combed[0][0]) > 1e-3);  // the wave made a difference
    }

    // O picks the Circular comb and shows its options. Pressed at the centre and dragged out and
    // a quarter way round, it shows the tines' circles and the arcs they sweep; the release turns the
    // ink about the centre the way the pointer went, one step of the history, which the undo and
    // redo keys take back and bring again.
    void circularCombTurnsTheInkAboutThePress()
    {
        MainWindow& w = *m_window;
        Canvas& canvas = w.canvas();
        QTest::keyClick(&w, Qt::Key_O);
        QCOMPARE(canvas.tool(), Tool::CircularComb);
        QVERIFY(test::child<QAction>(w, "toolCircularComb")->isChecked());
        QVERIFY(test::child<QToolBar>(w, "circularCombOptions")->isVisible());
        QVERIFY(!test::child<QToolBar>(w, "combOptions")->isVisible());
        auto* tines = test::child<QSpinBox>(w, "circularCombTines");
        tines->setFocus();
        tines->selectAll();
        QTest::keyClicks(tines, QStringLiteral("2"));
        typeInto(test::child<QDoubleSpinBox>(w, "circularCombSpacing"), QStringLiteral("0.08"));
        typeInto(test::child<QDoubleSpinBox>(w, "circularCombInnerRadius"), QStringLiteral("0.1"));
        const Geometry before = geometry(w);
        const QImage still = canvas.grab().toImage();

        const sim::Vec2 centre(0.35, 0.5);  // the ink's circle reaches from 0.05 to 0.35 of it
        const QList<QPoint> path = dragRound(canvas, centre, 0.22, 90.0, 6);
        const QImage dragging = canvas.grab().toImage();
        QCOMPARE(w.document().undoStack().count(), 0);  // nothing until the release
        // The outer tine (radius 0.18): its arc swept from +x towards +y, its circle's dashes
        // elsewhere; between the tines' circles nothing.
        QVERIFY(changedNear(still, dragging, canvas.mapFromCanvas({centre.x + 0.18 / std::sqrt(2.0), centre.y + 0.18 / std::sqrt(2.0)}).toPoint()));
        QVERIFY(changedNear(still, dragging, canvas.mapFromCanvas({centre.x, centre.y - 0.18}).toPoint()));
        QVERIFY(!changedNear(still, dragging, canvas.mapFromCanvas({centre.x + 0.14 / std::sqrt(2.0), centre.y - 0.14 / std::sqrt(2.0)}).toPoint()));
        QTest::mouseRelease(&canvas, Qt::LeftButton, {}, path.last());

        QCOMPARE(w.document().undoStack().count(), 1);
        QCOMPARE(w.document().undoStack().text(0), QStringLiteral("Circular comb"));
        const QPointF pressed = canvas.mapToCanvas(QPointF(canvas.mapFromCanvas({centre.x, centre.y}).toPoint()));
        const double swept = sweptAbout(canvas, pressed, path);
        QVERIFY(std::abs(swept - std::numbers::pi / 2.0) < 0.05);
        const sim::CircularComb comb{{pressed.x(), pressed.y()}, 0.1, 2, 0.08, 0.02, swept};
        const Geometry combed = geometry(w);
        const double off = offMap(comb, before[0][0], combed[0][0]);
        QVERIFY2(off < 1e-6, qPrintable(QString::number(off)));
        QVERIFY(offMap(comb.inverse(), before[0][0], combed[0][0]) > 0.01);  // not the other way round
        QVERIFY(sim::hausdorffDistance(combed[0][0], before[0][0]) > 0.05);

        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(sim::hausdorffDistance(geometry(w)[0][0], before[0][0]) < 1e-12);
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(sim::hausdorffDistance(geometry(w)[0][0], combed[0][0]) < 1e-12);

        // Saved and opened again, the project has the combed ink and the step to undo.
        const QString project = m_dir.filePath(QStringLiteral("combed.vfproj"));
        QVERIFY(w.saveTo(project));
        QVERIFY(w.openFile(project));
        QVERIFY(sim::hausdorffDistance(geometry(w)[0][0], combed[0][0]) < 1e-12);
        QCOMPARE(w.document().undoStack().count(), 1);
        QCOMPARE(w.document().undoStack().text(0), QStringLiteral("Circular comb"));
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(sim::hausdorffDistance(geometry(w)[0][0], before[0][0]) < 1e-12);
    }

    // W picks the Swirl. Pressed at the centre and dragged out and a quarter way round the other
    // way: the circle as far out as the pointer and an arrow along the arc; the release swirls
    // the ink by the vortex of that radius and angle, one step of the history.
    void swirlTurnsAsFarAsThePointerWent()
    {
        MainWindow& w = *m_window;
        Canvas& canvas = w.canvas();
        QTest::keyClick(&w, Qt::Key_W);
        QCOMPARE(canvas.tool(), Tool::Swirl);
        QVERIFY(test::child<QToolBar>(w, "swirlOptions")->isVisible());
        const Geometry before = geometry(w);
        const QImage still = canvas.grab().toImage();

        const sim::Vec2 centre(0.5, 0.3);  // on the ink's edge
        const QList<QPoint> path = dragRound(canvas, centre, 0.15, -90.0, 8);
        const QImage dragging = canvas.grab().toImage();
        QVERIFY(changedNear(still, dragging, canvas.mapFromCanvas({centre.x + 0.15 / std::sqrt(2.0), centre.y - 0.15 / std::sqrt(2.0)}).toPoint()));
        QVERIFY(changedNear(still, dragging, canvas.mapFromCanvas({centre.x - 0.15, centre.y}).toPoint()));
        QVERIFY(!changedNear(still, dragging, canvas.mapFromCanvas({centre.x - 0.07, centre.y}).toPoint()));
        QTest::mouseRelease(&canvas, Qt::LeftButton, {}, path.last());

        QCOMPARE(w.document().undoStack().count(), 1);
        QCOMPARE(w.document().undoStack().text(0), QStringLiteral("Swirl"));
        const QPointF pressed = canvas.mapToCanvas(QPointF(canvas.mapFromCanvas({centre.x, centre.y}).toPoint()));
        const QPointF released = canvas.mapToCanvas(QPointF(path.last()));
        const double radius = std::hypot(released.x() - pressed.x(), released.y() - pressed.y());
        const double swept = sweptAbout(canvas, pressed, path);
        QVERIFY(std::abs(swept + std::numbers::pi / 2.0) < 0.05);
        const sim::Swirl swirl{{pressed.x(), pressed.y()}, radius, swept};
        const Geometry swirled = geometry(w);
        const double off = offMap(swirl, before[0][0], swirled[0][0]);
        QVERIFY2(off < 1e-6, qPrintable(QString::number(off)));
        QVERIFY(sim::hausdorffDistance(swirled[0][0], before[0][0]) > 0.02);
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(sim::hausdorffDistance(geometry(w)[0][0], before[0][0]) < 1e-12);
    }

    // In the water (the bar's mode), each tool pushes the water while dragged, all its pens one
    // step of the history named for it; undone, the ink is back where it was.
    void toolsInTheWaterPushTheInk_data()
    {
        QTest::addColumn<int>("key");
        QTest::addColumn<QString>("mode");
        QTest::addColumn<QString>("step");
        QTest::newRow("comb") << int(Qt::Key_C) << "combMode" << "Comb (in the water)";
        QTest::newRow("circular comb") << int(Qt::Key_O) << "circularCombMode" << "Circular comb (in the water)";
        QTest::newRow("swirl") << int(Qt::Key_W) << "swirlMode" << "Swirl (in the water)";
    }

    void toolsInTheWaterPushTheInk()
    {
        QFETCH(int, key);
        QFETCH(QString, mode);
        QFETCH(QString, step);
        const QString path = m_dir.filePath(QStringLiteral("water.vfscene"));
        QCOMPARE(model::writeSceneFile(waterScene(), path), QString());
        MainWindow& w = *m_window;
        QVERIFY(w.openFile(path));
        w.simulation().setPlaying(false);
        QTest::keyClick(&w, Qt::Key(key));
        auto* modes = test::child<QComboBox>(w, mode.toLatin1().constData());
        modes->setFocus();
        QTest::keyClick(modes, Qt::Key_Down);
        QCOMPARE(modes->currentText(), QStringLiteral("In the water"));
        const Geometry before = geometry(w);

        const QList<QPoint> moves = dragRound(w.canvas(), {0.35, 0.5}, 0.2, 180.0, 10);
        QTest::mouseRelease(&w.canvas(), Qt::LeftButton, {}, moves.last(), 20);
        QCOMPARE(w.document().undoStack().count(), 1);
        QCOMPARE(w.document().undoStack().text(0), step);
        for (int i = 0; i < 30; ++i)  // the pens' moves not yet fed, and the water they set going
            w.simulation().stepOnce();
        const double moved = sim::hausdorffDistance(geometry(w)[0][0], before[0][0]);
        QVERIFY2(moved > 0.01, qPrintable(QString::number(moved)));
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(sim::hausdorffDistance(geometry(w)[0][0], before[0][0]) < 1e-12);
    }

    void scenesOwnCombActsAsInRender()
    {
        model::Scene scene = stillScene();
        scene.time.dt = 0.01;
        scene.strokes.push_back(model::CombStroke{model::CombStroke::Mode::Exact, 0.05, {0.5, 0.2}, {0.5, 0.35}, 3, 0.1});
        const QString path = m_dir.filePath(QStringLiteral("combed.vfscene"));
        QCOMPARE(model::writeSceneFile(scene, path), QString());
        MainWindow& w = *m_window;
        QVERIFY(w.openFile(path));
        w.simulation().setPlaying(false);
        for (int k = 0; k < 8; ++k)
            QTest::keyClick(&w, Qt::Key_Period);  // Simulation ▸ Single Step
        w.simulation().sync();
        const auto shown = w.simulation().frame()->regions;

        model::SceneRunner rendered(scene);
        for (int k = 0; k < 8; ++k)
            rendered.step(scene.time.dt);
        const auto expected = rendered.simulation().regions();
        QCOMPARE(shown.size(), expected.size());
        QVERIFY(sim::hausdorffDistance(shown[0][0], expected[0][0]) < 1e-9);
        // And the comb did act: the circle's top was pulled down the tray.
        QVERIFY(sim::hausdorffDistance(shown[0][0], model::SceneRunner(stillScene()).simulation().regions()[0][0]) > 0.05);
    }

private:
    QTemporaryDir m_dir;
    QString m_scenePath;
    std::unique_ptr<MainWindow> m_window;
    QStringList m_reports;
};

QTEST_MAIN(TestMarblingTools)
#include "tst_marblingtools.moc"
