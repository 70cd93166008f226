// The last guard of an exact motion (sim/CrossedChords): chords that cross where the curves they
// depict do not are split until they no longer cross, on a made-up bend and on every backend.
#include "Backends.h"
#include "StillWater.h"
#include "sim/CrossedChords.h"
#include "sim/Crossings.h"
#include "sim/ExactMap.h"

#include <QTest>

#include <algorithm>

Q_DECLARE_METATYPE(vf::sim::ExactMap)

using namespace vf;
using sim::Contour;
using sim::Vec2;

namespace {

// (x, y) → (x, y + x²): a shear that keeps areas and bends every horizontal line into a parabola,
// so a long straight edge's chord misses its curve by up to a quarter of its squared length.
Vec2 bend(Vec2 p) { return {p.x, p.y + p.x * p.x}; }

// A contour at `polygon` before the bend, and bent.
Contour bent(const sim::Polygon& polygon)
{
    Contour c;
    c.previous = polygon;
    for (const Vec2& p : polygon)
        c.positions.push_back(bend(p));
    c.spacing.assign(polygon.size(), 0.1);
    return c;
}

std::size_t crossingsOf(const std::vector<Contour>& contours)
{
    std::vector<const sim::Polygon*> outlines;
    for (const Contour& c : contours)
        outlines.push_back(&c.positions);
    return sim::countCrossings(outlines);
}

} // namespace

class TestCrossedChords : public QObject {
    Q_OBJECT
private slots:
    void splitsUntilTheChordsFollowTheCurves_data()
    {
        QTest::addColumn<bool>("floatPositions");
        QTest::newRow("double") << false;
        QTest::newRow("float") << true;
    }
    // Below, a square whose top is one edge from x = 1 to x = −1; 1e-3 above it, a layer whose
    // bottom has a vertex at x = 0.3. Bent, the square's top is the chord y = 1 while the layer's
    // vertex drops to y ≈ 0.09: its chords cross the square's. The curves lie 1e-3 apart. In float
    // (a device's), the vertices split in are where floats lie: what the device will keep.
    void splitsUntilTheChordsFollowTheCurves()
    {
        QFETCH(bool, floatPositions);
        std::vector<Contour> contours{bent({{-1.0, -1.0}, {1.0, -1.0}, {1.0, 0.0}, {-1.0, 0.0}}),
                                      bent({{-1.0, 1e-3}, {0.3, 1e-3}, {1.0, 1e-3}, {1.0, 1.0}, {-1.0, 1.0}})};
        QCOMPARE(crossingsOf(contours), std::size_t(2));
        const std::vector<Contour> before = contours;
        const sim::ExactMotion motion{bend, {}, 1e-7, true};
        const std::size_t inserted = sim::splitCrossedChords(contours, motion, floatPositions);
        QVERIFY(inserted > 0);
        QCOMPARE(contours[0].positions.size() + contours[1].positions.size(), 9 + inserted);
        QCOMPARE(crossingsOf(contours), std::size_t(0));
        for (std::size_t k = 0; k < contours.size(); ++k) {  // every vertex on its curve, where it came from
            const Contour& c = contours[k];
            QCOMPARE(c.previous.size(), c.positions.size());
            QCOMPARE(c.spacing.size(), c.positions.size());
            for (std::size_t i = 0; i < c.positions.size(); ++i) {
                const Vec2 p = c.positions[i];
                QVERIFY(glm::distance(p, bend(c.previous[i])) <= (floatPositions ? 1e-7 : 0.0));
                const bool splitIn = std::find(before[k].previous.begin(), before[k].previous.end(), c.previous[i]) ==
                                     before[k].previous.end();
                QVERIFY(!(floatPositions && splitIn) || (double(float(p.x)) == p.x && double(float(p.y)) == p.y));
            }
        }
    }

    // Two squares that overlap before the motion (one that moves nothing) keep their crossings: no
    // split could undo them.
    void leavesCrossingsThePreImagesHad()
    {
        const auto still = [](Vec2 p) { return p; };
        std::vector<Contour> contours(2);
        contours[0].positions = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
        contours[1].positions = {{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};
        for (Contour& c : contours) {
            c.previous = c.positions;
            c.spacing.assign(4, 0.1);
        }
        QCOMPARE(crossingsOf(contours), std::size_t(2));
        QCOMPARE(sim::splitCrossedChords(contours, {still, {}, 1e-7, true}, false), std::size_t(0));
        QCOMPARE(crossingsOf(contours), std::size_t(2));
    }

    void pressedLayersDoNotCross_data()
    {
        test::addBackendColumn();
        QTest::addColumn<sim::ExactMap>("map");
        QTest::addColumn<double>("gap");
        const sim::ExactMap wavy = sim::Comb{{0.1, 0.5}, {0.4, 0.5}, 4, 0.25, 0.03, 0.04, 0.3, 1.0};
        const sim::ExactMap circular = sim::CircularComb{{0.5, 0.5}, 0.12, 3, 0.125, 0.02, 0.8};
        // The wavy comb with tines 30 times as sharp: a shear of 300 at each, which splits chords
        // down to a float spacing on OpenCL.
        const sim::ExactMap sharp = sim::Comb{{0.1, 0.5}, {0.4, 0.5}, 4, 0.25, 0.001, 0.04, 0.3, 1.0};
        // Double positions hold a gap far under the chord tolerance; float ones (OpenCL) resolve
        // no gap under a float spacing (6e-8 here), so the device's rows keep five of them.
        for (const auto& [backend, gap] : {std::pair(u"reference"_qs, 3e-8), std::pair(u"opencl"_qs, 3e-7)}) {
            QTest::newRow(qPrintable(backend + u" wavy comb"_qs)) << backend << wavy << gap;
            QTest::newRow(qPrintable(backend + u" circular comb"_qs)) << backend << circular << gap;
            QTest::newRow(qPrintable(backend + u" sharp comb"_qs)) << backend << sharp << gap;
        }
    }
    // Six bands stacked `gap` apart, under the chord tolerance, through a map.
    void pressedLayersDoNotCross()
    {
        QFETCH(QString, backend);
        QFETCH(sim::ExactMap, map);
        QFETCH(double, gap);
        VF_REQUIRE_BACKEND(backend);
        auto simulation = test::stillWater(backend);
        for (int k = 0; k < 6; ++k) {
            const double y = 0.35 + k * (0.05 + gap);
            simulation->addRegion({sim::resample({{0.2, y}, {0.8, y}, {0.8, y + 0.05}, {0.2, y + 0.05}}, 0.004)});
        }
        QVERIFY(simulation->applyMap(map));
        QCOMPARE(test::crossings(test::outlines(*simulation)), std::size_t(0));
    }
};

QTEST_APPLESS_MAIN(TestCrossedChords)
#include "tst_crossed_chords.moc"
