// SVG import: every element kind and path command becomes the right region in canvas units,
// curves are flattened within the spacing with vertices on the true curve, transforms, the viewBox
// fit and colours follow SVG, and bad files give one line naming the problem.
// One file past 500 lines: each element kind and path command is a case, sharing the helpers below.
#include "model/SvgImport.h"
#include "sim/Crossings.h"

#include <QTemporaryDir>
#include <QtTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

using namespace vf;
using namespace vf::model;
using namespace Qt::StringLiterals;
using sim::Vec2;

namespace {

constexpr double kPi = std::numbers::pi;
// The edge bound holds up to the rounding of sim::resample's equal pieces.
constexpr double kEdgeSlack = 1.0 + 1e-9;
// Vertices need not fall on a curve's extreme points: a chord of length s where the radius of
// curvature is r stays within s²/(8r) of the curve, under 5e-4 for the spacings and curves here.
constexpr double kCurveBoundsTolerance = 5e-4;

// viewBox 0 0 100 100 on the unit canvas: canvas = user units / 100.
SvgImport importBody(const QString& body, double spacing = 0.01, const QString& rootAttributes = u"viewBox=\"0 0 100 100\""_s)
{
    const QString svg = u"<svg xmlns=\"http://www.w3.org/2000/svg\" "_s + rootAttributes + u">"_s + body + u"</svg>"_s;
    return importSvg(svg.toUtf8(), u"test.svg"_s, 1.0, 1.0, spacing);
}

struct Box {
    Vec2 min{std::numeric_limits<double>::max()}, max{-std::numeric_limits<double>::max()};
};

Box bounds(const ImportedShape& shape)
{
    Box box;
    for (const sim::Polygon& contour : shape.contours) {
        for (const Vec2& p : contour) {
            box.min = glm::min(box.min, p);
            box.max = glm::max(box.max, p);
        }
    }
    return box;
}

// The area filled even-odd: a contour inside an odd number of others is a hole.
double filledArea(const ImportedShape& shape)
{
    double area = 0.0;
    for (const sim::Polygon& contour : shape.contours) {
        int depth = 0;
        for (const sim::Polygon& other : shape.contours)
            depth += &other != &contour && sim::windingNumber(other, contour.front()) != 0 ? 1 : 0;
        area += (depth % 2 == 0 ? 1.0 : -1.0) * sim::signedArea(contour);
    }
    return area;
}

double longestEdge(const sim::Polygon& contour)
{
    double longest = 0.0;
    for (std::size_t i = 0; i < contour.size(); ++i)
        longest = std::max(longest, glm::distance(contour[i], contour[(i + 1) % contour.size()]));
    return longest;
}

// What every imported shape promises: positive, simple, non-crossing contours with short edges.
void verifyWellFormed(const ImportedShape& shape, double spacing)
{
    QVERIFY(!shape.contours.empty());
    std::vector<const sim::Polygon*> all;
    for (const sim::Polygon& contour : shape.contours) {
        QVERIFY(contour.size() >= 3);
        QVERIFY2(sim::signedArea(contour) > 0.0, qPrintable(shape.name));
        QVERIFY2(sim::isSimple(contour), qPrintable(shape.name));
        QVERIFY2(longestEdge(contour) <= spacing * kEdgeSlack, qPrintable(shape.name));
        all.push_back(&contour);
    }
    QCOMPARE(sim::countCrossings(all), std::size_t(0));
}

void verifyOneLineError(const SvgImport& result, const QString& expected)
{
    QVERIFY2(!result.ok(), "accepted");
    QVERIFY(result.shapes.empty());
    QVERIFY2(result.error.startsWith(u"test.svg: "_s), qPrintable(result.error));
    QVERIFY2(result.error.contains(expected), qPrintable(u"expected \"%1\" in: %2"_s.arg(expected, result.error)));
    QVERIFY2(!result.error.contains(u'\n'), qPrintable(result.error));
}

// The largest distance between corresponding vertices of two contour lists of the same shape.
double vertexDifference(const std::vector<sim::Polygon>& a, const std::vector<sim::Polygon>& b)
{
    if (a.size() != b.size())
        return std::numeric_limits<double>::infinity();
    double difference = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].size() != b[i].size())
            return std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < a[i].size(); ++j)
            difference = std::max(difference, glm::distance(a[i][j], b[i][j]));
    }
    return difference;
}

bool onSegment(Vec2 p, Vec2 a, Vec2 b, double tolerance)
{
    const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
    return glm::distance(p, a + t * (b - a)) <= tolerance;
}

} // namespace

