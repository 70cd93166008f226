// Contour surgery (sim/Pinches): a layer of ink thinner than positions resolve is cut, one that
// they resolve is left alone, and the cut contours stay simple and keep their ink; a layer between
// two contours that thin is widened instead.
#include "Backends.h"
#include "sim/Crossings.h"
#include "sim/Pinches.h"
#include "sim/Separation.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cfloat>
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

// The least distance from a vertex of one of the contours to an edge of the other.
double gapBetween(const Polygon& a, const Polygon& b)
{
    double gap = INFINITY;
    for (const auto& [from, to] : {std::pair{&a, &b}, std::pair{&b, &a}})
        for (Vec2 p : *from)
            for (std::size_t j = 0; j < to->size(); ++j)
                gap = std::min(gap, std::sqrt(sim::squaredDistanceToSegment(p, (*to)[j], (*to)[(j + 1) % to->size()])));
    return gap;
}

// A simulation in still water holding the dumbbell with a neck 1e-7 thick.
std::unique_ptr<sim::Simulation> dumbbellInStillWater(const QString& backend)
{
    sim::SimulationSettings settings;
    settings.flow = sim::SimulationSettings::FlowType::Analytic;
    settings.tracking.maxSpacing = spacing;
    auto simulation = test::makeBackend(backend, settings);
    simulation->addRegion({dumbbell(1e-7)});
    return simulation;
}

// The pinch width where the largest coordinate is `largest`.
double pinchWidth(double largest)
{
    return sim::pinchSpacings * double(FLT_EPSILON) * largest;
}

} // namespace

class TestPinches : public QObject {
    Q_OBJECT

    // Kept from test to test, as a simulation keeps it from check to check.
    sim::EdgeGrid::Storage grid;

private slots:
    void tongueThinnerThanFloatsIsCutAtItsRoot()
    {
        const Contour original = tracked(squareWithTongue(1e-7));
        std::vector<Contour> contours{original};
        QVERIFY(sim::cutPinches(contours, grid) >= 1);
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
        QVERIFY(sim::cutPinches(contours, grid) >= 1);
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
        QCOMPARE(sim::cutPinches(contours, grid), std::size_t(0));
        QVERIFY(contours == before);
    }

    // Two inks a hair apart: each side moves off the other by what the width asks, no farther, and
    // a layer positions resolve is left as it is.
    void twoContourLayerIsWidened()
    {
        const Polygon below = outline({{0.1, 0.7}, {0.5, 0.7}, {0.5, 0.8}, {0.1, 0.8}});
        const Polygon above = outline({{0.1, 0.8 + 1e-7}, {0.5, 0.8 + 1e-7}, {0.5, 0.9}, {0.1, 0.9}});
        std::vector<Contour> contours{tracked(below, 0), tracked(above, 1)};
        const std::size_t touching = std::count_if(above.begin(), above.end(), [](Vec2 p) { return p.y < 0.81; });
        QCOMPARE(sim::separateLayers(contours), 2 * touching);
        const double width = pinchWidth(0.9);
        QVERIFY2(gapBetween(contours[0].positions, contours[1].positions) >= width,
                 qPrintable(QString::number(gapBetween(contours[0].positions, contours[1].positions))));
        QCOMPARE(crossings(contours), std::size_t(0));
        for (const auto& [moved, original] : {std::pair{&contours[0], &below}, std::pair{&contours[1], &above}})
            for (std::size_t i = 0; i < original->size(); ++i)
                QVERIFY(glm::distance(moved->positions[i], (*original)[i]) <= width);

        std::vector<Contour> apart{tracked(below, 0), tracked(outline({{0.1, 0.8001}, {0.5, 0.8001}, {0.5, 0.9}, {0.1, 0.9}}), 1)};
        const std::vector<Contour> before = apart;
        QCOMPARE(sim::separateLayers(apart), std::size_t(0));
        QVERIFY(apart == before);
    }

    // Nested inks (drops within drops) stacked at the top, 2.4e-6, 4.7e-6 and 2.4e-6 apart, each
    // within the width (6.9e-6 here) of its neighbours only: each middle side is pushed off its
    // nearer neighbour toward the other middle side, and the two pushes made whole would leave
    // 1e-7 between them. No layer ends thinner than the thinnest was, and the outer two widen.
    void stackedLayersAreNotPressedThinner()
    {
        const double tops[] = {0.9, 0.9 - 2.4e-6, 0.9 - 7.1e-6, 0.9 - 9.5e-6};
        std::vector<Contour> contours;
        for (int k = 0; k < 4; ++k) {
            const double in = 0.1 * k;
            contours.push_back(tracked(outline({{0.1 + in, 0.1 + in}, {0.8 - in, 0.1 + in}, {0.8 - in, tops[k]}, {0.1 + in, tops[k]}}), k));
        }
        QVERIFY(sim::separateLayers(contours) > 0);
        QCOMPARE(crossings(contours), std::size_t(0));
        double gaps[3];
        for (int k = 0; k < 3; ++k)
            gaps[k] = gapBetween(contours[k].positions, contours[k + 1].positions);
        const QByteArray shown = QStringLiteral("%1 %2 %3").arg(gaps[0]).arg(gaps[1]).arg(gaps[2]).toLatin1();
        QVERIFY2(gaps[1] >= 2.4e-6 * (1.0 - 1e-9), shown.constData());
        QVERIFY2(gaps[0] > 4e-6 && gaps[2] > 4e-6, shown.constData());
    }

