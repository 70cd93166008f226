// The marbling tools in the main window, by keys. Tools ▸ Pattern…: the dialog says how many drops
// the pattern makes on this canvas, OK makes it as one step of the history in the inks of the
// palette shown, and the undo and redo keys take it back and bring it again; a pattern the canvas
// cannot hold is refused in the dialog. A scene's own exact tools act in the app as they do in
// `vectorfluid render`.
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
        // Three tines 0.08 apart: the middle one's path runs down from the press.
        const QPoint onPath = w.canvas().mapFromCanvas({0.5, 0.27}).toPoint();
        const QPoint between = w.canvas().mapFromCanvas({0.54, 0.27}).toPoint();
        QVERIFY(dragging.pixel(onPath) != still.pixel(onPath));
        QCOMPARE(dragging.pixel(between), still.pixel(between));
        QCOMPARE(w.document().undoStack().count(), 0);  // nothing until the release
        QTest::mouseRelease(&w.canvas(), Qt::LeftButton, {}, to);

        QCOMPARE(w.document().undoStack().count(), 1);
        QCOMPARE(w.document().undoStack().text(0), QStringLiteral("Comb"));
        const Geometry combed = geometry(w);
        // The comb from and to where the pointer was, whole pixels mapped back onto the canvas.
        const QPointF a = w.canvas().mapToCanvas(QPointF(from)), b = w.canvas().mapToCanvas(QPointF(to));
        const sim::Comb comb{{a.x(), a.y()}, {b.x(), b.y()}, 3, 0.08, 0.02};
        std::vector<sim::Vec2> expected;
        for (const sim::Vec2& p : before[0][0])
            expected.push_back(comb(p));
        // Every vertex the circle had, moved by the exact comb, lies on the combed contour.
        const double off = sim::directedHausdorffDistance(expected, combed[0][0]);
        QVERIFY2(off < 1e-6, qPrintable(QString::number(off)));
        QVERIFY(sim::hausdorffDistance(combed[0][0], before[0][0]) > 0.05);
        QVERIFY(w.canvas().grab().toImage() != still);
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