class TestSvgImport : public QObject {
    Q_OBJECT

private slots:
    void elementKinds_data()
    {
        QTest::addColumn<QString>("element");
        QTest::addColumn<double>("area");  // canvas units², to 1%
        QTest::addColumn<double>("minX");
        QTest::addColumn<double>("minY");
        QTest::addColumn<double>("maxX");
        QTest::addColumn<double>("maxY");
        QTest::newRow("rect") << u"<rect x='10' y='20' width='30' height='40'/>"_s << 0.12 << 0.1 << 0.2 << 0.4 << 0.6;
        QTest::newRow("rect px") << u"<rect x='10px' y='20' width='30px' height='40'/>"_s << 0.12 << 0.1 << 0.2 << 0.4 << 0.6;
        QTest::newRow("rounded rect") << u"<rect x='10' y='20' width='30' height='40' rx='10'/>"_s
                                      << 0.12 - (4.0 - kPi) * 0.01 << 0.1 << 0.2 << 0.4 << 0.6;
        QTest::newRow("circle") << u"<circle cx='50' cy='50' r='25'/>"_s << kPi * 0.0625 << 0.25 << 0.25 << 0.75 << 0.75;
        QTest::newRow("ellipse") << u"<ellipse cx='50' cy='40' rx='30' ry='10'/>"_s << kPi * 0.03 << 0.2 << 0.3 << 0.8 << 0.5;
        QTest::newRow("polygon") << u"<polygon points='10,10 90,10 50,90'/>"_s << 0.32 << 0.1 << 0.1 << 0.9 << 0.9;
        QTest::newRow("path") << u"<path d='M10 10 H90 V90 H10 Z'/>"_s << 0.64 << 0.1 << 0.1 << 0.9 << 0.9;
        QTest::newRow("open path is closed") << u"<path d='M10 10 H90 V90'/>"_s << 0.32 << 0.1 << 0.1 << 0.9 << 0.9;
    }
    void elementKinds()
    {
        QFETCH(QString, element);
        const SvgImport result = importBody(element, 0.005);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(result.shapes.size(), std::size_t(1));
        const ImportedShape& shape = result.shapes.front();
        QCOMPARE(shape.contours.size(), std::size_t(1));
        verifyWellFormed(shape, 0.005);
        QFETCH(double, area);
        QVERIFY2(std::abs(filledArea(shape) - area) <= 0.01 * area, qPrintable(QString::number(filledArea(shape))));
        const Box box = bounds(shape);
        QFETCH(double, minX);
        QFETCH(double, minY);
        QFETCH(double, maxX);
        QFETCH(double, maxY);
        QVERIFY(glm::distance(box.min, Vec2(minX, minY)) < kCurveBoundsTolerance);
        QVERIFY(glm::distance(box.max, Vec2(maxX, maxY)) < kCurveBoundsTolerance);
    }

    void namesFromIdOrTagAndCount()
    {
        const SvgImport result = importBody(u"<rect width='5' height='5'/><circle id='sun' cx='50' cy='50' r='5'/>"
                                            "<rect x='20' width='5' height='5'/>"_s);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(result.shapes.size(), std::size_t(3));
        QCOMPARE(result.shapes[0].name, u"rect 1"_s);
        QCOMPARE(result.shapes[1].name, u"sun"_s);
        QCOMPARE(result.shapes[2].name, u"rect 2"_s);
    }

    void relativeAndAbsoluteCommandsAgree()
    {
        // The same outline through every command, absolute, relative, and packed with implicit
        // repeats, flags without separators and numbers that run into each other.
        const QStringList forms = {
            u"M10 10 L30 10 H50 V30 C60 30 70 40 70 50 S60 70 50 70 Q40 80 30 70 T10 50 A10 10 0 0 1 10 30 Z"_s,
            u"m10 10 l20 0 h20 v20 c10 0 20 10 20 20 s-10 20 -20 20 q-10 10 -20 0 t-20 -20 a10 10 0 0 1 0 -20 z"_s,
            u"M10,10 30,10L50 10V30C60,30,70,40,70,50S60,70,50,70Q40,80,30,70T10,50A10,10,0,0110,30z"_s,
            u"M1e1 1e1l2e1-0h20v20c10 0 20 10 20 20s-10 20-20 20q-10 10-20 0t-20-20a10 10 0 0 1 0-20z"_s,
        };
        const SvgImport reference = importBody(u"<path d='%1'/>"_s.arg(forms[0]));
        QVERIFY2(reference.ok(), qPrintable(reference.error));
        verifyWellFormed(reference.shapes.front(), 0.01);
        for (const QString& d : forms) {
            const SvgImport result = importBody(u"<path d='%1'/>"_s.arg(d));
            QVERIFY2(result.ok(), qPrintable(d + u": "_s + result.error));
            QVERIFY2(vertexDifference(result.shapes.front().contours, reference.shapes.front().contours) < 1e-12, qPrintable(d));
        }
    }

    void numbersWithoutSeparators()
    {
        // "10-5.5.5" is 10, -5.5, .5 and "1.5e-3-2.5" is 1.5e-3, -2.5.
        const SvgImport packed = importBody(u"<path d='M0,0L1e1,0,10,10-5.5.5L1.5e-3-2.5z'/>"_s);
        const SvgImport spaced = importBody(u"<path d='M 0 0 L 10 0 L 10 10 L -5.5 0.5 L 0.0015 -2.5 Z'/>"_s);
        QVERIFY2(packed.ok(), qPrintable(packed.error));
        QVERIFY2(spaced.ok(), qPrintable(spaced.error));
        QCOMPARE(vertexDifference(packed.shapes.front().contours, spaced.shapes.front().contours), 0.0);
    }

