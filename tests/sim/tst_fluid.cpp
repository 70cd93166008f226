// Tests of the stable-fluids solver (sim/FluidSolver): projection, walls, viscosity, stylus,
// sampling, settings validation, determinism.
#include "sim/FluidSolver.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

using namespace vf::sim;

Q_DECLARE_METATYPE(vf::sim::Advection)

namespace {

constexpr double kDt = 0.002;  // the scene default time step

FluidSettings settings(int nx, int ny, double width, double height, double viscosity,
                       Advection advection = Advection::MacCormack)
{
    FluidSettings s;
    s.nx = nx;
    s.ny = ny;
    s.width = width;
    s.height = height;
    s.viscosity = viscosity;
    s.advection = advection;
    return s;
}

// A pen circling the centre of the canvas, one segment per call.
void stir(FluidSolver& fluid, int segment)
{
    const FluidSettings& s = fluid.settings();
    const Vec2 center{0.5 * s.width, 0.5 * s.height};
    const double radius = 0.3 * std::min(s.width, s.height);
    const auto at = [&](int k) {
        const double a = 0.4 * k;
        return center + radius * Vec2{std::cos(a), std::sin(a)};
    };
    fluid.addStylus(at(segment), at(segment + 1), 0.05 * std::min(s.width, s.height), 5 * kDt);
}

// Integral of u over the faces within `radius` of p: the x-momentum the pen put there.
double localMomentumX(const FluidSolver& fluid, Vec2 p, double radius)
{
    const MacVelocity& m = fluid.velocity();
    double sum = 0.0;
    for (int j = 0; j < m.ny; ++j)
        for (int i = 0; i <= m.nx; ++i) {
            const Vec2 face{i * m.hx, (j + 0.5) * m.hy};
            if (glm::length(face - p) < radius)
                sum += m.u[std::size_t(j) * (m.nx + 1) + i] * m.hx * m.hy;
        }
    return sum;
}

bool isZero(const std::vector<double>& values)
{
    return std::all_of(values.begin(), values.end(), [](double x) { return x == 0.0; });
}

} // namespace

class TestFluid : public QObject {
    Q_OBJECT

private slots:
    void divergenceFreeAfterStylus_data();
    void divergenceFreeAfterStylus();
    void stillFluidStaysStill_data();
    void stillFluidStaysStill();
    void viscosityDampsEnergy_data();
    void viscosityDampsEnergy();
    void stylusMovesFluidInPenDirection_data();
    void stylusMovesFluidInPenDirection();
    void fasterPenGivesMoreMomentum();
    void degenerateStrokesDoNothing();
    void highViscosityStopsRightAfterStroke();
    void sampleReproducesLinearField();
    void badSettingsThrow();
    void deterministicAndSnapshotsReplay();
    void largeGrid();
};

void TestFluid::divergenceFreeAfterStylus_data()
{
    QTest::addColumn<int>("nx");
    QTest::addColumn<int>("ny");
    QTest::addColumn<double>("width");
    QTest::addColumn<double>("height");
    QTest::addColumn<double>("tolerance");
    QTest::newRow("64x64 on 1x1") << 64 << 64 << 1.0 << 1.0 << 1e-8;
    QTest::newRow("96x48 on 2x1") << 96 << 48 << 2.0 << 1.0 << 1e-8;
    QTest::newRow("40x100 on 1x3") << 40 << 100 << 1.0 << 3.0 << 1e-8;
    QTest::newRow("64x16 on 1x1, thin cells") << 64 << 16 << 1.0 << 1.0 << 1e-8;
    QTest::newRow("64x64, loose tolerance") << 64 << 64 << 1.0 << 1.0 << 1e-3;
}