    // Moves meant for a device go where a float pair lies, so that what was checked is what the
    // device keeps (an optimiser once dropped the rounding, and the device's contours then crossed).
    void singlePrecisionMovesLandOnFloats()
    {
        const double third = 1.0 / 3.0;  // no float holds it, nor anything moved off it by a width
        const Polygon below = outline({{0.1, third - 0.1}, {0.5, third - 0.1}, {0.5, third}, {0.1, third}});
        const Polygon above = outline({{0.1, third + 1e-7}, {0.5, third + 1e-7}, {0.5, 0.9}, {0.1, 0.9}});
        const std::vector<Contour> contours{tracked(below, 0), tracked(above, 1)};
        const std::vector<sim::VertexMove> moves = sim::findSeparations(sim::outlinesOf(contours), true);
        QVERIFY(!moves.empty());
        for (const sim::VertexMove& m : moves)
            QVERIFY2(double(float(m.to.x)) == m.to.x && double(float(m.to.y)) == m.to.y,
                     qPrintable(QStringLiteral("(%1, %2)").arg(m.to.x, 0, 'g', 17).arg(m.to.y, 0, 'g', 17)));
    }

    // A drop landing 1e-4 from ink's edge pushes it to about 1e-7 outside its rim (ρ²/2r); both
    // backends leave the width between them instead, with no crossing.
    void dropBesideInkLeavesTheWidth_data() { test::addBackendRows(); }
    void dropBesideInkLeavesTheWidth()
    {
        QFETCH(QString, backend);
        VF_REQUIRE_BACKEND(backend);
        sim::SimulationSettings settings;
        settings.flow = sim::SimulationSettings::FlowType::Analytic;
        settings.tracking.maxSpacing = 0.004;
        auto simulation = test::makeBackend(backend, settings);
        simulation->addRegion({sim::resample({{0.3, 0.2}, {0.7, 0.2}, {0.7, 0.5 - 1e-4}, {0.3, 0.5 - 1e-4}}, 0.004)});
        simulation->drop({0.5, 0.5}, 0.05);
        const std::vector<Contour> contours = simulation->contours();
        QCOMPARE(contours.size(), std::size_t(2));
        QCOMPARE(crossings(contours), std::size_t(0));
        const double gap = gapBetween(contours[0].positions, contours[1].positions);
        QVERIFY2(gap >= 0.99 * pinchWidth(0.55), qPrintable(QString::number(gap)));
    }

    // The search shares the vertices of all contours among threads once there are enough of them:
    // a dozen necked shapes of 8,000 vertices each are cut exactly as each alone, searched on one
    // thread, is (on a machine with one hardware thread, both searches take one).
    void manyContoursAreCutAsEachAlone()
    {
        std::vector<Polygon> shapes;
        for (int k = 0; k < 12; ++k) {
            const Vec2 offset(0.3 * (k % 4), 0.3 * (k / 4));
            Polygon shape = sim::resample(dumbbell(k % 3 == 0 ? 1e-4 : 1e-7), 2.3e-4);
            for (Vec2& p : shape)
                p = offset + 0.3 * p;
            shapes.push_back(std::move(shape));
        }
        std::vector<sim::Outline> all(shapes.begin(), shapes.end());
        QVERIFY(shapes[0].size() > 7000 && shapes[0].size() < 32768 / 2);
        const std::vector<sim::ContourCut> together = sim::findCuts(all, grid);
        QCOMPARE(together.size(), std::size_t(8));  // the necks of 1e-7, not those of 1e-4
        std::size_t next = 0;
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            const std::vector<sim::ContourCut> alone = sim::findCuts({sim::Outline(shapes[k])}, grid);
            if (alone.empty())
                continue;
            QVERIFY(next < together.size());
            const sim::ContourCut& cut = together[next++];
            QCOMPARE(cut.contour, k);
            QCOMPARE(cut.cuts, alone[0].cuts);
            QCOMPARE(cut.kept.size(), alone[0].kept.size());
            for (std::size_t i = 0; i < cut.kept.size(); ++i) {
                QVERIFY(cut.kept[i].vertices == alone[0].kept[i].vertices);
                QCOMPARE(cut.kept[i].area, alone[0].kept[i].area);
            }
        }
        QCOMPARE(next, together.size());
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
        const auto simulation = dumbbellInStillWater(backend);
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

    // A drop's push can press a layer of one contour within a float spacing, and the refinement
    // after it must not start there: such a neck is cut before it, not a check period later. (Here
    // the neck is there before the drop, which lands far from it.)
    void dropCutsBeforeRefining_data() { test::addBackendRows(); }
    void dropCutsBeforeRefining()
    {
        QFETCH(QString, backend);
        VF_REQUIRE_BACKEND(backend);
        const auto simulation = dumbbellInStillWater(backend);
        simulation->drop({0.5, 0.85}, 0.05);
        const std::vector<sim::Contour> contours = simulation->contours();
        QCOMPARE(contours.size(), std::size_t(3));  // the dumbbell's two squares and the drop
        QCOMPARE(crossings(contours), std::size_t(0));
        for (const Contour& c : contours)
            if (c.region == 0)
                QVERIFY(std::abs(sim::signedArea(c.positions) - 0.09) < 1e-5);
    }
};

QTEST_APPLESS_MAIN(TestPinches)
#include "tst_pinches.moc"