    void curvesFlattenedOntoTheCurve_data()
    {
        QTest::addColumn<double>("spacing");
        QTest::newRow("fine") << 0.002;
        QTest::newRow("coarse") << 0.05;
    }
    void curvesFlattenedOntoTheCurve()
    {
        QFETCH(double, spacing);
        // A quarter of the ellipse around (50, 50) with radii 40, 30, closed by its chord.
        const SvgImport arc = importBody(u"<path d='M50 20 A40 30 0 0 1 90 50 Z'/>"_s, spacing);
        QVERIFY2(arc.ok(), qPrintable(arc.error));
        verifyWellFormed(arc.shapes.front(), spacing);
        int onArc = 0;
        for (const Vec2& p : arc.shapes.front().contours.front()) {
            const Vec2 q = (p - Vec2(0.5)) / Vec2(0.4, 0.3);
            const bool onEllipse = std::abs(glm::dot(q, q) - 1.0) < 1e-9 && p.x >= 0.5 - 1e-12 && p.y <= 0.5 + 1e-12;
            QVERIFY(onEllipse || onSegment(p, {0.5, 0.2}, {0.9, 0.5}, 1e-12));
            onArc += onEllipse ? 1 : 0;
        }
        QVERIFY(onArc > 4);

        // Radii too small to reach the end point grow until they do (SVG F.6.6): a half circle.
        const SvgImport grown = importBody(u"<path d='M10 50 A1 1 0 0 1 90 50 Z'/>"_s, spacing);
        QVERIFY2(grown.ok(), qPrintable(grown.error));
        verifyWellFormed(grown.shapes.front(), spacing);
        for (const Vec2& p : grown.shapes.front().contours.front())
            QVERIFY(std::abs(glm::distance(p, Vec2(0.5)) - 0.4) < 1e-9 || std::abs(p.y - 0.5) < 1e-12);
        QVERIFY(bounds(grown.shapes.front()).min.y < 0.1 + kCurveBoundsTolerance);  // sweep 1: up, through (50, 10)

        // A cubic: every vertex on the curve (to a dense polyline of it) or on the closing chord.
        const Vec2 c[4] = {{0.1, 0.8}, {0.2, 0.1}, {0.8, 0.1}, {0.9, 0.8}};
        const SvgImport cubic = importBody(u"<path d='M10 80 C20 10 80 10 90 80 Z'/>"_s, spacing);
        QVERIFY2(cubic.ok(), qPrintable(cubic.error));
        verifyWellFormed(cubic.shapes.front(), spacing);
        std::vector<Vec2> curve;
        constexpr int kSamples = 20000;
        for (int i = 0; i <= kSamples; ++i) {
            const double t = double(i) / kSamples, r = 1.0 - t;
            curve.push_back(r * r * r * c[0] + 3.0 * r * r * t * c[1] + 3.0 * r * t * t * c[2] + t * t * t * c[3]);
        }
        for (const Vec2& p : cubic.shapes.front().contours.front()) {
            bool onCurve = false;
            for (int i = 0; i < kSamples && !onCurve; ++i)
                onCurve = onSegment(p, curve[i], curve[i + 1], 1e-7);
            QVERIFY(onCurve || onSegment(p, c[3], c[0], 1e-12));
        }
    }

    void circleVerticesOnTheCircle()
    {
        const SvgImport result = importBody(u"<circle cx='50' cy='50' r='25'/>"_s, 0.003);
        QVERIFY2(result.ok(), qPrintable(result.error));
        verifyWellFormed(result.shapes.front(), 0.003);
        for (const Vec2& p : result.shapes.front().contours.front())
            QVERIFY(std::abs(glm::distance(p, Vec2(0.5)) - 0.25) < 1e-12);
        // Equal arc length: no edge much shorter than the others.
        const sim::Polygon& contour = result.shapes.front().contours.front();
        for (std::size_t i = 0; i < contour.size(); ++i)
            QVERIFY(glm::distance(contour[i], contour[(i + 1) % contour.size()]) > 0.9 * 0.25 * 2.0 * kPi / double(contour.size()));
    }

