// Target-driven design (sim/TargetDrive, sim/Coverage, sim/DistanceField, the body force of both
// backends): the ink and target densities, the target's depth, the force's direction, and ink
// gathering into a target on every backend without a crossing and with its areas kept, further
// with the gathering term than without.
#include "Backends.h"
#include "StillWater.h"
#include "sim/TargetDrive.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>

using namespace vf;
using sim::CellLattice;
using sim::Polygon;
using sim::Vec2;

namespace {

Polygon square(Vec2 lo, Vec2 hi)
{
    return {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}};
}

double sum(const std::vector<double>& values) { return std::accumulate(values.begin(), values.end(), 0.0); }

sim::SimulationSettings gatheringWater()
{
    sim::SimulationSettings settings;
    settings.fluid.viscosity = 0.005;
    settings.tracking.maxSpacing = 0.008;
    settings.tracking.areaCorrection = true;
    return settings;
}

} // namespace

class TestTargetDrive : public QObject {
    Q_OBJECT

private slots:
    // Cells wholly inside count 1, wholly outside 0, cut in half ½; a hole (even-odd) is empty.
    void coverageCountsTheShareOfEachCell()
    {
        const CellLattice cells{10, 10, 1.0, 1.0};
        const std::vector<double> c = sim::coverage({{square({0.2, 0.2}, {0.65, 0.8}), square({0.3, 0.3}, {0.4, 0.4})}}, cells, 4);
        QCOMPARE(c[5 * 10 + 2], 1.0);
        QCOMPARE(c[5 * 10 + 8], 0.0);
        QCOMPARE(c[5 * 10 + 6], 0.5);
        QCOMPARE(c[3 * 10 + 3], 0.0);
        QVERIFY(std::abs(sum(c) / 100.0 - (0.45 * 0.6 - 0.01)) < 1e-12);
    }

    // A blur keeps what stays on the canvas and spreads it evenly both ways.
    void blurKeepsTheInkAndItsSymmetry()
    {
        const CellLattice cells{41, 41, 1.0, 1.0};
        std::vector<double> spot(cells.size(), 0.0);
        spot[20 * 41 + 20] = 1.0;
        const std::vector<double> b = sim::gaussianBlur(spot, cells, 0.05);
        QVERIFY(std::abs(sum(b) - 1.0) < 1e-12);
        QCOMPARE(b[20 * 41 + 18], b[18 * 41 + 20]);
        QCOMPARE(b[20 * 41 + 18], b[20 * 41 + 22]);
        QVERIFY(b[20 * 41 + 20] > b[20 * 41 + 21] && b[20 * 41 + 21] > b[20 * 41 + 22]);
    }

