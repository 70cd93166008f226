// Tests of the fluid solvers. Behaviour, on both solvers as data rows (Fluids.h): projection,
// walls, viscosity, the pen, degenerate strokes, determinism and snapshots, bad input. The
// reference FluidSolver's own: momentum against pen speed, sampling, the largest grid.
#include "Fluids.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

using namespace vf::sim;
using namespace vf::test;

Q_DECLARE_METATYPE(vf::sim::Advection)
Q_DECLARE_METATYPE(vf::sim::FluidSettings)

namespace {

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
    void degenerateStrokesDoNothing_data() { addBackendRows(); }
    void degenerateStrokesDoNothing();
    void highViscosityStopsRightAfterStroke_data() { addBackendRows(); }
    void highViscosityStopsRightAfterStroke();
    void deterministicAndSnapshotsReplay_data() { addBackendRows(); }
    void deterministicAndSnapshotsReplay();
    void fasterPenGivesMoreMomentum();
    void sampleReproducesLinearField();
    void badInputThrows_data() { addBackendRows(); }
    void badInputThrows();
    void largeGrid();
};

void TestFluid::divergenceFreeAfterStylus_data()
{
    addBackendColumn();
    QTest::addColumn<FluidSettings>("settings");
    for (const QString& b : backendNames()) {
        const auto row = [&](const char* name, const FluidSettings& s) {
            QTest::addRow("%s: %s", qPrintable(b), name) << b << s;
        };
        row("64x64 on 1x1", fluidSettings(64, 64, 1.0, 1.0, 5e-4));
        row("96x48 on 2x1", fluidSettings(96, 48, 2.0, 1.0, 5e-4));
        row("40x100 on 1x3", fluidSettings(40, 100, 1.0, 3.0, 5e-4));
        row("64x16 on 1x1, thin cells", fluidSettings(64, 16, 1.0, 1.0, 5e-4));
        row("256x256, inviscid", fluidSettings(256, 256, 1.0, 1.0, 0.0));
        FluidSettings loose = fluidSettings(64, 64, 1.0, 1.0, 5e-4);
        loose.pressureTolerance = 1e-3;
        row("64x64, loose tolerance", loose);
    }
}

// After every projection max |div u| is within the solver's bound: the tolerance, and on float32
// what rounding leaves (Fluids.h).
void TestFluid::divergenceFreeAfterStylus()
{
    QFETCH(QString, backend);
    QFETCH(FluidSettings, settings);
    VF_REQUIRE_BACKEND(backend);
    const std::unique_ptr<FluidUnderTest> fluid = makeFluid(backend, settings);
    for (int k = 0; k < 15; ++k) {
        stir(*fluid, k);
        fluid->step(kDt);
        const double bound = fluid->divergenceBound(fluid->velocity());
        QVERIFY2(fluid->maxDivergence() <= bound, qPrintable(QString("step %1: max |div u| = %2, bound %3")
                                                                 .arg(k)
                                                                 .arg(fluid->maxDivergence())
                                                                 .arg(bound)));
    }
    QVERIFY(fluid->maxSpeed() > 0.1);  // the pen did stir it
}

void TestFluid::stillFluidStaysStill_data()
{
    addBackendColumn();
    QTest::addColumn<Advection>("advection");
    QTest::addColumn<double>("viscosity");
    for (const QString& b : backendNames()) {
        QTest::addRow("%s: semi-Lagrangian, inviscid", qPrintable(b)) << b << Advection::SemiLagrangian << 0.0;
        QTest::addRow("%s: MacCormack, inviscid", qPrintable(b)) << b << Advection::MacCormack << 0.0;
        QTest::addRow("%s: MacCormack, viscous", qPrintable(b)) << b << Advection::MacCormack << 0.05;
    }
}

void TestFluid::stillFluidStaysStill()
{
    QFETCH(QString, backend);
    QFETCH(Advection, advection);
    QFETCH(double, viscosity);
    VF_REQUIRE_BACKEND(backend);
    const auto fluid = makeFluid(backend, fluidSettings(36, 24, 1.5, 1.0, viscosity, advection));
    for (int k = 0; k < 100; ++k)
        fluid->step(kDt);
    const MacVelocity m = fluid->velocity();
    QVERIFY(isZero(m.u));
    QVERIFY(isZero(m.v));
}