    void transforms_data()
    {
        QTest::addColumn<QString>("body");
        QTest::addColumn<double>("area");
        QTest::addColumn<double>("minX");
        QTest::addColumn<double>("minY");
        QTest::addColumn<double>("maxX");
        QTest::addColumn<double>("maxY");
        // rotate(90 5 0) turns the 10x5 rect to x in [0, 5], y in [-5, 5]; scale(2); translate(10 0).
        QTest::newRow("nested, rotate about a centre")
            << u"<g transform='translate(10 0)'><g transform='scale(2)'>"
               "<rect width='10' height='5' transform='rotate(90 5 0)'/></g></g>"_s
            << 0.02 << 0.1 << -0.1 << 0.2 << 0.1;
        QTest::newRow("list applies right to left")
            << u"<rect width='10' height='5' transform='translate(10,0) scale(2) rotate(90,5,0)'/>"_s
            << 0.02 << 0.1 << -0.1 << 0.2 << 0.1;
        QTest::newRow("matrix") << u"<rect width='10' height='10' transform='matrix(2 0 0 3 5 5)'/>"_s
                                << 0.06 << 0.05 << 0.05 << 0.25 << 0.35;
        QTest::newRow("skewX") << u"<rect width='10' height='10' transform='skewX(45)'/>"_s << 0.01 << 0.0 << 0.0 << 0.2 << 0.1;
        QTest::newRow("skewY") << u"<rect width='10' height='10' transform='skewY(45)'/>"_s << 0.01 << 0.0 << 0.0 << 0.1 << 0.2;
        QTest::newRow("scale one number") << u"<circle r='5' transform='translate(50 50) scale(3)'/>"_s
                                          << kPi * 0.0225 << 0.35 << 0.35 << 0.65 << 0.65;
        QTest::newRow("non-uniform scale of a circle")
            << u"<g transform='translate(50,50)'><circle r='10' transform='scale(2 .5)'/></g>"_s
            << kPi * 0.01 << 0.3 << 0.45 << 0.7 << 0.55;
    }
    void transforms()
    {
        QFETCH(QString, body);
        const SvgImport result = importBody(body, 0.004);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(result.shapes.size(), std::size_t(1));
        verifyWellFormed(result.shapes.front(), 0.004);
        QFETCH(double, area);
        QVERIFY2(std::abs(filledArea(result.shapes.front()) - area) <= 0.01 * area, qPrintable(QString::number(filledArea(result.shapes.front()))));
        const Box box = bounds(result.shapes.front());
        QFETCH(double, minX);
        QFETCH(double, minY);
        QFETCH(double, maxX);
        QFETCH(double, maxY);
        QVERIFY2(glm::distance(box.min, Vec2(minX, minY)) < kCurveBoundsTolerance, qPrintable(u"%1 %2"_s.arg(box.min.x).arg(box.min.y)));
        QVERIFY2(glm::distance(box.max, Vec2(maxX, maxY)) < kCurveBoundsTolerance, qPrintable(u"%1 %2"_s.arg(box.max.x).arg(box.max.y)));
    }

    void viewBoxFitsAndCentres_data()
    {
        QTest::addColumn<QString>("root");
        QTest::addColumn<QString>("rect");
        QTest::newRow("viewBox") << u"viewBox='0 0 200 100'"_s << u"x='0' y='0'"_s;
        QTest::newRow("viewBox with origin") << u"viewBox='-100,-50,200,100' width='9cm'"_s << u"x='-100' y='-50'"_s;
        QTest::newRow("width and height") << u"width='200' height='100px'"_s << u"x='0' y='0'"_s;
    }
    void viewBoxFitsAndCentres()
    {
        // A rect filling a 2:1 document fills the unit canvas's width, centred vertically.
        QFETCH(QString, root);
        QFETCH(QString, rect);
        const SvgImport result = importBody(u"<rect %1 width='200' height='100'/>"_s.arg(rect), 0.01, root);
        QVERIFY2(result.ok(), qPrintable(result.error));
        const Box box = bounds(result.shapes.front());
        QVERIFY(glm::distance(box.min, Vec2(0.0, 0.25)) < 1e-12);
        QVERIFY(glm::distance(box.max, Vec2(1.0, 0.75)) < 1e-12);

        // On a tall canvas the same document is centred horizontally at the canvas's width.
        const QString svg = u"<svg xmlns='http://www.w3.org/2000/svg' %1><rect %2 width='200' height='100'/></svg>"_s.arg(root, rect);
        const SvgImport tall = importSvg(svg.toUtf8(), u"test.svg"_s, 2.0, 4.0, 0.01);
        QVERIFY2(tall.ok(), qPrintable(tall.error));
        const Box tallBox = bounds(tall.shapes.front());
        QVERIFY(glm::distance(tallBox.min, Vec2(0.0, 1.5)) < 1e-12);
        QVERIFY(glm::distance(tallBox.max, Vec2(2.0, 2.5)) < 1e-12);
    }

    void colours_data()
    {
        QTest::addColumn<QString>("body");
        QTest::addColumn<QColor>("expected");
        const QString shape = u"<rect width='10' height='10' %1/>"_s;
        QTest::newRow("default black") << shape.arg(QString()) << QColor(0, 0, 0);
        QTest::newRow("name") << shape.arg(u"fill='teal'"_s) << QColor(0, 0x80, 0x80);
        QTest::newRow("#rgb") << shape.arg(u"fill='#0f8'"_s) << QColor(0x00, 0xff, 0x88);
        QTest::newRow("#rrggbb") << shape.arg(u"fill='#123456'"_s) << QColor(0x12, 0x34, 0x56);
        QTest::newRow("rgb()") << shape.arg(u"fill='rgb(10, 20,30)'"_s) << QColor(10, 20, 30);
        QTest::newRow("rgb() percent") << shape.arg(u"fill='rgb(100%,0%,50%)'"_s) << QColor(255, 0, 128);
        QTest::newRow("style wins") << shape.arg(u"fill='red' style='stroke:blue; fill: #00ff00'"_s) << QColor(0, 255, 0);
        QTest::newRow("inherited") << u"<g fill='#abcdef'><g>"_s + shape.arg(QString()) + u"</g></g>"_s << QColor(0xab, 0xcd, 0xef);
        QTest::newRow("own beats inherited") << u"<g style='fill:red'>"_s + shape.arg(u"fill='blue'"_s) + u"</g>"_s << QColor(0, 0, 255);
        QTest::newRow("currentColor") << u"<g color='#102030'>"_s + shape.arg(u"fill='currentColor'"_s) + u"</g>"_s << QColor(0x10, 0x20, 0x30);
        QTest::newRow("fill-opacity") << shape.arg(u"fill='red' fill-opacity='0.5'"_s) << QColor(255, 0, 0, 128);
        QTest::newRow("opacities multiply") << u"<g opacity='0.5' fill-opacity='0.5'>"_s + shape.arg(u"fill='red'"_s) + u"</g>"_s
                                            << QColor(255, 0, 0, 64);
        QTest::newRow("gradient fallback") << shape.arg(u"fill='url(#g) #00f'"_s) << QColor(0, 0, 255);
    }
    void colours()
    {
        QFETCH(QString, body);
        QFETCH(QColor, expected);
        const SvgImport result = importBody(body);
        QVERIFY2(result.ok(), qPrintable(result.error));
        const QColor color = result.shapes.front().color;
        QCOMPARE(color.rgb(), expected.rgb());
        QVERIFY2(std::abs(color.alpha() - expected.alpha()) <= 1, qPrintable(QString::number(color.alpha())));
    }