void TestFluid::divergenceFreeAfterStylus()
{
    QFETCH(int, nx);
    QFETCH(int, ny);
    QFETCH(double, width);
    QFETCH(double, height);
    QFETCH(double, tolerance);
    FluidSettings s = settings(nx, ny, width, height, 5e-4);
    s.pressureTolerance = tolerance;
    FluidSolver fluid(s);
    for (int k = 0; k < 15; ++k) {
        stir(fluid, k);
        fluid.step(kDt);
        QVERIFY2(fluid.maxDivergence() <= tolerance,
                 qPrintable(QString("step %1: max |div u| = %2")
                                .arg(k)
                                .arg(fluid.maxDivergence())));
        QVERIFY(fluid.lastPressureIterations() > 0);  // the stylus did make the field divergent
    }
    QVERIFY(fluid.maxSpeed() > 0.1);
}

void TestFluid::stillFluidStaysStill_data()
{
    QTest::addColumn<Advection>("advection");
    QTest::addColumn<double>("viscosity");
    QTest::newRow("semi-Lagrangian, inviscid") << Advection::SemiLagrangian << 0.0;
    QTest::newRow("MacCormack, inviscid") << Advection::MacCormack << 0.0;
    QTest::newRow("MacCormack, viscous") << Advection::MacCormack << 0.05;
}

void TestFluid::stillFluidStaysStill()
{
    QFETCH(Advection, advection);
    QFETCH(double, viscosity);
    FluidSolver fluid(settings(36, 24, 1.5, 1.0, viscosity, advection));
    for (int k = 0; k < 100; ++k) {
        fluid.step(kDt);
        QCOMPARE(fluid.lastPressureIterations(), 0);
    }
    QVERIFY(isZero(fluid.velocity().u));
    QVERIFY(isZero(fluid.velocity().v));
}

void TestFluid::viscosityDampsEnergy_data()
{
    QTest::addColumn<Advection>("advection");
    QTest::addColumn<double>("viscosity");
    for (const double viscosity : {5e-4, 0.05, 5.0}) {
        QTest::addRow("MacCormack, nu = %g", viscosity) << Advection::MacCormack << viscosity;
        QTest::addRow("semi-Lagrangian, nu = %g", viscosity)
            << Advection::SemiLagrangian << viscosity;
    }
}

void TestFluid::viscosityDampsEnergy()
{
    QFETCH(Advection, advection);
    QFETCH(double, viscosity);
    FluidSolver fluid(settings(32, 32, 1.0, 1.0, viscosity, advection));
    for (int k = 0; k < 6; ++k) {
        stir(fluid, k);
        fluid.step(kDt);
    }
    double energy = fluid.kineticEnergy();
    QVERIFY(energy > 0.0);
    for (int k = 0; k < 40; ++k) {
        fluid.step(kDt);
        const double next = fluid.kineticEnergy();
        QVERIFY2(next < energy,
                 qPrintable(QString("step %1: %2 -> %3").arg(k).arg(energy).arg(next)));
        energy = next;
    }
}

void TestFluid::stylusMovesFluidInPenDirection_data()
{
    QTest::addColumn<Vec2>("direction");
    QTest::newRow("right") << Vec2{1.0, 0.0};
    QTest::newRow("left") << Vec2{-1.0, 0.0};
    QTest::newRow("up") << Vec2{0.0, -1.0};
    QTest::newRow("down") << Vec2{0.0, 1.0};
    QTest::newRow("diagonal") << glm::normalize(Vec2{1.0, 1.0});
}

void TestFluid::stylusMovesFluidInPenDirection()
{
    QFETCH(Vec2, direction);
    FluidSolver fluid(settings(96, 48, 2.0, 1.0, 5e-4));
    const Vec2 center{1.0, 0.5};
    fluid.addStylus(center - 0.1 * direction, center + 0.1 * direction, 0.05, 0.1);  // 2 units/s
    fluid.step(kDt);
    const Vec2 velocity = fluid.velocity().sample(center);
    const double along = glm::dot(velocity, direction);
    const double across = std::abs(velocity.x * direction.y - velocity.y * direction.x);
    QVERIFY2(along > 0.05, qPrintable(QString("along the pen: %1").arg(along)));
    QVERIFY2(across < 0.01 * along, qPrintable(QString("across the pen: %1").arg(across)));
}