    // The Gaussian taps (narrow blurs) and the three boxes (from eight cells on) spread a spot with
    // the variance asked for, along both axes.
    void blurHasTheVarianceAsked_data()
    {
        QTest::addColumn<double>("cells");
        QTest::newRow("1.5 cells, taps") << 1.5;
        QTest::newRow("7.9 cells, taps") << 7.9;
        QTest::newRow("8 cells, boxes") << 8.0;
        QTest::newRow("12.5 cells, boxes") << 12.5;
    }
    void blurHasTheVarianceAsked()
    {
        QFETCH(double, cells);
        const int n = 201, middle = 100;
        const CellLattice lattice{n, n, 1.0, 1.0};
        std::vector<double> spot(lattice.size(), 0.0);
        spot[std::size_t(middle) * n + middle] = 1.0;
        const std::vector<double> b = sim::gaussianBlur(spot, lattice, cells / n);
        double across = 0.0, down = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                across += b[std::size_t(j) * n + i] * (i - middle) * (i - middle);
                down += b[std::size_t(j) * n + i] * (j - middle) * (j - middle);
            }
        QVERIFY2(std::abs(across / (cells * cells) - 1.0) < 0.05, qPrintable(QString::number(across / (cells * cells))));
        QVERIFY2(std::abs(down / (cells * cells) - 1.0) < 0.05, qPrintable(QString::number(down / (cells * cells))));
    }

    // The distance transform agrees with measuring every pair, on cells that are not square, and
    // is infinite where there are no seeds.
    void distancesAreExact()
    {
        const CellLattice cells{23, 17, 1.0, 0.5};
        std::mt19937 random(7);
        std::vector<bool> seed(cells.size());
        for (std::size_t k = 0; k < seed.size(); ++k)
            seed[k] = random() % 13 == 0;
        const std::vector<double> d = sim::distanceToSeeds(seed, cells);
        const double hx = cells.width / cells.cols, hy = cells.height / cells.rows;
        for (int j = 0; j < cells.rows; ++j)
            for (int i = 0; i < cells.cols; ++i) {
                double nearest = std::numeric_limits<double>::infinity();
                for (int b = 0; b < cells.rows; ++b)
                    for (int a = 0; a < cells.cols; ++a)
                        if (seed[std::size_t(b) * cells.cols + a])
                            nearest = std::min(nearest, std::hypot((a - i) * hx, (b - j) * hy));
                QVERIFY2(std::abs(d[std::size_t(j) * cells.cols + i] - nearest) < 1e-12,
                         qPrintable(QStringLiteral("cell %1,%2: %3, brute force %4").arg(i).arg(j).arg(d[std::size_t(j) * cells.cols + i]).arg(nearest)));
            }
        for (double x : sim::distanceToSeeds(std::vector<bool>(cells.size(), false), cells))
            QVERIFY(std::isinf(x));
    }

    // The depth rises toward a square's middle from inside, falls away from it outside, and is
    // flat for a shape that covers everything.
    void depthRisesIntoTheShape()
    {
        const CellLattice cells{40, 40, 1.0, 1.0};
        const std::vector<double> depth = sim::signedDepth(sim::coverage({{square({0.25, 0.25}, {0.75, 0.75})}}, cells, 4), cells);
        const auto at = [&](int i) { return depth[std::size_t(20) * 40 + i]; };  // along the row through the middle
        QVERIFY(at(2) < at(5) && at(5) < 0.0);
        QVERIFY(at(12) > 0.0 && at(12) < at(16) && at(16) < at(19));
        // Cells are 0.025 wide; cell 9 is the last outside the square and cell 10 the first in.
        QCOMPARE(at(19), 10 * 0.025);
        QCOMPARE(at(2), -8 * 0.025);
        for (double x : sim::signedDepth(std::vector<double>(cells.size(), 1.0), cells))
            QCOMPARE(x, 0.0);
    }

    void intersectionOverUnionOfSimpleShapes()
    {
        const CellLattice cells{200, 200, 1.0, 1.0};
        const Polygon left = square({0.2, 0.2}, {0.6, 0.6}), right = square({0.4, 0.2}, {0.8, 0.6});
        QCOMPARE(sim::intersectionOverUnion({{left}}, {left}, cells), 1.0);
        QCOMPARE(sim::intersectionOverUnion({{left}}, {square({0.7, 0.7}, {0.9, 0.9})}, cells), 0.0);
        QVERIFY(std::abs(sim::intersectionOverUnion({{left}}, {right}, cells) - 1.0 / 3.0) < 1e-9);
    }

    // Ink left of the target is pushed right, toward it, and water far from any ink feels nothing.
    void forceLeadsInkTowardTheTarget()
    {
        sim::FluidSettings grid;
        const sim::TargetDrive drive({{square({0.6, 0.4}, {0.8, 0.6})}}, grid, {});
        const sim::BodyForce f = drive.force({{sim::circle({0.3, 0.5}, 0.05, 0.005)}});
        QCOMPARE(f.damping, drive.settings().attenuation);
        const int nx = grid.nx;
        const auto u = [&](Vec2 p) { return f.acceleration.u[std::size_t(p.y * grid.ny) * (nx + 1) + std::size_t(p.x * nx)]; };
        QVERIFY2(u({0.3, 0.5}) > 0.0, qPrintable(QString::number(u({0.3, 0.5}))));
        QCOMPARE(u({0.3, 0.1}), 0.0);
        QCOMPARE(u({0.9, 0.9}), 0.0);
    }

    void badInputRefused()
    {
        sim::FluidSettings grid;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sim::TargetDrive({{square({0.1, 0.1}, {0.2, 0.2})}}, grid, {1.0, 1.0, 0.0}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sim::TargetDrive({{square({0.1, 0.1}, {0.2, 0.2})}}, grid, {-1.0, 1.0, 0.02}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sim::TargetDrive({{square({0.1, 0.1}, {0.2, 0.2})}}, grid, {1.0, 1.0, 0.02, std::nan("")}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sim::TargetDrive({}, grid, {}));
        auto simulation = sim::makeReferenceSimulation(gatheringWater());
        sim::BodyForce wrongGrid{sim::FluidSolver::atRest({8, 8, 1.0, 1.0}), 1.0};
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, simulation->drive(wrongGrid));
        sim::BodyForce notANumber{sim::FluidSolver::atRest(gatheringWater().fluid), 1.0};
        notANumber.acceleration.u[100] = std::nan("");
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, simulation->drive(notANumber));
    }

    // Six drops in a column beside a disc flow into it: the overlap grows from none to a good share
    // in 1.5 s, nothing crosses and each drop keeps its area (area correction on). The gathering
    // term takes the ink further in than the driving force alone.
    void inkGathersIntoTheTarget_data() { test::addBackendRows(); }
    void inkGathersIntoTheTarget()
    {
        QFETCH(QString, backend);
        VF_REQUIRE_BACKEND(backend);
        const Gathered alone = gather(backend, 0.0), gathered = gather(backend, 5.0);
        qInfo("overlap after: %.3f by the driving force alone, %.3f with the gathering term", alone.after, gathered.after);
        for (const Gathered& g : {alone, gathered}) {
            QCOMPARE(g.before, 0.0);
            QCOMPARE(g.crossings, std::size_t(0));
            QVERIFY2(g.worstAreaChange < 1e-2, qPrintable(QString::number(g.worstAreaChange)));
        }
        QVERIFY2(alone.after > 0.1, qPrintable(QString::number(alone.after)));
        QVERIFY2(gathered.after > alone.after + 0.05, qPrintable(QString::number(gathered.after)));
    }