void TestFluid::viscosityDampsEnergy_data()
{
    addBackendColumn();
    QTest::addColumn<Advection>("advection");
    QTest::addColumn<double>("viscosity");
    for (const QString& b : backendNames()) {
        for (const double viscosity : {5e-4, 0.05, 10.0}) {
            QTest::addRow("%s: MacCormack, nu = %g", qPrintable(b), viscosity)
                << b << Advection::MacCormack << viscosity;
            QTest::addRow("%s: semi-Lagrangian, nu = %g", qPrintable(b), viscosity)
                << b << Advection::SemiLagrangian << viscosity;
        }    }
}

void TestFluid::viscosityDampsEnergy()
{
    QFETCH(QString, backend);
    QFETCH(Advection, advection);
    QFETCH(double, viscosity);
    VF_REQUIRE_BACKEND(backend);
    const auto fluid = makeFluid(backend, fluidSettings(32, 32, 1.0, 1.0, viscosity, advection));
    for (int k = 0; k < 6; ++k) {
        stir(*fluid, k);
        fluid->step(kDt);
    }
    double energy = fluid->kineticEnergy();
    QVERIFY(energy > 0.0);
    for (int k = 0; k < 40; ++k) {
        fluid->step(kDt);
        const double next = fluid->kineticEnergy();
        QVERIFY2(next < energy, qPrintable(QString("step %1: %2 -> %3").arg(k).arg(energy).arg(next)));
        energy = next;
    }
}

void TestFluid::stylusMovesFluidInPenDirection_data()
{
    addBackendColumn();
    QTest::addColumn<Vec2>("direction");
    for (const QString& b : backendNames()) {
        QTest::addRow("%s: right", qPrintable(b)) << b << Vec2{1.0, 0.0};
        QTest::addRow("%s: left", qPrintable(b)) << b << Vec2{-1.0, 0.0};
        QTest::addRow("%s: up", qPrintable(b)) << b << Vec2{0.0, -1.0};
        QTest::addRow("%s: down", qPrintable(b)) << b << Vec2{0.0, 1.0};
        QTest::addRow("%s: diagonal", qPrintable(b)) << b << glm::normalize(Vec2{1.0, 1.0});
    }
}

void TestFluid::stylusMovesFluidInPenDirection()
{
    QFETCH(QString, backend);
    QFETCH(Vec2, direction);
    VF_REQUIRE_BACKEND(backend);
    const std::unique_ptr<FluidUnderTest> fluid = makeFluid(backend, fluidSettings(96, 48, 2.0, 1.0, 5e-4));
    const Vec2 center{1.0, 0.5};
    fluid->addStylus(center - 0.1 * direction, center + 0.1 * direction, 0.05, 0.1);  // 2 units/s
    fluid->step(kDt);
    const Vec2 velocity = fluid->velocity().sample(center);
    const double along = glm::dot(velocity, direction);
    const double across = std::abs(velocity.x * direction.y - velocity.y * direction.x);
    QVERIFY2(along > 0.05, qPrintable(QString("along the pen: %1").arg(along)));
    QVERIFY2(across < 0.01 * along, qPrintable(QString("across the pen: %1").arg(across)));
}

void TestFluid::degenerateStrokesDoNothing()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::unique_ptr<FluidUnderTest> fluid = makeFluid(backend, fluidSettings(32, 32, 1.0, 1.0, 5e-4));
    fluid->addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, 0.0);  // a jump
    fluid->addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, -1.0);
    fluid->addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, nan);
    fluid->addStylus({0.2, 0.5}, {0.8, 0.5}, nan, 0.1);
    fluid->addStylus({0.2, 0.5}, {0.8, 0.5}, 0.0, 0.1);
    fluid->addStylus({nan, 0.5}, {0.8, 0.5}, 0.05, 0.1);
    fluid->addStylus({0.2, 0.5}, {inf, 0.5}, 0.05, 0.1);
    fluid->addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, 1e-320);  // pen velocity overflows
    fluid->step(kDt);
    // Far outside the canvas, beyond float32: touches nothing either, and is safe.
    fluid->addStylus({1e300, -1e300}, {2e300, -1e300}, 1e299, 1.0);
    fluid->addStylus({1e30, 0.5}, {2e30, 0.5}, 0.05, 1e30);
    fluid->step(kDt);
    const MacVelocity m = fluid->velocity();
    QVERIFY(isZero(m.u));
    QVERIFY(isZero(m.v));
}