void TestFluid::fasterPenGivesMoreMomentum()
{
    const Vec2 from{0.4, 0.5}, to{0.6, 0.5};
    double previous = 0.0;
    for (const double duration : {2.0, 0.2, 0.05}) {  // 0.1, 1 and 4 canvas units/s
        FluidSolver fluid(settings(64, 64, 1.0, 1.0, 5e-4));
        fluid.addStylus(from, to, 0.05, duration);
        fluid.step(kDt);
        const double momentum = localMomentumX(fluid, {0.5, 0.5}, 0.15);
        QVERIFY2(momentum > 1.5 * previous,
                 qPrintable(QString("duration %1: %2 after %3")
                                .arg(duration)
                                .arg(momentum)
                                .arg(previous)));
        previous = momentum;
    }
    // A slow pen barely stirs: 0.1 units/s of pen moves the fluid by well under that.
    FluidSolver slow(settings(64, 64, 1.0, 1.0, 5e-4));
    slow.addStylus(from, to, 0.05, 2.0);
    slow.step(kDt);
    QVERIFY(slow.maxSpeed() < 0.02);
}

void TestFluid::degenerateStrokesDoNothing()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    FluidSolver fluid(settings(32, 32, 1.0, 1.0, 5e-4));
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, 0.0);    // a jump
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, -1.0);
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, nan);
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, nan, 0.1);
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.0, 0.1);
    fluid.addStylus({nan, 0.5}, {0.8, 0.5}, 0.05, 0.1);
    fluid.addStylus({0.2, 0.5}, {inf, 0.5}, 0.05, 0.1);
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, 1e-320);  // pen velocity overflows
    fluid.step(kDt);
    QVERIFY(isZero(fluid.velocity().u));
    QVERIFY(isZero(fluid.velocity().v));
    // A stroke far outside the canvas touches nothing either, and is safe.
    fluid.addStylus({1e300, -1e300}, {2e300, -1e300}, 1e299, 1.0);
    fluid.step(kDt);
    QVERIFY(isZero(fluid.velocity().u));
}

// "Shape design" (paper §5.2): with a very viscous fluid the motion dies right after the stroke.
// Even the slowest divergence-free mode of the free-slip unit box decays like exp(-2 pi^2 nu t),
// to 1% within 0.025 s at nu = 10; the flow a stroke leaves is far more local and dies faster.
void TestFluid::highViscosityStopsRightAfterStroke()
{
    FluidSolver fluid(settings(64, 64, 1.0, 1.0, 10.0));
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, 0.1);
    fluid.step(kDt);
    const double peak = fluid.maxSpeed();
    QVERIFY(peak > 0.0);
    for (int k = 0; k < 8; ++k)
        fluid.step(kDt);
    QVERIFY2(fluid.maxSpeed() < 0.01 * peak,
             qPrintable(QString("%1 of the peak speed left").arg(fluid.maxSpeed() / peak)));
}

void TestFluid::sampleReproducesLinearField()
{
    FluidSolver fluid(settings(20, 12, 2.0, 0.75, 0.0));
    MacVelocity m = fluid.velocity();
    const auto field = [](Vec2 p) {
        return Vec2{0.3 + 1.5 * p.x - 0.7 * p.y, -0.2 + 0.4 * p.x + 2.5 * p.y};
    };
    for (int j = 0; j < m.ny; ++j)
        for (int i = 0; i <= m.nx; ++i)
            m.u[std::size_t(j) * (m.nx + 1) + i] = field({i * m.hx, (j + 0.5) * m.hy}).x;
    for (int j = 0; j <= m.ny; ++j)
        for (int i = 0; i < m.nx; ++i)
            m.v[std::size_t(j) * m.nx + i] = field({(i + 0.5) * m.hx, j * m.hy}).y;
    // Where both components have lattice points on both sides: half a cell in from the walls.
    for (int k = 0; k < 500; ++k) {
        const Vec2 p{(0.5 + 19.0 * (k % 23) / 22.0) * m.hx, (0.5 + 11.0 * (k % 17) / 16.0) * m.hy};
        const Vec2 error = m.sample(p) - field(p);
        QVERIFY2(std::abs(error.x) < 1e-12 && std::abs(error.y) < 1e-12,
                 qPrintable(QString("at (%1, %2)").arg(p.x).arg(p.y)));
    }
    // Outside the canvas the sample is that of the nearest canvas point.
    QCOMPARE(m.sample({-1.0, 5.0}), m.sample({0.0, 0.75}));
    QCOMPARE(m.sample({3.0, -2.0}), m.sample({2.0, 0.0}));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(std::isfinite(m.sample({nan, nan}).x));
}

