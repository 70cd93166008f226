// Contour surgery (sim/Pinches): a layer of ink thinner than positions resolve is cut, one that
// they resolve is left alone, and the cut contours stay simple and keep their ink.
#include "Backends.h"
#include "sim/Crossings.h"
#include "sim/Pinches.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace vf;
using sim::Contour;
using sim::Polygon;
using sim::Vec2;

namespace {

constexpr double spacing = 0.01;

// A polygon through `corners`, its edges split to `spacing`, with positive area.
Polygon outline(Polygon corners)
{
    if (sim::signedArea(corners) < 0.0)
        std::reverse(corners.begin(), corners.end());
    return sim::resample(corners, spacing);
}

// The square [0.2, 0.6]² with a tongue `width` thick running from the middle of its right side to
// x = 0.9.
Polygon squareWithTongue(double width)
{
    const double low = 0.4 - width / 2, high = 0.4 + width / 2;
    return outline({{0.2, 0.2}, {0.6, 0.2}, {0.6, low}, {0.9, low}, {0.9, high}, {0.6, high}, {0.6, 0.6}, {0.2, 0.6}});
}

// Two squares 0.3 wide joined by a neck `width` thick and 0.1 long.
Polygon dumbbell(double width)
{
    const double low = 0.45 - width / 2, high = 0.45 + width / 2;
    return outline({{0.1, 0.3}, {0.4, 0.3}, {0.4, low}, {0.5, low}, {0.5, 0.3}, {0.8, 0.3}, {0.8, 0.6}, {0.5, 0.6},
                    {0.5, high}, {0.4, high}, {0.4, 0.6}, {0.1, 0.6}});
}

// A contour as the tracker keeps it: previous positions half a spacing off, spacing numbering the
// vertices, the area target its area.
Contour tracked(const Polygon& polygon, int region = 0)
{
    Contour c;
    c.region = region;
    c.positions = polygon;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        c.previous.push_back(polygon[i] + Vec2(spacing / 2));
        c.spacing.push_back(double(i));
    }
    c.targetArea = sim::signedArea(polygon);
    return c;
}

std::size_t crossings(const std::vector<Contour>& contours)
{
    std::vector<const Polygon*> polygons;
    for (const Contour& c : contours)
        polygons.push_back(&c.positions);
    return sim::countCrossings(polygons);
}

} // namespace

class TestPinches : public QObject {
    Q_OBJECT

private slots:
    void tongueThinnerThanFloatsIsCutAtItsRoot()
    {
        const Contour original = tracked(squareWithTongue(1e-7));
        std::vector<Contour> contours{original};
        QVERIFY(sim::cutPinches(contours) >= 1);
        QCOMPARE(contours.size(), std::size_t(1));
        const Contour& kept = contours[0];
        QCOMPARE(crossings(contours), std::size_t(0));
        QVERIFY(sim::isSimple(kept.positions));
        for (Vec2 p : kept.positions)
            QVERIFY2(p.x <= 0.6 + 1e-6, "a piece of the tongue is left");
        QVERIFY(std::abs(sim::signedArea(kept.positions) - 0.16) < 1e-6);
        QCOMPARE(kept.targetArea, original.targetArea);  // the ink cut off stays with the region
        // Every vertex kept carries its own previous position and spacing.
        QCOMPARE(kept.previous.size(), kept.positions.size());
        for (std::size_t i = 0; i < kept.positions.size(); ++i) {
            const auto k = std::size_t(kept.spacing[i]);
            QCOMPARE(kept.positions[i], original.positions[k]);
            QCOMPARE(kept.previous[i], original.previous[k]);
        }
    }

    void neckThinnerThanFloatsSplitsTheRegion()
    {
        const Contour original = tracked(dumbbell(1e-7));
        std::vector<Contour> contours{original};
        QVERIFY(sim::cutPinches(contours) >= 1);
        QCOMPARE(contours.size(), std::size_t(2));
        QCOMPARE(crossings(contours), std::size_t(0));
        double targets = 0.0;
        for (const Contour& c : contours) {
            QVERIFY(sim::isSimple(c.positions));
            QVERIFY(std::abs(sim::signedArea(c.positions) - 0.09) < 1e-6);
            QVERIFY(std::abs(c.targetArea - 0.09) < 1e-6);
            targets += c.targetArea;
        }
        QVERIFY(std::abs(targets - original.targetArea) < 1e-15);
    }

    // A layer positions resolve is ink a picture may show, and two contours are never joined or cut
    // however close: only a contour's own sides pinch.
    void resolvedLayersAndOtherContoursAreLeftAlone()
    {
        std::vector<Contour> contours{tracked(squareWithTongue(1e-5)), tracked(dumbbell(1e-5))};
        contours[1].positions = outline({{0.1, 0.7}, {0.5, 0.7}, {0.5, 0.8}, {0.1, 0.8}});
        Polygon touching = outline({{0.1, 0.8 + 1e-9}, {0.5, 0.8 + 1e-9}, {0.5, 0.9}, {0.1, 0.9}});
        contours[1] = tracked(contours[1].positions, 1);
        contours.push_back(tracked(touching, 2));
        const std::vector<Contour> before = contours;
        QCOMPARE(sim::cutPinches(contours), std::size_t(0));
        QVERIFY(contours == before);
    }

    void checksComeOnceAPeriod()
    {
        const double period = sim::pinchCheckPeriod;
        QVERIFY(!sim::pinchCheckDue(0.0, 0.4 * period));
        QVERIFY(sim::pinchCheckDue(0.4 * period, 1.2 * period));
        QVERIFY(!sim::pinchCheckDue(1.2 * period, 1.9 * period));
        QVERIFY(sim::pinchCheckDue(1.9 * period, 4.0 * period));
    }

    // Both backends cut a region's neck within a check period of stepping, and the steps go on.
    // (A thin tongue's tip would be eaten by refinement first, which removes needle tips.)
    void backendsCutWhileStepping_data() { test::addBackendRows(); }
    void backendsCutWhileStepping()
    {
        QFETCH(QString, backend);
        VF_REQUIRE_BACKEND(backend);
        sim::SimulationSettings settings;
        settings.flow = sim::SimulationSettings::FlowType::Analytic;
        settings.tracking.maxSpacing = spacing;
        auto simulation = test::makeBackend(backend, settings);
        simulation->addRegion({dumbbell(1e-7)});
        std::size_t cuts = 0;
        const double dt = 0.005;
        for (int k = 0; k * dt < 2 * sim::pinchCheckPeriod; ++k)
            cuts += simulation->step(dt).pinchesCut;
        QVERIFY(cuts >= 1);
        const std::vector<sim::Contour> contours = simulation->contours();
        QCOMPARE(contours.size(), std::size_t(2));
        QCOMPARE(crossings(contours), std::size_t(0));
        for (const Contour& c : contours)
            QVERIFY(std::abs(sim::signedArea(c.positions) - 0.09) < 1e-5);
        simulation->step(dt);
        QCOMPARE(simulation->contours().size(), std::size_t(2));
    }
};

QTEST_APPLESS_MAIN(TestPinches)
#include "tst_pinches.moc"
