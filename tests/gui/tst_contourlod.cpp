// ContourLod: a contour decimated for display keeps no more vertices than its pixels need, stays
// within the documented distance of the original, stays closed, keeps its extreme points, and
// disappears only when it lies outside the view. RegionPaths: panning draws the paths it built,
// shifted, as they would be built for the panned view, and builds them again only past their area.
#include "app/ContourLod.h"
#include "app/RegionPaths.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

using namespace vf;
using namespace vf::app;

namespace {

constexpr double kBound = kLodTolerance * std::numbers::sqrt2;  // the documented error bound
const QRectF kEverywhere(-1e9, -1e9, 2e9, 2e9);

sim::Polygon onDevice(const sim::Polygon& contour, const PixelMapping& m)
{
    sim::Polygon out;
    for (const sim::Vec2& v : contour) {
        const QPointF p = m.map(v);
        out.emplace_back(p.x(), p.y());
    }
    return out;
}

sim::Polygon toPolygon(const QPolygonF& points)
{
    sim::Polygon out;
    for (const QPointF& p : points)
        out.emplace_back(p.x(), p.y());
    return out;
}

// r(θ) = R·(1 + 0.3 sin 7θ + 0.1 sin 31θ): a marbled blob with both broad and fine wiggles.
sim::Polygon wigglyContour(sim::Vec2 centre, double radius, int vertices)
{
    sim::Polygon out;
    for (int i = 0; i < vertices; ++i) {
        const double a = 2.0 * std::numbers::pi * i / vertices;
        const double r = radius * (1.0 + 0.3 * std::sin(7 * a) + 0.1 * std::sin(31 * a));
        out.push_back(centre + r * sim::Vec2(std::cos(a), std::sin(a)));
    }
    return out;
}

// A box with a slit thinner than a pixel cut from its left side to near its middle: the contour
// runs along the slit and folds back. The fold's far end is neither extreme nor a sharp turn in
// direction as seen from the slit's mouth, so only a rule against folding back keeps it.
sim::Polygon slitBox(double slitLength, double gap)
{
    const sim::Polygon corners{{0, 0}, {400, 0}, {400, 200}, {0, 200}, {0, 100 + gap},
                               {slitLength, 100 + gap}, {slitLength, 100}, {0, 100}};
    return sim::resample(corners, 0.1);
}

bool contains(const QPolygonF& points, QPointF p)
{
    return std::find(points.begin(), points.end(), p) != points.end();
}

} // namespace

class TestContourLod : public QObject {
    Q_OBJECT

private slots:
    void bigCircleNeedsFewVerticesAndStaysClose()
    {
        const sim::Polygon contour = sim::circle({0.5, 0.5}, 0.4, 1e-4);  // ~25k vertices
        const PixelMapping m{1000.0, 12.0, -7.0};                              // radius 400 px
        QPolygonF kept;
        decimateContour(contour, m, kLodTolerance, kEverywhere, kept);

        // A regular polygon whose sagitta is the tolerance needs π / acos(1 − tol/R) vertices;
        // a greedy choice may need up to twice that, plus the forced extremes.
        const double needed = std::numbers::pi / std::acos(1.0 - kLodTolerance / 400.0);
        QVERIFY2(kept.size() <= 2 * needed + 4, qPrintable(QString::number(kept.size())));
        QVERIFY(kept.size() >= needed / 2);
        QVERIFY(sim::hausdorffDistance(onDevice(contour, m), toPolygon(kept)) <= kBound);
        QVERIFY(kept.first() != kept.last());  // closed by the implicit last edge, not repeated
    }

    void wigglyContourWithinBounds_data()
    {
        QTest::addColumn<double>("scale");
        QTest::newRow("far out: 50 px") << 100.0;
        QTest::newRow("fit: 800 px") << 1600.0;
        QTest::newRow("zoomed in: 20000 px") << 40000.0;
    }

    void wigglyContourWithinBounds()
    {
        QFETCH(double, scale);
        const sim::Polygon contour = wigglyContour({0.5, 0.5}, 0.25, 20000);
        const PixelMapping m{scale, 3.0, 5.0};
        const sim::Polygon device = onDevice(contour, m);
        QPolygonF kept;
        decimateContour(contour, m, kLodTolerance, kEverywhere, kept);

        QVERIFY(kept.size() <= qsizetype(contour.size()));
        QVERIFY2(kept.size() <= sim::perimeter(device) / kLodTolerance + 4,
                 qPrintable(QStringLiteral("%1 kept, perimeter %2 px").arg(kept.size()).arg(sim::perimeter(device))));
        QVERIFY(sim::hausdorffDistance(device, toPolygon(kept)) <= kBound);
        // The four extremes are the original's own vertices, so the bounding box is exact.
        QPolygonF all;
        for (const sim::Vec2& v : device)
            all.append({v.x, v.y});
        QCOMPARE(kept.boundingRect(), all.boundingRect());
    }