void TestFluid::badSettingsThrow()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const auto throwsFor = [](auto change) {
        FluidSettings s;
        change(s);
        try {
            FluidSolver fluid(s);
        } catch (const std::invalid_argument& e) {
            return QString(e.what()).startsWith("FluidSettings: ");
        }
        return false;
    };
    QVERIFY(throwsFor([](FluidSettings& s) { s.nx = 3; }));
    QVERIFY(throwsFor([](FluidSettings& s) { s.ny = 0; }));
    QVERIFY(throwsFor([](FluidSettings& s) { s.ny = -64; }));
    QVERIFY(throwsFor([](FluidSettings& s) { s.nx = 100000; }));
    QVERIFY(throwsFor([](FluidSettings& s) { s.width = 0.0; }));
    QVERIFY(throwsFor([](FluidSettings& s) { s.height = -1.0; }));
    QVERIFY(throwsFor([&](FluidSettings& s) { s.width = nan; }));
    QVERIFY(throwsFor([&](FluidSettings& s) { s.height = inf; }));
    QVERIFY(throwsFor([](FluidSettings& s) { s.viscosity = -1e-6; }));
    QVERIFY(throwsFor([&](FluidSettings& s) { s.viscosity = nan; }));
    QVERIFY(throwsFor([&](FluidSettings& s) { s.pressureTolerance = 0.0; }));
    QVERIFY(!throwsFor([](FluidSettings& s) { s.nx = 4; s.ny = 4; s.viscosity = 0.0; }));

    FluidSolver fluid(settings(16, 8, 2.0, 1.0, 0.0));
    MacVelocity wrong = FluidSolver(settings(8, 16, 1.0, 2.0, 0.0)).velocity();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid.setVelocity(wrong));
    wrong = fluid.velocity();
    wrong.u.pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid.setVelocity(wrong));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid.step(0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid.step(nan));
}

void TestFluid::deterministicAndSnapshotsReplay()
{
    const auto run = [](FluidSolver& fluid, int first, int count) {
        for (int k = first; k < first + count; ++k) {
            if (k < 15)
                stir(fluid, k);
            fluid.step(kDt);
        }
    };
    FluidSolver a(settings(48, 40, 1.2, 1.0, 5e-3)), b(settings(48, 40, 1.2, 1.0, 5e-3));
    run(a, 0, 10);
    run(b, 0, 10);
    QVERIFY(a.velocity().u == b.velocity().u && a.velocity().v == b.velocity().v);

    // A snapshot restored into a fresh solver and into the running one replays identically.
    const MacVelocity snapshot = a.velocity();
    FluidSolver restored(a.settings());
    restored.setVelocity(snapshot);
    a.setVelocity(snapshot);
    run(a, 10, 10);
    run(restored, 10, 10);
    QVERIFY(a.velocity().u == restored.velocity().u && a.velocity().v == restored.velocity().v);
    QVERIFY(!isZero(a.velocity().u));
}

// 512 x 512, the largest grid the solver is required to handle: one stroke, still divergence-free
// and bounded.
void TestFluid::largeGrid()
{
    FluidSolver fluid(settings(512, 512, 1.0, 1.0, 5e-4));
    fluid.addStylus({0.3, 0.5}, {0.7, 0.5}, 0.03, 0.1);
    fluid.step(kDt);
    QVERIFY(fluid.maxDivergence() <= fluid.settings().pressureTolerance);
    QVERIFY(fluid.maxSpeed() > 0.1 && fluid.maxSpeed() < 4.0);
}

QTEST_APPLESS_MAIN(TestFluid)
#include "tst_fluid.moc"