// "Shape design" (paper §5.2): with a very viscous fluid the motion dies right after the stroke.
// Even the slowest divergence-free mode of the free-slip unit box decays like exp(-2 pi^2 nu t),
// to 1% within 0.025 s at nu = 10; the flow a stroke leaves is far more local and dies faster.
void TestFluid::highViscosityStopsRightAfterStroke()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    const std::unique_ptr<FluidUnderTest> fluid = makeFluid(backend, fluidSettings(64, 64, 1.0, 1.0, 10.0));
    fluid->addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, 0.1);
    fluid->step(kDt);
    const double peak = fluid->maxSpeed();
    QVERIFY(peak > 0.0);
    for (int k = 0; k < 8; ++k)
        fluid->step(kDt);
    const double left = fluid->maxSpeed();
    QVERIFY2(left < 0.01 * peak, qPrintable(QString("%1 of the peak speed left").arg(left / peak)));
}

void TestFluid::deterministicAndSnapshotsReplay()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    const FluidSettings s = fluidSettings(48, 40, 1.2, 1.0, 5e-3);
    const std::unique_ptr<FluidUnderTest> a = makeFluid(backend, s), b = makeFluid(backend, s);
    stirAndRun(*a, 0, 10);
    stirAndRun(*b, 0, 10);
    const MacVelocity snapshot = a->velocity();
    QVERIFY(snapshot.u == b->velocity().u && snapshot.v == b->velocity().v);

    // A snapshot restored into a fresh solver and into the running one replays bit for bit.
    const std::unique_ptr<FluidUnderTest> restored = makeFluid(backend, s);
    restored->setVelocity(snapshot);
    a->setVelocity(snapshot);
    QVERIFY(restored->velocity().u == snapshot.u);
    stirAndRun(*a, 10, 10);
    stirAndRun(*restored, 10, 10);
    const MacVelocity replayed = a->velocity();
    QVERIFY(replayed.u == restored->velocity().u && replayed.v == restored->velocity().v);
    QVERIFY(!isZero(replayed.u));
}

void TestFluid::fasterPenGivesMoreMomentum()
{
    const Vec2 from{0.4, 0.5}, to{0.6, 0.5};
    double previous = 0.0;
    for (const double duration : {2.0, 0.2, 0.05}) {  // 0.1, 1 and 4 canvas units/s
        FluidSolver fluid(fluidSettings(64, 64, 1.0, 1.0, 5e-4));
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
    FluidSolver slow(fluidSettings(64, 64, 1.0, 1.0, 5e-4));
    slow.addStylus(from, to, 0.05, 2.0);
    slow.step(kDt);
    QVERIFY(slow.maxSpeed() < 0.02);
}

void TestFluid::sampleReproducesLinearField()
{
    FluidSolver fluid(fluidSettings(20, 12, 2.0, 0.75, 0.0));
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

void TestFluid::badInputThrows()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const auto throwsFor = [&](auto change) {
        FluidSettings s;
        change(s);
        try {
            makeFluid(backend, s);
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

    const std::unique_ptr<FluidUnderTest> fluid = makeFluid(backend, fluidSettings(16, 8, 2.0, 1.0, 0.0));
    MacVelocity wrong = FluidSolver(fluidSettings(8, 16, 1.0, 2.0, 0.0)).velocity();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid->setVelocity(wrong));
    wrong = fluid->velocity();
    wrong.u.pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid->setVelocity(wrong));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid->step(0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid->step(nan));
}

// 512 x 512, the largest grid the solver is required to handle: one stroke, still divergence-free
// and bounded.
void TestFluid::largeGrid()
{
    FluidSolver fluid(fluidSettings(512, 512, 1.0, 1.0, 5e-4));
    fluid.addStylus({0.3, 0.5}, {0.7, 0.5}, 0.03, 0.1);
    fluid.step(kDt);
    QVERIFY(fluid.maxDivergence() <= fluid.settings().pressureTolerance);
    QVERIFY(fluid.maxSpeed() > 0.1 && fluid.maxSpeed() < 4.0);
}

QTEST_APPLESS_MAIN(TestFluid)
#include "tst_fluid.moc"
