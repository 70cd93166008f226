// The Bézier fitter on its own: the two-sided tolerance, interpolation of vertices, compactness,
// corners, and inputs that could produce NaNs.
#include "TestGeometry.h"

#include "render/BezierFit.h"

#include <QtTest>

using namespace vf;
using sim::Polygon;
using sim::Vec2;

Q_DECLARE_METATYPE(Polygon)

class TestBezierFit : public QObject {
    Q_OBJECT

private slots:
    void circleWithinTolerance_data();
    void circleWithinTolerance();
    void wobblyShapeWithinTolerance_data();
    void wobblyShapeWithinTolerance();
    void smoothCircleIsCompact();
    void squareBecomesFourLines();
    void halfDiscKeepsItsCorners();
    void degenerateInputsStayFinite_data();
    void degenerateInputsStayFinite();
    void largeContourInterpolatesVertices();
};

namespace {

bool allFinite(const render::FittedContour& contour)
{
    const auto finite = [](Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); };
    return finite(contour.start)
           && std::all_of(contour.segments.begin(), contour.segments.end(), [&](const render::PathSegment& s) {
                  return finite(s.end) && (s.isLine || (finite(s.control1) && finite(s.control2)));
              });
}

// test::deviation is an upper bound up to rounding, so only rounding needs room.
constexpr double kMeasureSlack = 1e-9;

} // namespace

void TestBezierFit::circleWithinTolerance_data()
{
    QTest::addColumn<double>("radius");
    QTest::addColumn<int>("count");
    QTest::addColumn<double>("tolerance");
    QTest::newRow("default-ish") << 0.15 << 236 << 1.4e-4;
    QTest::newRow("tight") << 0.3 << 400 << 1e-6;
    QTest::newRow("small circle, loose") << 0.01 << 16 << 1e-3;
    QTest::newRow("coarse") << 0.4 << 40 << 1e-4;
}

void TestBezierFit::circleWithinTolerance()
{
    QFETCH(double, radius);
    QFETCH(int, count);
    QFETCH(double, tolerance);
    const Polygon polygon = test::circlePolygon({0.5, 0.5}, radius, count);
    const render::FittedContour fitted = render::fitClosedPolygon(polygon, tolerance);
    QVERIFY(test::endsFollowVertices(fitted, polygon));
    const double worst = test::deviation(fitted, polygon);
    QVERIFY2(worst <= tolerance * (1 + kMeasureSlack), qPrintable(QString::number(worst)));
}

void TestBezierFit::wobblyShapeWithinTolerance_data()
{
    QTest::addColumn<unsigned>("seed");
    QTest::addColumn<double>("tolerance");
    QTest::newRow("seed 1") << 1u << 1.4e-4;
    QTest::newRow("seed 2") << 2u << 1.4e-4;
    QTest::newRow("seed 3, below the noise") << 3u << 5e-5;
    QTest::newRow("seed 4, loose") << 4u << 1e-3;
}

void TestBezierFit::wobblyShapeWithinTolerance()
{
    QFETCH(unsigned, seed);
    QFETCH(double, tolerance);
    const Polygon polygon = test::wobblyPolygon({0.5, 0.5}, 0.3, 600, seed);
    const render::FittedContour fitted = render::fitClosedPolygon(polygon, tolerance);
    QVERIFY(test::endsFollowVertices(fitted, polygon));
    const double worst = test::deviation(fitted, polygon);
    QVERIFY2(worst <= tolerance * (1 + kMeasureSlack), qPrintable(QString::number(worst)));
}

void TestBezierFit::smoothCircleIsCompact()
{
    const Polygon polygon = test::circlePolygon({0.5, 0.5}, 0.3, 1000);
    const render::FittedContour fitted = render::fitClosedPolygon(polygon, 1.4e-4);
    QVERIFY2(fitted.segments.size() <= 4, qPrintable(QString::number(fitted.segments.size())));
    QVERIFY(std::none_of(fitted.segments.begin(), fitted.segments.end(),
                         [](const render::PathSegment& s) { return s.isLine; }));
}

