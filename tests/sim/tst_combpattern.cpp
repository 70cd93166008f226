// A long pattern of exact combs on every backend, as gel-git and nonpareil are made: twenty passes
// across and along a grid of drops cross no contours and keep every area. Labelled `long`: its
// million-vertex-step maps run in the Release build (under the sanitizers they take ten minutes).
#include "Backends.h"
#include "StillWater.h"
#include "sim/ExactMap.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace vf;
using sim::Comb;
using sim::Polygon;
using sim::Vec2;

namespace {

// A pattern of twenty combs: passes across and along the tray with 3 to 7 tines, both ways, as
// gel-git and nonpareil are made, every third one wavy.
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
        const double amplitude = k % 3 == 2 ? 0.03 * unit(random) : 0.0;  // every third one wavy
        combs.push_back({from, to, 3 + k % 5, 0.12, 0.02 + 0.02 * unit(random), amplitude, 0.25, 6.0 * unit(random)});
    }
    return combs;
}

} // namespace

class TestCombPattern : public QObject {
    Q_OBJECT

private slots:
    void twentyCombsCrossNothing_data() { test::addBackendRows(); }
    void twentyCombsCrossNothing()
    {
        QFETCH(QString, backend);
        VF_REQUIRE_BACKEND(backend);
        auto simulation = test::stillWater(backend);
        for (const Polygon& drop : test::dropGrid(5, simulation->settings().tracking.maxSpacing))
            simulation->addRegion({drop});
        std::vector<double> areas;
        for (const Polygon& p : test::outlines(*simulation))
            areas.push_back(sim::signedArea(p));
        for (const Comb& comb : twentyCombs())
            QVERIFY(simulation->applyMap(comb));
        const std::vector<Polygon> combed = test::outlines(*simulation);
        QCOMPARE(test::crossings(combed), std::size_t(0));
        QCOMPARE(combed.size(), areas.size());
        for (std::size_t c = 0; c < areas.size(); ++c)
            QVERIFY2(std::abs(sim::signedArea(combed[c]) - areas[c]) < 1e-3 * areas[c],  // 1.6e-4 measured
                     qPrintable(QString::number(sim::signedArea(combed[c]) / areas[c] - 1.0)));
    }
};

QTEST_APPLESS_MAIN(TestCombPattern)
#include "tst_combpattern.moc"
