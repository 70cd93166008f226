// The comb's exact map (sim/Comb) on every backend: it keeps every contour's area, the comb drawn
// back undoes it, and a long pattern of combs crosses no contours.
#include "Backends.h"
#include "sim/Comb.h"
#include "sim/Crossings.h"

#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace vf;
using sim::Comb;
using sim::Polygon;
using sim::Vec2;

namespace {

// Rows of touching-free drops, as a marbler starts: `rows` × `rows` circles in the unit square.
std::vector<Polygon> dropGrid(int rows, double spacing)
{
    std::vector<Polygon> drops;
    const double pitch = 1.0 / rows, radius = 0.4 * pitch;
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < rows; ++j)
            drops.push_back(sim::circle({(i + 0.5) * pitch, (j + 0.5) * pitch}, radius, spacing));
    return drops;
}

std::unique_ptr<sim::Simulation> stillWater(const QString& backend, bool areaCorrection = false)
{
    sim::SimulationSettings settings;
    settings.tracking.areaCorrection = areaCorrection;
    settings.flow = sim::SimulationSettings::FlowType::Analytic;  // at rest: only the combs move ink
    return test::makeBackend(backend, settings);
}

std::vector<Polygon> outlines(const sim::Simulation& simulation)
{
    std::vector<Polygon> out;
    for (sim::Contour& c : simulation.contours())
        out.push_back(std::move(c.positions));
    return out;
}

std::size_t crossings(const std::vector<Polygon>& polygons)
{
    std::vector<const Polygon*> pointers;
    for (const Polygon& p : polygons)
        pointers.push_back(&p);
    return sim::countCrossings(pointers);
}

// A pattern of twenty combs: straight passes across and along the tray with 3 to 7 tines, both
// ways, as gel-git and nonpareil are made (about 40k vertices at the end).
std::vector<Comb> twentyCombs()
{
    std::vector<Comb> combs;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 20; ++k) {
        const bool across = k % 2 == 0;
        const double at = 0.3 + 0.4 * unit(random), shift = 0.03 + 0.05 * unit(random);
        const double sign = (k / 2) % 2 == 0 ? 1.0 : -1.0;
        const Vec2 from = across ? Vec2(at, 0.5) : Vec2(0.5, at);
        const Vec2 to = from + sign * shift * (across ? Vec2(0.0, 1.0) : Vec2(1.0, 0.0));
        combs.push_back({from, to, 3 + k % 5, 0.12, 0.02 + 0.02 * unit(random)});
    }
    return combs;
}

} // namespace

class TestComb : public QObject {
    Q_OBJECT

private slots:
    void mapIsAnAreaPreservingShearUndoneByItsInverse()
    {
        const Comb comb{{0.2, 0.3}, {0.5, 0.7}, 5, 0.1, 0.02};
        const Vec2 along = glm::normalize(comb.to - comb.from);
        std::mt19937 random(3);
        std::uniform_real_distribution<double> unit(-1.0, 2.0);
        for (int k = 0; k < 1000; ++k) {
            const Vec2 p(unit(random), unit(random));
            const Vec2 q = comb(p);
            // It moves along the stroke only, and the inverse brings it back.
            QVERIFY(std::abs((q.x - p.x) * along.y - (q.y - p.y) * along.x) < 1e-12);
            QVERIFY(glm::distance(comb.inverse()(q), p) < 1e-12);
        }
        // Every point on a tine's line moves at least the stroke's length.
        QVERIFY(glm::distance(comb(comb.tineStart(2)), comb.tineStart(2)) >= 0.5 - 1e-12);
        // A comb of no length moves nothing.
        QCOMPARE(Comb({0.5, 0.5}, {0.5, 0.5}, 3, 0.1, 0.02)(Vec2(0.1, 0.2)), Vec2(0.1, 0.2));
    }

    // The map keeps areas exactly; the polygon keeps them as well as its chords follow the mapped
    // curve (the adaptive spacing: 2.5e-5 measured at the default d_max), and to rounding with area
    // correction on. Drawn back, the comb brings the ink back as far as the combed contour's chords
    // strayed from the mapped curve where the map bends it most, across the tines: 1.1e-3 to
    // 1.5e-3 measured (refinement bounds edge lengths, not how far a chord strays).
    void keepsAreasAndIsUndone_data()
    {
        test::addBackendColumn();
        QTest::addColumn<bool>("areaCorrection");
        QTest::addColumn<double>("areaTolerance");
        for (const QString& b : test::backendNames()) {
            QTest::newRow(qPrintable(b + u" default"_qs)) << b << false << 1e-4;
            QTest::newRow(qPrintable(b + u" area correction"_qs)) << b << true << 1e-6;
        }
    }
    void keepsAreasAndIsUndone()
    {
        QFETCH(QString, backend);
        QFETCH(bool, areaCorrection);
        QFETCH(double, areaTolerance);
        VF_REQUIRE_BACKEND(backend);
        auto simulation = stillWater(backend, areaCorrection);
        const double spacing = simulation->settings().tracking.maxSpacing;
        for (const Polygon& drop : dropGrid(4, spacing))
            simulation->addRegion({drop});
        const std::vector<Polygon> before = outlines(*simulation);
        const Comb comb{{0.1, 0.5}, {0.4, 0.5}, 4, 0.25, 0.03};
        QVERIFY(simulation->comb(comb));
        const std::vector<Polygon> combed = outlines(*simulation);
        QCOMPARE(combed.size(), before.size());
        double worstArea = 0.0, moved = 0.0;
        for (std::size_t c = 0; c < before.size(); ++c) {
            const double area = sim::signedArea(before[c]);
            worstArea = std::max(worstArea, std::abs(sim::signedArea(combed[c]) - area) / area);
            moved = std::max(moved, sim::hausdorffDistance(combed[c], before[c]));
        }
        QVERIFY2(moved > 0.1, "the comb moved no ink");
        QVERIFY2(worstArea < areaTolerance, qPrintable(QString::number(worstArea)));
        QCOMPARE(crossings(combed), std::size_t(0));
        QVERIFY(simulation->comb(comb.inverse()));
        const std::vector<Polygon> undone = outlines(*simulation);
        double worstReturn = 0.0;
        for (std::size_t c = 0; c < before.size(); ++c)
            worstReturn = std::max(worstReturn, sim::hausdorffDistance(undone[c], before[c]));
        QVERIFY2(worstReturn < 2e-3, qPrintable(QString::number(worstReturn)));
    }

    void twentyCombsCrossNothing_data() { test::addBackendRows(); }
    void twentyCombsCrossNothing()
    {
        QFETCH(QString, backend);
        VF_REQUIRE_BACKEND(backend);
        auto simulation = stillWater(backend);
        for (const Polygon& drop : dropGrid(5, simulation->settings().tracking.maxSpacing))
            simulation->addRegion({drop});
        std::vector<double> areas;
        for (const Polygon& p : outlines(*simulation))
            areas.push_back(sim::signedArea(p));
        for (const Comb& comb : twentyCombs())
            QVERIFY(simulation->comb(comb));
        const std::vector<Polygon> combed = outlines(*simulation);
        QCOMPARE(crossings(combed), std::size_t(0));
        QCOMPARE(combed.size(), areas.size());
        for (std::size_t c = 0; c < areas.size(); ++c)
            QVERIFY2(std::abs(sim::signedArea(combed[c]) - areas[c]) < 1e-3 * areas[c],  // 1.6e-4 measured
                     qPrintable(QString::number(sim::signedArea(combed[c]) / areas[c] - 1.0)));
    }
};

QTEST_APPLESS_MAIN(TestComb)
#include "tst_comb.moc"
