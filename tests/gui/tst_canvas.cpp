// Canvas: the view maps canvas units to the widget and back under zoom and pan, fits the canvas
// into the window, zooms about the cursor; each tool turns real mouse events into its signals in
// canvas units; the regions are drawn as the region table says (order, visibility, even-odd).
#include "app/Canvas.h"

#include <QNativeGestureEvent>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>

#include <cmath>
#include <memory>

using namespace vf;
using namespace vf::app;

namespace {

constexpr double kTolerance = 1e-9;

sim::Polygon rectangle(double x0, double y0, double x1, double y1)
{
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A 2 × 1 canvas: region 0 a square ring (outer square with a square hole), region 1 a bar
// crossing the ring's left side.
std::shared_ptr<const model::Frame> twoRegionFrame()
{
    auto frame = std::make_shared<model::Frame>();
    frame->width = 2.0;
    frame->height = 1.0;
    frame->regions = {{rectangle(0.2, 0.2, 0.8, 0.8), rectangle(0.4, 0.4, 0.6, 0.6)},
                      {rectangle(0.1, 0.45, 1.5, 0.55)}};
    return frame;
}

model::RegionTable lookFor(bool bottomVisible, bool topVisible, bool swapped = false)
{
    model::RegionTable table{{QStringLiteral("ring"), QColor(Qt::red), bottomVisible, 0},
                             {QStringLiteral("bar"), QColor(Qt::blue), topVisible, 1}};
    if (swapped)
        std::swap(table[0], table[1]);
    return table;
}

bool near(QPointF a, QPointF b, double tolerance = kTolerance)
{
    return std::abs(a.x() - b.x()) <= tolerance && std::abs(a.y() - b.y()) <= tolerance;
}

void wheel(QWidget* widget, QPointF at, int angle)
{
    QWheelEvent event(at, widget->mapToGlobal(at), QPoint(), QPoint(0, angle), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &event);
}

void drag(QWidget* widget, Qt::MouseButton button, QPoint from, QPoint to)
{
    QTest::mousePress(widget, button, {}, from);
    QTest::mouseMove(widget, (from + to) / 2);
    QTest::mouseMove(widget, to);
    QTest::mouseRelease(widget, button, {}, to);
}

} // namespace

class TestCanvas : public QObject {
    Q_OBJECT