    void holeIsOneShapeWithTwoContours()
    {
        // The inner square runs the other way, as drawing tools write holes; both come out positive.
        const SvgImport result = importBody(u"<path id='frame' d='M10 10 H90 V90 H10 Z M30 30 V70 H70 V30 Z'/>"_s);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(result.shapes.size(), std::size_t(1));
        const ImportedShape& shape = result.shapes.front();
        QCOMPARE(shape.name, u"frame"_s);
        QCOMPARE(shape.contours.size(), std::size_t(2));
        verifyWellFormed(shape, 0.01);
        QVERIFY(std::abs(filledArea(shape) - (0.64 - 0.16)) < 1e-12);
    }

    void nonzeroHolesDrawnSameWayWarned()
    {
        // Both squares clockwise: nonzero fills the inner one, even-odd (regions) makes it a hole.
        const QString d = u"M10 10 H90 V90 H10 Z M30 30 H70 V70 H30 Z"_s;
        const SvgImport nonzero = importBody(u"<path id='p' d='%1'/>"_s.arg(d));
        QVERIFY2(nonzero.ok(), qPrintable(nonzero.error));
        QCOMPARE(nonzero.warnings.size(), 1);
        QVERIFY2(nonzero.warnings.front().contains(u"path \"p\": a hole drawn the same way round"_s), qPrintable(nonzero.warnings.front()));
        QVERIFY(importBody(u"<g fill-rule='evenodd'><path d='%1'/></g>"_s.arg(d)).warnings.isEmpty());
        // Drawn the other way round, the hole is a hole under both rules.
        QVERIFY(importBody(u"<path d='M10 10 H90 V90 H10 Z M30 30 V70 H70 V30 Z'/>"_s).warnings.isEmpty());
    }

    void degenerateSubpathsDropped()
    {
        // A subpath that doubles back on itself, one of two points, and a lone moveto.
        const SvgImport result = importBody(u"<path d='M10 10 H90 V90 Z M5 5 L50 5 L20 5 Z M1 1 L2 2 Z M7 7'/>"_s);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(result.shapes.front().contours.size(), std::size_t(1));
        verifyWellFormed(result.shapes.front(), 0.01);
    }

    // Radii at the edges of double: far below the chord the arc is scaled up to reach (F.6.6);
    // far above it, or scaled past what a double holds, it is a straight line (as zero radii are,
    // F.6.2); an ellipse scaled past any size the canvas can hold is refused.
    void arcRadiiAtTheEdgesOfDouble_data()
    {
        QTest::addColumn<QString>("radii");
        QTest::addColumn<double>("bulge");  // of the arc above the edge; NaN: refused
        QTest::newRow("1e-300") << u"1e-300 1e-300"_s << 0.1;
        QTest::newRow("denormal") << u"4e-320 4e-320"_s << 0.1;
        QTest::newRow("1e300") << u"1e300 1e300"_s << 0.0;
        QTest::newRow("1e308 by 1e-308") << u"1e308 1e-308"_s << 0.0;
        QTest::newRow("1e-300 by 1") << u"1e-300 1"_s << std::nan("");
        QTest::newRow("1e-308 by 1e300") << u"1e-308 1e300"_s << 0.0;
    }
    void arcRadiiAtTheEdgesOfDouble()
    {
        QFETCH(QString, radii);
        QFETCH(double, bulge);
        // A square's top edge (40, 20)–(60, 20) replaced by an arc that bulges out of the square.
        const SvgImport result = importBody(u"<path id='arc' d='M40 20 a"_s + radii + u" 0 0 1 20 0 V60 H40 Z'/>"_s);
        if (std::isnan(bulge)) {
            verifyOneLineError(result, u"shape \"arc\" would need more than"_s);
            return;
        }
        QVERIFY2(result.ok(), qPrintable(result.error));
        verifyWellFormed(result.shapes.front(), 0.01);
        const Box box = bounds(result.shapes.front());
        QVERIFY(std::abs(box.min.x - 0.4) < 1e-9 && std::abs(box.max.x - 0.6) < 1e-9);
        QVERIFY(std::abs(box.max.y - 0.6) < 1e-9);
        QVERIFY2(std::abs(box.min.y - (0.2 - bulge)) < kCurveBoundsTolerance, qPrintable(QString::number(box.min.y)));
    }