void TestBezierFit::squareBecomesFourLines()
{
    const Polygon polygon = test::squarePolygon({0.2, 0.3}, 0.4, 50);
    const render::FittedContour fitted = render::fitClosedPolygon(polygon, 1.4e-4);
    QCOMPARE(fitted.segments.size(), std::size_t(4));
    const Vec2 c(0.2, 0.3);
    const std::vector<Vec2> corners{c, c + Vec2(0.4, 0), c + Vec2(0.4, 0.4), c + Vec2(0, 0.4)};
    QVERIFY(std::find(corners.begin(), corners.end(), fitted.start) != corners.end());
    for (const render::PathSegment& s : fitted.segments) {
        QVERIFY(s.isLine);
        QVERIFY(std::find(corners.begin(), corners.end(), s.end) != corners.end());
    }
}

// A semicircle closed by its diameter: the two 90° junctions must be segment ends (kinks kept),
// and the arc must still come out as a few cubics.
void TestBezierFit::halfDiscKeepsItsCorners()
{
    Polygon polygon;
    const int arc = 200;
    for (int i = 0; i <= arc; ++i) {
        const double a = std::numbers::pi * i / arc;
        polygon.push_back(Vec2(0.5, 0.5) + 0.3 * Vec2(std::cos(a), -std::sin(a)));
    }
    for (int i = 1; i < 50; ++i)
        polygon.push_back(glm::mix(Vec2(0.2, 0.5), Vec2(0.8, 0.5), double(i) / 50));
    const render::FittedContour fitted = render::fitClosedPolygon(polygon, 1.4e-4);
    std::vector<Vec2> ends{fitted.start};
    for (const render::PathSegment& s : fitted.segments)
        ends.push_back(s.end);
    QVERIFY(std::find(ends.begin(), ends.end(), polygon[0]) != ends.end());
    QVERIFY(std::find(ends.begin(), ends.end(), polygon[arc]) != ends.end());
    QVERIFY(fitted.segments.size() <= 8);
    QVERIFY(test::deviation(fitted, polygon) <= 1.4e-4 * (1 + kMeasureSlack));
}

void TestBezierFit::degenerateInputsStayFinite_data()
{
    QTest::addColumn<Polygon>("polygon");
    QTest::addColumn<int>("segments");
    QTest::newRow("empty") << Polygon{} << 0;
    QTest::newRow("one point") << Polygon{{0.5, 0.5}} << 0;
    QTest::newRow("two points") << Polygon{{0.1, 0.1}, {0.2, 0.1}} << 2;
    QTest::newRow("repeated vertices") << Polygon{{0.1, 0.1}, {0.1, 0.1}, {0.2, 0.1}, {0.2, 0.2}, {0.2, 0.2},
                                                  {0.1, 0.1}}
                                       << 3;
    QTest::newRow("hairpin") << Polygon{{0.1, 0.1}, {0.5, 0.1}, {0.9, 0.1}, {0.5, 0.1}} << -1;
    Polygon dense = test::circlePolygon({0.5, 0.5}, 0.2, 200);
    dense.insert(dense.begin() + 50, dense[50]);
    dense.push_back(dense.front());
    QTest::newRow("circle with duplicates") << dense << -1;
}

void TestBezierFit::degenerateInputsStayFinite()
{
    QFETCH(Polygon, polygon);
    QFETCH(int, segments);
    const render::FittedContour fitted = render::fitClosedPolygon(polygon, 1e-4);
    QVERIFY(allFinite(fitted));
    if (segments >= 0)
        QCOMPARE(int(fitted.segments.size()), segments);
    if (!fitted.segments.empty())
        QCOMPARE(fitted.segments.back().end, fitted.start);
}

// Large enough to exercise the halving of long pieces; the two-sided check is brute force, so
// only the structure is verified at this size.
void TestBezierFit::largeContourInterpolatesVertices()
{
    const Polygon polygon = test::wobblyPolygon({0.5, 0.5}, 0.35, 30000, 7, 0.0);
    const render::FittedContour fitted = render::fitClosedPolygon(polygon, 1.4e-4);
    QVERIFY(allFinite(fitted));
    QVERIFY(test::endsFollowVertices(fitted, polygon));
    QVERIFY2(fitted.segments.size() < polygon.size() / 20, qPrintable(QString::number(fitted.segments.size())));
}

QTEST_GUILESS_MAIN(TestBezierFit)
#include "tst_bezierfit.moc"