    void foldedFilamentKeepsItsTip()
    {
        const sim::Polygon contour = slitBox(300.0, 0.2);
        QPolygonF kept;
        decimateContour(contour, PixelMapping{1.0, 0.0, 0.0}, kLodTolerance, kEverywhere, kept);
        QVERIFY(sim::hausdorffDistance(contour, toPolygon(kept)) <= kBound);
        QVERIFY(kept.size() <= 16);  // straight sides only
    }

    void extremePointsAreKept()
    {
        const sim::Polygon contour = wigglyContour({0.4, 0.6}, 0.3, 20000);
        const PixelMapping m{500.0, 0.0, 0.0};
        QPolygonF kept;
        decimateContour(contour, m, kLodTolerance, kEverywhere, kept);
        const auto byX = [](const sim::Vec2& a, const sim::Vec2& b) { return a.x < b.x; };
        const auto byY = [](const sim::Vec2& a, const sim::Vec2& b) { return a.y < b.y; };
        for (const sim::Vec2& extreme : {*std::min_element(contour.begin(), contour.end(), byX),
                                         *std::max_element(contour.begin(), contour.end(), byX),
                                         *std::min_element(contour.begin(), contour.end(), byY),
                                         *std::max_element(contour.begin(), contour.end(), byY)})
            QVERIFY(contains(kept, m.map(extreme)));
    }

    void subPixelContourCollapses()
    {
        const sim::Polygon contour = sim::circle({0.5, 0.5}, 1e-4, 1e-6);  // 0.1 px across
        QPolygonF kept;
        decimateContour(contour, PixelMapping{1000.0, 0.0, 0.0}, kLodTolerance, kEverywhere, kept);
        QVERIFY(!kept.isEmpty());
        QVERIFY(kept.size() <= 4);
    }

    void contoursOutsideTheViewAreSkipped()
    {
        const sim::Polygon contour = sim::circle({0.5, 0.5}, 0.1, 0.001);  // 400..600 px
        const PixelMapping m{1000.0, 0.0, 0.0};
        QPolygonF kept;
        decimateContour(contour, m, kLodTolerance, QRectF(0, 0, 390, 390), kept);
        QVERIFY(kept.isEmpty());
        decimateContour(contour, m, kLodTolerance, QRectF(0, 0, 410, 410), kept);
        QVERIFY(!kept.isEmpty());
        // A flat contour (zero height) is still seen.
        decimateContour(sim::Polygon{{0.1, 0.2}, {0.3, 0.2}, {0.2, 0.2}}, m, kLodTolerance,
                        QRectF(0, 0, 1000, 1000), kept);
        QVERIFY(!kept.isEmpty());
    }

    void panningShiftsThePathsItBuilt()
    {
        auto frame = std::make_shared<model::Frame>();
        frame->regions = {{sim::circle({0.5, 0.5}, 0.1, 0.001)}};  // 400..600 px at 1000 px a unit
        const QRectF view(0, 0, 800, 600);
        const PixelMapping at{1000.0, 0.0, 0.0}, panned{1000.0, 300.0, -250.0};
        RegionPaths paths;
        paths.setView(frame, at, view);
        const QPainterPath built = paths.region(0);

        // Shifted, it is what decimating for the panned view gives.
        QPolygonF fresh;
        decimateContour(frame->regions[0][0], panned, kLodTolerance, view, fresh);
        const QPainterPath shifted = built.translated(300.0, -250.0);
        QCOMPARE(shifted.elementCount(), qsizetype(fresh.size()) + 1);  // closed: the first point again
        for (qsizetype i = 0; i < fresh.size(); ++i)
            QVERIFY(std::hypot(shifted.elementAt(int(i)).x - fresh[i].x(), shifted.elementAt(int(i)).y - fresh[i].y()) < 1e-9);

        // Panned within its area, the path is not built again: a contour changed in place (the
        // app's frames never are) does not show.
        frame->regions[0][0] = sim::circle({0.5, 0.5}, 0.05, 0.001);
        paths.setView(frame, panned, view);
        QCOMPARE(paths.shift(), QPointF(300.0, -250.0));
        QVERIFY(paths.region(0) == built);
        // Three views away, or at another zoom, it is.
        paths.setView(frame, PixelMapping{1000.0, 3000.0, 0.0}, view);
        QVERIFY(paths.region(0).isEmpty());  // the circle lies outside this view
        paths.setView(frame, PixelMapping{2000.0, 0.0, 0.0}, QRectF(0, 0, 2000, 2000));
        QVERIFY(std::abs(paths.region(0).boundingRect().width() - 200.0) < 1.0);  // the new circle
    }
};

QTEST_APPLESS_MAIN(TestContourLod)
#include "tst_contourlod.moc"