private:
    struct Gathered {
        double before, after;  // overlap with the target
        std::size_t crossings;
        double worstAreaChange;  // relative, of any drop
    };

    // Six drops gathered for 1.5 s into a disc beside them, with the gathering term at `gathering`.
    static Gathered gather(const QString& backend, double gathering)
    {
        auto simulation = test::makeBackend(backend, gatheringWater());
        std::vector<double> areas;
        for (int k = 0; k < 6; ++k) {
            const Polygon drop = sim::circle({0.25, 0.25 + 0.1 * k}, 0.04, 0.008);
            simulation->addRegion({drop});
            areas.push_back(sim::signedArea(drop));
        }
        const Polygon disc = sim::circle({0.6, 0.5}, 0.16, 0.008);
        const sim::TargetDrive drive({{disc}}, simulation->settings().fluid, {150.0, 10.0, 0.02, gathering});
        const CellLattice fine{256, 256, 1.0, 1.0};
        Gathered g{};
        g.before = sim::intersectionOverUnion(simulation->regions(), {disc}, fine);
        for (int step = 0; step < 150; ++step) {
            simulation->drive(drive.force(simulation->regions()));
            simulation->step(0.01);
        }
        g.after = sim::intersectionOverUnion(simulation->regions(), {disc}, fine);
        g.crossings = test::crossings(test::outlines(*simulation));
        const auto regions = simulation->regions();
        for (std::size_t r = 0; r < areas.size(); ++r)
            g.worstAreaChange = std::max(g.worstAreaChange, std::abs(sim::filledArea(regions[r]) / areas[r] - 1.0));
        return g;
    }
};

QTEST_APPLESS_MAIN(TestTargetDrive)
#include "tst_targetdrive.moc"
