// render/SvgRounding: the step follows the canvas, rounded vertices print in the step's digits,
// rounding drops the vertices it makes equal and never makes a crossing.
#include "TestGeometry.h"

#include "render/SvgRounding.h"
#include "sim/Crossings.h"

#include <QtTest>

#include <charconv>
#include <string>

using namespace vf;
using sim::Polygon;
using sim::Vec2;

namespace {

model::DrawnRegion regionOf(std::vector<Polygon> contours)
{
    return {QStringLiteral("r"), Qt::black, true, std::move(contours)};
}

// Digits after the decimal point in the shortest text that reads back as `value`.
int decimalsOf(double value)
{
    char text[32];
    const std::string s(text, std::to_chars(text, text + sizeof text, value).ptr);
    const std::size_t point = s.find('.');
    return point == std::string::npos ? 0 : int(s.size() - point - 1);
}

} // namespace

class TestSvgRounding : public QObject {
    Q_OBJECT

private slots:
    void stepIsAPowerOfTenBelowAMillionthOfTheCanvas();
    void verticesMoveLessThanHalfAStepAndPrintShort();
    void verticesThatMeetAreDropped();
    void roundingThatWouldCrossKeepsTheRegionExact();
};

void TestSvgRounding::stepIsAPowerOfTenBelowAMillionthOfTheCanvas()
{
    const auto step = [](double width, double height) {
        model::Drawing drawing;
        drawing.width = width;
        drawing.height = height;
        return render::svgCoordinateStep(drawing);
    };
    QCOMPARE(step(1, 0.75), 1e-6);
    QCOMPARE(step(0.5, 3), 1e-6);
    QCOMPARE(step(1000, 700), 1e-3);
    QCOMPARE(step(999, 700), 1e-4);
    QCOMPARE(step(1e6, 1), 1.0);
}

void TestSvgRounding::verticesMoveLessThanHalfAStepAndPrintShort()
{
    const Polygon wobbly = test::wobblyPolygon({0.5, 0.5}, 0.3, 5000, 3);
    const render::RoundedRegion rounded = render::roundedRegion(regionOf({wobbly}), 1e-6);
    QVERIFY(!rounded.exact);
    QCOMPARE(rounded.region.contours.size(), std::size_t(1));
    const Polygon& out = rounded.region.contours.front();
    QCOMPARE(out.size(), wobbly.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        QVERIFY(std::abs(out[i].x - wobbly[i].x) <= 0.5e-6 * (1 + 1e-9));
        QVERIFY(std::abs(out[i].y - wobbly[i].y) <= 0.5e-6 * (1 + 1e-9));
        QVERIFY(decimalsOf(out[i].x) <= 6 && decimalsOf(out[i].y) <= 6);
    }
}

// Two vertices 1e-7 apart become one; a contour smaller than the step disappears.
void TestSvgRounding::verticesThatMeetAreDropped()
{
    const Polygon square = {{0.1, 0.1}, {0.2, 0.1}, {0.2000001, 0.1000001}, {0.2, 0.2}, {0.1, 0.2}, {0.1000001, 0.1}};
    const Polygon speck = {{0.5, 0.5}, {0.5000002, 0.5}, {0.5, 0.5000002}};
    const render::RoundedRegion rounded = render::roundedRegion(regionOf({square, speck}), 1e-6);
    QVERIFY(!rounded.exact);
    QCOMPARE(rounded.region.contours.size(), std::size_t(1));
    const Polygon expected = {{0.1, 0.1}, {0.2, 0.1}, {0.2, 0.2}, {0.1, 0.2}};
    QVERIFY(rounded.region.contours.front() == expected);
}

// A spike whose tip is 3e-7 below a slanted edge of another contour: rounded, the tip rises to
// 0.500001 and the edge's middle falls to 0.5000005, so the spike would pierce the edge.
void TestSvgRounding::roundingThatWouldCrossKeepsTheRegionExact()
{
    const Polygon spike = {{0.45, 0.4}, {0.55, 0.4}, {0.5, 0.5000006}};
    const Polygon above = {{0.4, 0.5000004}, {0.6, 0.5000014}, {0.6, 0.7}, {0.4, 0.7}};
    QCOMPARE(sim::countCrossings({&spike, &above}), std::size_t(0));
    const model::DrawnRegion region = regionOf({spike, above});
    const render::RoundedRegion rounded = render::roundedRegion(region, 1e-6);
    QVERIFY(rounded.exact);
    QVERIFY(rounded.region.contours == region.contours);

    const render::RoundedRegion apart = render::roundedRegion(regionOf({spike}), 1e-6);
    QVERIFY(!apart.exact);  // alone, the spike rounds as any contour
}

QTEST_GUILESS_MAIN(TestSvgRounding)
#include "tst_svgrounding.moc"
