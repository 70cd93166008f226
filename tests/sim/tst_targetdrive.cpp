// Target-driven design (sim/TargetDrive, sim/Coverage, the body force of both backends): the ink
// and target densities, the force's direction, and ink gathering into a target on every backend
// without a crossing and with its areas kept.
#include "Backends.h"
#include "StillWater.h"
#include "sim/TargetDrive.h"

#include <QTest>

#include <cmath>
#include <numeric>
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
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sim::TargetDrive({}, grid, {}));
        auto simulation = sim::makeReferenceSimulation(gatheringWater());
        sim::BodyForce wrongGrid{sim::FluidSolver::atRest({8, 8, 1.0, 1.0}), 1.0};
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, simulation->drive(wrongGrid));
        sim::BodyForce notANumber{sim::FluidSolver::atRest(gatheringWater().fluid), 1.0};
        notANumber.acceleration.u[100] = std::nan("");
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, simulation->drive(notANumber));
    }

    // Six drops in a column beside a disc flow into it: the overlap grows from none to a good share
    // in 1.5 s, nothing crosses and each drop keeps its area (area correction on).
    void inkGathersIntoTheTarget_data() { test::addBackendRows(); }
    void inkGathersIntoTheTarget()
    {
        QFETCH(QString, backend);
        VF_REQUIRE_BACKEND(backend);
        auto simulation = test::makeBackend(backend, gatheringWater());
        std::vector<double> areas;
        for (int k = 0; k < 6; ++k) {
            const Polygon drop = sim::circle({0.25, 0.25 + 0.1 * k}, 0.04, 0.008);
            simulation->addRegion({drop});
            areas.push_back(sim::signedArea(drop));
        }
        const Polygon disc = sim::circle({0.6, 0.5}, 0.16, 0.008);
        const sim::TargetDrive drive({{disc}}, simulation->settings().fluid, {150.0, 3.0, 0.02});
        const CellLattice fine{256, 256, 1.0, 1.0};
        const double before = sim::intersectionOverUnion(simulation->regions(), {disc}, fine);
        for (int step = 0; step < 150; ++step) {
            simulation->drive(drive.force(simulation->regions()));
            simulation->step(0.01);
        }
        const double after = sim::intersectionOverUnion(simulation->regions(), {disc}, fine);
        qInfo("overlap %.3f before, %.3f after", before, after);
        QCOMPARE(before, 0.0);
        QVERIFY2(after > 0.1, qPrintable(QString::number(after)));
        QCOMPARE(test::crossings(test::outlines(*simulation)), std::size_t(0));
        const auto regions = simulation->regions();
        for (std::size_t r = 0; r < areas.size(); ++r)
            QVERIFY2(std::abs(sim::filledArea(regions[r]) / areas[r] - 1.0) < 1e-2,
                     qPrintable(QString::number(sim::filledArea(regions[r]) / areas[r] - 1.0)));
    }
};

QTEST_APPLESS_MAIN(TestTargetDrive)
#include "tst_targetdrive.moc"