    std::unique_ptr<Canvas> m_canvas;

private slots:
    void init()
    {
        m_canvas = std::make_unique<Canvas>();
        m_canvas->resize(400, 300);
        m_canvas->setFrame(twoRegionFrame());
        m_canvas->setRegions(lookFor(true, true));
        m_canvas->setBackground(Qt::white);
        m_canvas->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_canvas.get()));
    }

    void cleanup() { m_canvas.reset(); }

    void firstFrameIsFittedInsideTheWidget()
    {
        const QRectF page(m_canvas->mapFromCanvas({0, 0}), m_canvas->mapFromCanvas({2, 1}));
        QVERIFY(QRectF(m_canvas->rect()).contains(page));
        // Fitted, not just inside: the wider side fills the width up to the margin.
        QVERIFY(page.width() > 0.8 * m_canvas->width());
        QVERIFY(near(page.center(), QRectF(m_canvas->rect()).center(), 1e-6));
    }

    void fitToWindowUndoesZoomAndPan()
    {
        wheel(m_canvas.get(), {50, 50}, 600);
        drag(m_canvas.get(), Qt::MiddleButton, {100, 100}, {300, 250});
        QVERIFY(!QRectF(m_canvas->rect()).contains(QRectF(m_canvas->mapFromCanvas({0, 0}), m_canvas->mapFromCanvas({2, 1}))));
        m_canvas->fitToWindow();
        QVERIFY(QRectF(m_canvas->rect()).contains(QRectF(m_canvas->mapFromCanvas({0, 0}), m_canvas->mapFromCanvas({2, 1}))));
        // Fitting lasts: a resize fits again.
        m_canvas->resize(200, 500);
        const QRectF page(m_canvas->mapFromCanvas({0, 0}), m_canvas->mapFromCanvas({2, 1}));
        QVERIFY(QRectF(m_canvas->rect()).contains(page));
        QVERIFY(page.width() > 0.8 * 200);
    }

    void mapRoundTripUnderZoomAndPan()
    {
        const double fitted = m_canvas->zoom();
        wheel(m_canvas.get(), {120, 90}, 360);
        drag(m_canvas.get(), Qt::MiddleButton, {200, 150}, {150, 170});
        m_canvas->zoomOut();
        QVERIFY(m_canvas->zoom() != fitted);
        for (const QPointF p : {QPointF(0, 0), QPointF(2, 1), QPointF(0.37, 0.81), QPointF(-3.5, 12.25)})
            QVERIFY(near(m_canvas->mapToCanvas(m_canvas->mapFromCanvas(p)), p, 1e-12));
        for (const QPointF w : {QPointF(0, 0), QPointF(399.5, 299.5), QPointF(17.25, 230)})
            QVERIFY(near(m_canvas->mapFromCanvas(m_canvas->mapToCanvas(w)), w, 1e-9));
    }

    void wheelZoomKeepsThePointUnderTheCursor()
    {
        const QPointF cursor(123, 77);
        const QPointF under = m_canvas->mapToCanvas(cursor);
        const double before = m_canvas->zoom();
        wheel(m_canvas.get(), cursor, 120);
        QVERIFY(m_canvas->zoom() > before);
        QVERIFY(near(m_canvas->mapToCanvas(cursor), under, 1e-9));
        wheel(m_canvas.get(), cursor, -480);
        QVERIFY(m_canvas->zoom() < before);
        QVERIFY(near(m_canvas->mapToCanvas(cursor), under, 1e-9));
    }

    void pinchZoomKeepsThePointUnderTheFingers()
    {
        const QPointF centre(300, 200);
        const QPointF under = m_canvas->mapToCanvas(centre);
        const double before = m_canvas->zoom();
        QNativeGestureEvent pinch(Qt::ZoomNativeGesture, QPointingDevice::primaryPointingDevice(), 2, centre,
                                  centre, m_canvas->mapToGlobal(centre), 0.5, QPointF());
        QApplication::sendEvent(m_canvas.get(), &pinch);
        QVERIFY(std::abs(m_canvas->zoom() / before - 1.5) < 1e-9);
        QVERIFY(near(m_canvas->mapToCanvas(centre), under, 1e-9));
    }

    void zoomIsBounded()
    {
        for (int i = 0; i < 200; ++i)
            wheel(m_canvas.get(), {10, 10}, 1200);
        const double most = m_canvas->zoom();
        QVERIFY(std::isfinite(most));
        wheel(m_canvas.get(), {10, 10}, 1200);
        QCOMPARE(m_canvas->zoom(), most);
        for (int i = 0; i < 400; ++i)
            wheel(m_canvas.get(), {10, 10}, -1200);
        QVERIFY(m_canvas->zoom() > 0.0);
        QVERIFY(m_canvas->mapFromCanvas({2, 1}).x() - m_canvas->mapFromCanvas({0, 0}).x() >= 1.0);
    }

    void dropClickUsesTheDefaultRadius()
    {
        QSignalSpy drops(m_canvas.get(), &Canvas::dropRequested);
        m_canvas->setTool(Tool::Drop);
        m_canvas->setClickDropRadius(0.07);
        QTest::mouseClick(m_canvas.get(), Qt::LeftButton, {}, QPoint(150, 120));
        QCOMPARE(drops.count(), 1);
        QVERIFY(near(drops[0][0].toPointF(), m_canvas->mapToCanvas(QPointF(150, 120))));
        QCOMPARE(drops[0][1].toDouble(), 0.07 * 2.0);  // of the canvas width
    }

    void dropDragSetsTheRadius()
    {
        QSignalSpy drops(m_canvas.get(), &Canvas::dropRequested);
        m_canvas->setTool(Tool::Drop);
        drag(m_canvas.get(), Qt::LeftButton, {150, 120}, {180, 160});  // 50 px away
        QCOMPARE(drops.count(), 1);
        QVERIFY(near(drops[0][0].toPointF(), m_canvas->mapToCanvas(QPointF(150, 120))));
        QVERIFY(std::abs(drops[0][1].toDouble() - 50.0 / m_canvas->zoom()) < 1e-9);
    }

    void stylusEmitsAConnectedTimedStroke()
    {
        QSignalSpy started(m_canvas.get(), &Canvas::strokeStarted);
        QSignalSpy moved(m_canvas.get(), &Canvas::strokeMoved);
        QSignalSpy finished(m_canvas.get(), &Canvas::strokeFinished);
        m_canvas->setTool(Tool::Stylus);
        const QList<QPoint> path{{100, 100}, {120, 110}, {150, 115}, {190, 140}};
        QTest::mousePress(m_canvas.get(), Qt::LeftButton, {}, path[0]);
        for (int i = 1; i < path.size(); ++i)
            QTest::mouseMove(m_canvas.get(), path[i], 20);
        QTest::mouseRelease(m_canvas.get(), Qt::LeftButton, {}, path.last());

        QCOMPARE(started.count(), 1);
        QVERIFY(near(started[0][0].toPointF(), m_canvas->mapToCanvas(QPointF(path[0]))));
        QCOMPARE(moved.count(), path.size() - 1);
        for (int i = 0; i < moved.count(); ++i) {
            QVERIFY(near(moved[i][0].toPointF(), m_canvas->mapToCanvas(QPointF(path[i]))));
            QVERIFY(near(moved[i][1].toPointF(), m_canvas->mapToCanvas(QPointF(path[i + 1]))));
            QVERIFY(moved[i][2].toDouble() > 0.0);
        }
        QCOMPARE(finished.count(), 1);
    }

    // A click starts the text at its baseline; typing edits it, Enter sets it, Esc drops it.
    void textIsTypedWhereClicked()
    {
        QSignalSpy edits(m_canvas.get(), &Canvas::textEdited);
        QSignalSpy commits(m_canvas.get(), &Canvas::textCommitted);
        QSignalSpy drops(m_canvas.get(), &Canvas::dropRequested);
        m_canvas->setTool(Tool::Text);
        QTest::mouseClick(m_canvas.get(), Qt::LeftButton, {}, QPoint(210, 90));
        QVERIFY(m_canvas->textEntry().isActive());
        QVERIFY(near(m_canvas->textEntry().baselineStart(), m_canvas->mapToCanvas(QPointF(210, 90))));
        QTest::keyClicks(m_canvas.get(), QStringLiteral("Sun x"));
        QTest::keyClick(m_canvas.get(), Qt::Key_Backspace);
        QCOMPARE(m_canvas->textEntry().text(), QStringLiteral("Sun "));
        QCOMPARE(edits.count(), 1 + 5 + 1);
        QTest::keyClick(m_canvas.get(), Qt::Key_Return);
        QCOMPARE(commits.count(), 1);
        QCOMPARE(commits[0][1].toString(), QStringLiteral("Sun "));
        QVERIFY(near(commits[0][0].toPointF(), m_canvas->mapToCanvas(QPointF(210, 90))));
        QVERIFY(!m_canvas->textEntry().isActive());

        QTest::mouseClick(m_canvas.get(), Qt::LeftButton, {}, QPoint(100, 100));
        QTest::keyClicks(m_canvas.get(), QStringLiteral("gone"));
        QTest::keyClick(m_canvas.get(), Qt::Key_Escape);
        QVERIFY(!m_canvas->textEntry().isActive());
        QCOMPARE(commits.count(), 1);
        QCOMPARE(drops.count(), 0);
    }

    void panningMovesTheViewAndRequestsNothing_data()
    {
        QTest::addColumn<int>("way");
        QTest::newRow("pan tool") << 0;
        QTest::newRow("middle button") << 1;
        QTest::newRow("space + drag") << 2;
    }

    void panningMovesTheViewAndRequestsNothing()
    {
        QFETCH(int, way);
        QSignalSpy drops(m_canvas.get(), &Canvas::dropRequested);
        QSignalSpy strokes(m_canvas.get(), &Canvas::strokeStarted);
        m_canvas->setTool(way == 0 ? Tool::Pan : Tool::Drop);
        const QPointF origin = m_canvas->mapFromCanvas({0, 0});
        const double zoom = m_canvas->zoom();
        if (way == 2)
            QTest::keyPress(m_canvas.get(), Qt::Key_Space);
        drag(m_canvas.get(), way == 1 ? Qt::MiddleButton : Qt::LeftButton, {100, 100}, {160, 70});
        if (way == 2)
            QTest::keyRelease(m_canvas.get(), Qt::Key_Space);
        QVERIFY(near(m_canvas->mapFromCanvas({0, 0}), origin + QPointF(60, -30)));
        QCOMPARE(m_canvas->zoom(), zoom);
        QCOMPARE(drops.count() + strokes.count(), 0);
        // Space released: the Drop tool works again.
        QTest::mouseClick(m_canvas.get(), Qt::LeftButton, {}, QPoint(100, 100));
        QCOMPARE(drops.count(), way == 0 ? 0 : 1);
    }

    void regionsFollowTheTable()
    {
        // (0.3, 0.5): ring and bar overlap. (0.5, 0.5): the ring's hole, bar only.
        // (0.7, 0.3): ring only.
        const auto colourAt = [&](QPointF canvasPoint) {
            const QImage image = m_canvas->grab().toImage();
            return image.pixelColor((m_canvas->mapFromCanvas(canvasPoint) * image.devicePixelRatio()).toPoint());
        };
        const QPointF both(0.3, 0.5), hole(0.5, 0.5), ringOnly(0.7, 0.3), hollow(0.5, 0.42);
        QCOMPARE(colourAt(both), QColor(Qt::blue));  // the bar is on top
        QCOMPARE(colourAt(ringOnly), QColor(Qt::red));
        QCOMPARE(colourAt(hollow), QColor(Qt::white));  // even-odd: the inner square is a hole

        m_canvas->setRegions(lookFor(true, true, true));  // ring on top
        QCOMPARE(colourAt(both), QColor(Qt::red));
        QCOMPARE(colourAt(hole), QColor(Qt::blue));

        m_canvas->setRegions(lookFor(true, false));  // bar hidden
        QCOMPARE(colourAt(both), QColor(Qt::red));
        QCOMPARE(colourAt(hole), QColor(Qt::white));

        m_canvas->setRegions(lookFor(false, false));
        m_canvas->setBackground(Qt::green);
        QCOMPARE(colourAt(both), QColor(Qt::green));
    }

    void overlaysDrawOnlyWhenOn()
    {
        auto frame = std::make_shared<model::Frame>(*twoRegionFrame());
        sim::MacVelocity field;
        field.nx = 4;
        field.ny = 2;
        field.hx = field.hy = 0.5;
        field.u.assign(std::size_t((field.nx + 1) * field.ny), 1.0);  // a uniform flow to the right
        field.v.assign(std::size_t(field.nx * (field.ny + 1)), 0.0);
        frame->velocity = field;
        m_canvas->setFrame(frame);
        const auto colourAt = [&](QPointF canvasPoint) {
            const QImage image = m_canvas->grab().toImage();
            return image.pixelColor((m_canvas->mapFromCanvas(canvasPoint) * image.devicePixelRatio()).toPoint());
        };
        const QPointF gridLine(1.0, 0.1);    // between cells 1 and 2, on white
        const QPointF barCorner(1.5, 0.55);  // a vertex of the blue bar
        QCOMPARE(colourAt(gridLine), QColor(Qt::white));
        const QColor cornerBefore = colourAt(barCorner);
        m_canvas->setShowGrid(true);
        QVERIFY(colourAt(gridLine) != QColor(Qt::white));
        m_canvas->setShowGrid(false);
        QCOMPARE(colourAt(gridLine), QColor(Qt::white));
        m_canvas->setShowVertices(true);
        QVERIFY(colourAt(barCorner) != cornerBefore);

        // Arrows: some pixels of the white corner (no ink there) change.
        m_canvas->setShowVertices(false);
        const QImage without = m_canvas->grab().toImage();
        m_canvas->setShowVelocity(true);
        const QImage with = m_canvas->grab().toImage();
        QVERIFY(with != without);
    }

    void paintedFramesAreCounted()
    {
        m_canvas->grab();
        m_canvas->grab();
        QVERIFY(m_canvas->displayFps() >= 2);
    }
};

QTEST_MAIN(TestCanvas)
#include "tst_canvas.moc"