    void crossingShapesRefused_data()
    {
        QTest::addColumn<QString>("body");
        QTest::addColumn<QString>("expected");
        QTest::newRow("bow tie") << u"<path id='star' d='M10 10 L90 90 L90 10 L10 90 Z'/>"_s << u"shape \"star\" crosses itself"_s;
        QTest::newRow("overlapping subpaths") << u"<path d='M10 10 H60 V60 H10 Z M40 40 H90 V90 H40 Z'/>"_s
                                              << u"shape \"path 1\" crosses itself"_s;
        QTest::newRow("pinched polygon") << u"<polygon id='eight' points='10 10 50 50 90 10 90 90 50 50 10 90'/>"_s
                                         << u"shape \"eight\" crosses itself"_s;
    }
    void crossingShapesRefused()
    {
        QFETCH(QString, body);
        QFETCH(QString, expected);
        verifyOneLineError(importBody(body), expected);
    }

    // What fuzzing finds slowly or not at all (docs/fuzzing.md): each input is imported or refused
    // with one line, never a crash, a hang or an exception.
    void hostileInput_data()
    {
        QTest::addColumn<QByteArray>("svg");
        QTest::addColumn<QString>("expected");  // empty: imported
        const auto wrap = [](const QByteArray& body, const QByteArray& root = "viewBox='0 0 100 100'") {
            return "<svg xmlns='http://www.w3.org/2000/svg' " + root + ">" + body + "</svg>";
        };
        // An arc whose radii are far too small to reach its end is scaled up to a half ellipse.
        QTest::newRow("arc radii 1e-300") << wrap("<path d='M0 0 a1e-300 1e-300 0 1 1 10 10z'/>") << QString();
        QTest::newRow("arc radii denormal") << wrap("<path d='M0 0 a4.9e-324 4.9e-324 30 1 1 10 10z'/>") << QString();
        // Their ratio, 5e-14, is kept: an ellipse far too long to flatten.
        QTest::newRow("arc radii denormal and tiny") << wrap("<path d='M0 0 a4.9e-324 1e-310 30 1 1 10 10z'/>") << u"would need more than"_s;
        QTest::newRow("arc radii 1e308") << wrap("<path d='M0 0 h10 a1e308 1e308 0 0 1 -10 10z'/>") << QString();
        QTest::newRow("coordinates 1e308") << wrap("<rect width='1e308' height='1e308'/>") << u"would need more than"_s;
        QTest::newRow("coordinates -1e308") << wrap("<path d='M-1e308 0 L1e308 0 L0 1e308z'/>") << u"would need more than"_s;
        QTest::newRow("coordinates 1e-308") << wrap("<rect x='1e-308' width='1e-308' height='1e-308'/>") << u"nothing to import"_s;
        QTest::newRow("overflowing number") << wrap("<rect width='1e309' height='5'/>") << u"width"_s;
        QTest::newRow("inf text") << wrap("<rect width='inf' height='5'/>") << u"width"_s;
        QTest::newRow("nan text") << wrap("<path d='M0 0 L nan 5 L5 5z'/>") << u"bad path data"_s;
        QTest::newRow("denormal viewBox") << wrap("<rect width='5' height='5'/>", "viewBox='0 0 4.9e-324 4.9e-324'")
                                          << u"would need more than"_s;
        QTest::newRow("huge viewBox") << wrap("<rect width='1e300' height='1e300'/>", "viewBox='0 0 1e308 1e308'") << QString();
        QTest::newRow("scale(0)") << wrap("<rect width='5' height='5' transform='scale(0)'/>") << u"nothing to import"_s;
        QTest::newRow("scale(0 1)") << wrap("<rect width='5' height='5' transform='scale(0 1)'/>") << u"nothing to import"_s;
        QTest::newRow("zero matrix") << wrap("<g transform='matrix(0 0 0 0 0 0)'><circle r='5'/></g>") << u"nothing to import"_s;
        QTest::newRow("scale 1e308 twice") << wrap("<g transform='scale(1e308)'><rect width='5' height='5' transform='scale(1e308)'/></g>")
                                           << u"would need more than"_s;
        QTest::newRow("scale 1e-308 twice") << wrap("<g transform='scale(1e-308)'><rect width='5' height='5' transform='scale(1e-308)'/></g>")
                                            << u"nothing to import"_s;
        // Entities: Qt stops expanding at its limit, so a billion laughs is refused, not expanded.
        QByteArray laughs = "<?xml version='1.0'?><!DOCTYPE svg [<!ENTITY l0 'M0 0h1v1h-1z'>";
        for (int i = 1; i <= 9; ++i)
            laughs += QByteArray("<!ENTITY l%1 '").replace("%1", QByteArray::number(i)) +
                      QByteArray("&l%1;").replace("%1", QByteArray::number(i - 1)).repeated(10) + "'>";
        QTest::newRow("billion laughs") << laughs + "]>" + wrap("<path d='&l9;'/>") << u"not well-formed XML"_s;
        QTest::newRow("entity loop") << "<!DOCTYPE svg [<!ENTITY a '&b;'><!ENTITY b '&a;'>]>" + wrap("<path d='&a;'/>")
                                     << u"not well-formed XML"_s;
        // References are never followed (docs/svg-import.md), so one that loops is skipped.
        QTest::newRow("use referring to itself") << wrap("<use id='u' href='#u'/><rect width='5' height='5'/>") << QString();
        QTest::newRow("fill referring to itself") << wrap("<linearGradient id='g' href='#g'/><rect width='5' height='5' fill='url(#g)'/>")
                                                  << QString();
        // Found by fuzzing (docs/fuzzing.md).
        QTest::newRow("url without parenthesis") << wrap("<rect width='5' height='5' fill='url(#e76f51'/>") << QString();
        QTest::newRow("long thin path") << wrap("<path d='M110,10 C130,0 0,1050 170,10 S190,40 170,601005Q9 , 170,3 0T110,10 Z'/>",
                                                "width='200' height='100'")
                                        << QString();
        QTest::newRow("deep groups") << wrap(QByteArray("<g>").repeated(100'000) + "<rect width='5' height='5'/>" +
                                             QByteArray("</g>").repeated(100'000))
                                     << u"nested deeper than"_s;
        QTest::newRow("deep unknown elements") << wrap(QByteArray("<x>").repeated(100'000) + QByteArray("</x>").repeated(100'000))
                                               << u"nothing to import"_s;
    }
    void hostileInput()
    {
        QFETCH(QByteArray, svg);
        QFETCH(QString, expected);
        const SvgImport result = importSvg(svg, u"test.svg"_s, 1.0, 1.0, 0.01);
        if (!expected.isEmpty()) {
            verifyOneLineError(result, expected);
            return;
        }
        QVERIFY2(result.ok(), qPrintable(result.error));
        for (const ImportedShape& shape : result.shapes)
            verifyWellFormed(shape, 0.01);
    }

    // Contours lying on one another are refused at their first contact: the time grows with the
    // segments, not with their pairs (tests/model/CMakeLists.txt gives this test a time limit).
    void coincidentSegmentsRefusedQuickly_data()
    {
        QTest::addColumn<QString>("d");
        constexpr int kRepeats = 100'000;
        QTest::newRow("one closed curve, repeated") << u"M0,0 C1,2 3,4 5,6"_s.repeated(kRepeats);
        QTest::newRow("one square, repeated") << u"M0 0h1v1h-1z"_s.repeated(kRepeats);
        QTest::newRow("one loop, repeated") << u"M0,0 C1,2 3,4 5,6 C1,2 3,4 5,6"_s + u" C1,2 3,4 5,6"_s.repeated(kRepeats);
        QTest::newRow("one triangle, repeated") << u"M0 0"_s + u" L10 0 L0 10 L0 0"_s.repeated(kRepeats) + u"z"_s;
    }
    void coincidentSegmentsRefusedQuickly()
    {
        QFETCH(QString, d);
        // Small in the canvas, so that 100,000 copies stay within the vertex limit.
        verifyOneLineError(importBody(u"<path id='p' d='%1'/>"_s.arg(d), 0.01, u"viewBox=\"0 0 1000 1000\""_s), u"shape \"p\" crosses itself"_s);
    }

    // 1,000 squares nested a millionth apart (400,000 vertices): every edge has a thousand others
    // within a grid cell, and every contour lies inside the others' bounding boxes.
    void nestedContoursImportInSeconds()
    {
        QString d;
        for (int k = 0; k < 1000; ++k) {
            const double lo = 0.1 + k * 1e-6, hi = 0.9 - k * 1e-6;
            // Alternate ways round, as drawing tools write holes: nonzero and even-odd agree.
            const QString path = k % 2 == 0 ? u"M%1 %1 H%2 V%2 H%1 Z "_s : u"M%1 %1 V%2 H%2 V%1 Z "_s;
            d += path.arg(lo, 0, 'g', 17).arg(hi, 0, 'g', 17);
        }
        const SvgImport result = importBody(u"<path d='%1'/>"_s.arg(d), 0.01, u"viewBox=\"0 0 1 1\""_s);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(result.shapes.front().contours.size(), std::size_t(1000));
        QVERIFY2(result.warnings.join(u'\n').contains(u"too many nested contours to tell"_s), qPrintable(result.warnings.join(u'\n')));
    }

    void overlappingElementsAreSeparateShapes()
    {
        const SvgImport result = importBody(u"<rect width='60' height='60'/><rect x='30' y='30' width='60' height='60'/>"_s);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(result.shapes.size(), std::size_t(2));
    }

    void badInput_data()
    {
        QTest::addColumn<QByteArray>("svg");
        QTest::addColumn<QString>("expected");
        const auto wrap = [](const char* body) {
            return QByteArray("<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 10 10'>") + body + "</svg>";
        };
        QTest::newRow("empty") << QByteArray(" \n") << u"empty file"_s;
        QTest::newRow("not XML") << QByteArray("\x89PNG\r\n\x1a\n") << u"not well-formed XML"_s;
        QTest::newRow("unclosed tag") << QByteArray("<svg viewBox='0 0 10 10'>\n  <rect width='5' height='5'>\n</svg>")
                                      << u"test.svg: 3:"_s;
        QTest::newRow("other root") << QByteArray("<html><rect width='5' height='5'/></html>") << u"root element is <html>"_s;
        QTest::newRow("no size") << QByteArray("<svg><rect width='5' height='5'/></svg>") << u"neither a viewBox nor"_s;
        QTest::newRow("bad viewBox") << QByteArray("<svg viewBox='0 0 -1 10'><rect width='5' height='5'/></svg>") << u"viewBox"_s;
        QTest::newRow("units") << QByteArray("<svg width='10cm' height='5cm'><rect width='5' height='5'/></svg>") << u"\"10cm\""_s;
        QTest::newRow("bad path data") << wrap("<path id='logo' d='M 1 1 L 5 1 L 5 x'/>") << u"path \"logo\": bad path data"_s;
        QTest::newRow("bad path quotes text") << wrap("<path id='logo' d='M 1 1 L 5 1 L 5 x'/>") << u"\"x\""_s;
        QTest::newRow("path without moveto") << wrap("<path d='L 5 5 10 10'/>") << u"path \"path 1\": bad path data: path data must start with a moveto"_s;
        QTest::newRow("numbers after Z") << wrap("<path d='M1 1 H5 V5 Z 3 3'/>") << u"expected a command"_s;
        QTest::newRow("bad arc flag") << wrap("<path d='M1 1 A 2 2 0 2 1 5 5'/>") << u"bad arguments to 'A'"_s;
        QTest::newRow("odd points") << wrap("<polygon id='tri' points='1 1 5 1 5'/>") << u"polygon \"tri\""_s;
        QTest::newRow("bad transform") << wrap("<rect width='5' height='5' transform='spin(3)'/>") << u"transform"_s;
        QTest::newRow("bad length") << wrap("<rect width='5em' height='5'/>") << u"width"_s;
        QTest::newRow("nothing") << wrap("<polyline points='1 1 5 5 1 5'/>") << u"nothing to import"_s;
        QTest::newRow("only unfilled") << wrap("<rect width='5' height='5' fill='none'/>") << u"nothing to import"_s;
    }
    void badInput()
    {
        QFETCH(QByteArray, svg);
        QFETCH(QString, expected);
        verifyOneLineError(importSvg(svg, u"test.svg"_s, 1.0, 1.0, 0.01), expected);
    }

    void skippedElementsWarned()
    {
        const SvgImport result = importBody(
            u"<defs><rect id='hidden' width='5' height='5'/></defs>"
            "<clipPath><circle r='5'/></clipPath><symbol><rect width='5' height='5'/></symbol>"
            "<polyline points='1 1 5 5 1 5'/><line x2='5' y2='5'/><polyline points='1 1 5 5 1 5'/>"
            "<use href='#hidden'/><text>hi</text><rect width='5' height='5' fill='none'/>"
            "<rect width='5' height='5' display='none'/><title>a title</title>"
            "<rect id='kept' x='50' width='5' height='5'/>"_s);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(result.shapes.size(), std::size_t(1));
        QCOMPARE(result.shapes.front().name, u"kept"_s);
        const QString warnings = result.warnings.join(u'\n');
        QVERIFY2(warnings.contains(u"skipped 2 × <polyline>"_s), qPrintable(warnings));
        QVERIFY2(warnings.contains(u"skipped 1 × <line>"_s), qPrintable(warnings));
        QVERIFY2(warnings.contains(u"<use>"_s), qPrintable(warnings));
        QVERIFY2(warnings.contains(u"<text>"_s), qPrintable(warnings));
        QVERIFY2(warnings.contains(u"<rect> with fill=\"none\""_s), qPrintable(warnings));
        QVERIFY2(!warnings.contains(u"title"_s) && !warnings.contains(u"defs"_s), qPrintable(warnings));
        for (const QString& warning : result.warnings)
            QVERIFY2(warning.startsWith(u"test.svg: "_s), qPrintable(warning));
    }

    void longPathImportsFully()
    {
        // 100,000 line segments: QtSvg would stop at 32,767 path elements.
        constexpr int kSegments = 100'000;
        QString d = u"M90 50"_s;
        for (int i = 1; i < kSegments; ++i) {
            const double a = 2.0 * kPi * i / kSegments;
            d += u" L%1 %2"_s.arg(50.0 + 40.0 * std::cos(a), 0, 'g', 17).arg(50.0 + 40.0 * std::sin(a), 0, 'g', 17);
        }
        const SvgImport result = importBody(u"<path d='%1Z'/>"_s.arg(d), 0.01);
        QVERIFY2(result.ok(), qPrintable(result.error));
        const sim::Polygon& contour = result.shapes.front().contours.front();
        QCOMPARE(contour.size(), std::size_t(kSegments));
        QVERIFY(std::abs(sim::signedArea(contour) - kPi * 0.16) < 1e-6);
        verifyWellFormed(result.shapes.front(), 0.01);
    }

    void fromFile()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(u"logo.svg"_s);
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 10 10'><path id='star' d='M1 1 L9 9 L9 1 L1 9 Z'/></svg>");
        file.close();
        const SvgImport result = importSvgFile(path, 1.0, 1.0, 0.01);
        QVERIFY2(result.error.startsWith(u"logo.svg: 1:"_s), qPrintable(result.error));
        QVERIFY2(result.error.endsWith(u": shape \"star\" crosses itself"_s), qPrintable(result.error));

        const SvgImport missing = importSvgFile(dir.filePath(u"missing.svg"_s), 1.0, 1.0, 0.01);
        QVERIFY(missing.error.startsWith(u"missing.svg: "_s));
    }
};

QTEST_GUILESS_MAIN(TestSvgImport)
#include "tst_svgimport.moc"
