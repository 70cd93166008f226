// Tests of the OpenCL fluid solver (sim/opencl/DeviceFluid) against the reference FluidSolver:
// agreement after strokes, projection, walls, viscosity, the pen, determinism and snapshots, the
// fields binding() hands to the contour kernels (from it and from HostFluid) and their sampling in
// flow_fluid.cl, contours moved by either fluid, bad input.
// Skipped, with the reason, when no OpenCL device can be opened.
#include "sim/FluidSolver.h"
#include "sim/StreamFunction.h"
#include "sim/opencl/DeviceFluid.h"
#include "sim/opencl/OpenClSimulation.h"
#include "sim/opencl/KernelSources.h"
#include "sim/opencl/Launch.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

using namespace vf::sim;
using vf::sim::opencl::Device;
using vf::sim::opencl::DeviceError;
using vf::sim::opencl::DeviceFluid;
using vf::sim::opencl::FlowBinding;
using vf::sim::opencl::FluidPlacement;

Q_DECLARE_METATYPE(vf::sim::Advection)
Q_DECLARE_METATYPE(vf::sim::FluidSettings)
Q_DECLARE_METATYPE(vf::sim::opencl::FluidPlacement)

namespace {

constexpr double kDt = 0.002;  // the scene default time step
// The projection's bound relative to the divergence scale S (DeviceFluid.cpp): the solver stops at
// 1e-6 S; float32 rounding of the stored field and pressure leaves up to 2.2e-6 S at 256^2
// (4.5e-6 S at 512^2).
constexpr double kDivergenceBound = 1e-5;

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

// A pen circling the centre of the canvas, one segment per call (as in tst_fluid.cpp).
template <class Fluid>
void stir(Fluid& fluid, int segment)
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

// Stirred for the first 15 steps, then left to flow.
template <class Fluid>
void run(Fluid& fluid, int first, int count)
{
    for (int k = first; k < first + count; ++k) {
        if (k < 15)
            stir(fluid, k);
        fluid.step(kDt);
    }
}

// The reference solver holding the device's field: its diagnostics, in double.
FluidSolver onReference(const DeviceFluid& fluid)
{
    FluidSolver probe(fluid.settings());
    probe.setVelocity(fluid.readVelocity());
    return probe;
}

double maxComponent(const MacVelocity& m)
{
    return std::max(maxAbs(m.u), maxAbs(m.v));
}

double maxDifference(const MacVelocity& a, const MacVelocity& b)
{
    double d = 0.0;
    for (std::size_t k = 0; k < a.u.size(); ++k)
        d = std::max(d, std::abs(a.u[k] - b.u[k]));
    for (std::size_t k = 0; k < a.v.size(); ++k)
        d = std::max(d, std::abs(a.v[k] - b.v[k]));
    return d;
}

// S of DeviceFluid.cpp: the largest sum of the magnitudes of the terms of a cell's divergence.
double divergenceScale(const MacVelocity& m)
{
    double s = 0.0;
    for (int j = 0; j < m.ny; ++j)
        for (int i = 0; i < m.nx; ++i) {
            const double* u = m.u.data() + std::size_t(j) * (m.nx + 1) + i;
            const double* v = m.v.data() + std::size_t(j) * m.nx + i;
            s = std::max(s, (std::abs(u[0]) + std::abs(u[1])) / m.hx
                                + (std::abs(v[0]) + std::abs(v[m.nx])) / m.hy);
        }
    return s;
}

bool isZero(const std::vector<double>& values)
{
    return std::all_of(values.begin(), values.end(), [](double x) { return x == 0.0; });
}

std::vector<double> readBuffer(Device& device, const cl::Buffer& buffer, std::size_t count)
{
    std::vector<float> values(count);
    device.queue().enqueueReadBuffer(buffer, CL_TRUE, 0, count * sizeof(float), values.data());
    return {values.begin(), values.end()};
}

// A smooth, divergent field: enough structure for sampling and vorticity to be checked.
MacVelocity waves(const FluidSettings& s, double phase)
{
    MacVelocity m = FluidSolver(s).velocity();
    for (int j = 0; j < m.ny; ++j)
        for (int i = 0; i <= m.nx; ++i)
            m.u[std::size_t(j) * (m.nx + 1) + i] =
                std::sin(3.0 * i * m.hx + phase) * std::cos(2.0 * (j + 0.5) * m.hy);
    for (int j = 0; j <= m.ny; ++j)
        for (int i = 0; i < m.nx; ++i)
            m.v[std::size_t(j) * m.nx + i] =
                std::cos(2.5 * (i + 0.5) * m.hx - phase) * std::sin(4.0 * j * m.hy);
    return m;
}

struct FlowSample {
    Vec2 velocity;
    double vorticity;
};

// The flow FluidFlow gives at (p, t) between the fields `start` at t0 and `end` at t1.
FlowSample blended(const MacVelocity& startField, const MacVelocity& endField, double t0, double t1, Vec2 p,
                   double t)
{
    const StreamField start = StreamField::of(startField), end = StreamField::of(endField);
    const double span = t1 - t0;
    const double s = span > 0.0 ? std::clamp((t - t0) / span, 0.0, 1.0) : 1.0;
    return {start.velocity(p) + s * (end.velocity(p) - start.velocity(p)),
            start.vorticity(p) + s * (end.vorticity(p) - start.vorticity(p))};
}

// The largest difference between the stream function lattice `lattice` of the three in `stream`
// (start, halfway, end) and `expected`, relative to the largest |ψ|.
double streamDifference(const std::vector<double>& stream, int lattice, const StreamField& expected)
{
    double d = 0.0, size = 0.0;
    const std::size_t corners = expected.psi.size();
    for (std::size_t k = 0; k < corners; ++k) {
        d = std::max(d, std::abs(stream[lattice * corners + k] - expected.psi[k]));
        size = std::max(size, std::abs(expected.psi[k]));
    }
    return d / size;
}

} // namespace

class TestDeviceFluid : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void agreesWithReference_data();
    void agreesWithReference();
    void divergenceFreeAfterStylus_data();
    void divergenceFreeAfterStylus();
    void stillFluidStaysStill_data();
    void stillFluidStaysStill();
    void stylusMovesFluidInPenDirection_data();
    void stylusMovesFluidInPenDirection();
    void viscosityDampsEnergy_data();
    void viscosityDampsEnergy();
    void highViscosityStopsRightAfterStroke();
    void degenerateStrokesDoNothing();
    void deterministicAndSnapshotsReplay();
    void bindingHoldsStepStartAndEnd_data();
    void bindingHoldsStepStartAndEnd();
    void contoursMoveAlikeWithEitherFluid();
    void flowSamplingMatchesReference();
    void laneSamplingMatchesOnePoint();
    void badInputThrows();

private:
    std::vector<double> sampleOnDevice(const FlowBinding& flow, const std::vector<float>& points);
    std::vector<double> sampleLanesOnDevice(const FlowBinding& flow, const std::vector<float>& points);
    std::vector<double> runSampler(const FlowBinding& flow, const std::vector<float>& points, const char* kernel,
                                   const char* name, int workItems);

    std::optional<Device> m_device;
};

void TestDeviceFluid::initTestCase()
{
    try {
        m_device = Device::open();
    } catch (const DeviceError& e) {
        QSKIP(qPrintable(QString("no OpenCL device: %1").arg(e.what())));
    }
}

void TestDeviceFluid::agreesWithReference_data()
{
    QTest::addColumn<FluidSettings>("settings");
    QTest::addColumn<int>("steps");
    QTest::newRow("64x64, MacCormack") << settings(64, 64, 1.0, 1.0, 5e-4) << 50;
    QTest::newRow("64x64, semi-Lagrangian")
        << settings(64, 64, 1.0, 1.0, 5e-4, Advection::SemiLagrangian) << 50;
    QTest::newRow("64x64, inviscid") << settings(64, 64, 1.0, 1.0, 0.0) << 50;
    // The motion dies within a few steps of the last stroke: compared right after it.
    QTest::newRow("64x64, nu = 10") << settings(64, 64, 1.0, 1.0, 10.0) << 15;
    QTest::newRow("96x48 on 2x1, MacCormack") << settings(96, 48, 2.0, 1.0, 5e-4) << 50;
    QTest::newRow("96x48 on 2x1, semi-Lagrangian")
        << settings(96, 48, 2.0, 1.0, 5e-4, Advection::SemiLagrangian) << 50;
    QTest::newRow("128x128, nu = 0.05") << settings(128, 128, 1.0, 1.0, 0.05) << 50;
}

// Strokes in the first 15 steps: the float32 device and the double reference stay within 1e-3 of
// the largest velocity of each other (measured: a few 1e-6).
void TestDeviceFluid::agreesWithReference()
{
    QFETCH(FluidSettings, settings);
    QFETCH(int, steps);
    DeviceFluid device(*m_device, settings);
    FluidSolver reference(settings);
    run(device, 0, steps);
    run(reference, 0, steps);
    const MacVelocity expected = reference.velocity();
    const double error = maxDifference(device.readVelocity(), expected) / maxComponent(expected);
    QVERIFY(maxComponent(expected) > 0.1);
    QVERIFY2(error < 1e-3, qPrintable(QString("max difference %1 of max |u|").arg(error)));
}

void TestDeviceFluid::divergenceFreeAfterStylus_data()
{
    QTest::addColumn<FluidSettings>("settings");
    QTest::newRow("64x64 on 1x1") << settings(64, 64, 1.0, 1.0, 5e-4);
    QTest::newRow("96x48 on 2x1") << settings(96, 48, 2.0, 1.0, 5e-4);
    QTest::newRow("40x100 on 1x3") << settings(40, 100, 1.0, 3.0, 5e-4);
    QTest::newRow("64x16 on 1x1, thin cells") << settings(64, 16, 1.0, 1.0, 5e-4);
    QTest::newRow("256x256, inviscid") << settings(256, 256, 1.0, 1.0, 0.0);
    FluidSettings loose = settings(64, 64, 1.0, 1.0, 5e-4);
    loose.pressureTolerance = 1e-2;
    QTest::newRow("64x64, loose tolerance") << loose;
}

// After every projection max |div u| <= max(pressure tolerance, kDivergenceBound * S).
void TestDeviceFluid::divergenceFreeAfterStylus()
{
    QFETCH(FluidSettings, settings);
    DeviceFluid fluid(*m_device, settings);
    for (int k = 0; k < 15; ++k) {
        stir(fluid, k);
        fluid.step(kDt);
        const MacVelocity m = fluid.readVelocity();
        const double bound =
            std::max(settings.pressureTolerance, kDivergenceBound * divergenceScale(m));
        QVERIFY2(fluid.maxDivergence() <= bound,
                 qPrintable(QString("step %1: max |div u| = %2, bound %3")
                                .arg(k)
                                .arg(fluid.maxDivergence())
                                .arg(bound)));
    }
    QVERIFY(onReference(fluid).maxSpeed() > 0.1);
}

void TestDeviceFluid::stillFluidStaysStill_data()
{
    QTest::addColumn<Advection>("advection");
    QTest::addColumn<double>("viscosity");
    QTest::newRow("semi-Lagrangian, inviscid") << Advection::SemiLagrangian << 0.0;
    QTest::newRow("MacCormack, inviscid") << Advection::MacCormack << 0.0;
    QTest::newRow("MacCormack, viscous") << Advection::MacCormack << 0.05;
}

void TestDeviceFluid::stillFluidStaysStill()
{
    QFETCH(Advection, advection);
    QFETCH(double, viscosity);
    DeviceFluid fluid(*m_device, settings(36, 24, 1.5, 1.0, viscosity, advection));
    for (int k = 0; k < 100; ++k)
        fluid.step(kDt);
    const MacVelocity m = fluid.readVelocity();
    QVERIFY(isZero(m.u));
    QVERIFY(isZero(m.v));
}

void TestDeviceFluid::stylusMovesFluidInPenDirection_data()
{
    QTest::addColumn<Vec2>("direction");
    QTest::newRow("right") << Vec2{1.0, 0.0};
    QTest::newRow("left") << Vec2{-1.0, 0.0};
    QTest::newRow("up") << Vec2{0.0, -1.0};
    QTest::newRow("down") << Vec2{0.0, 1.0};
    QTest::newRow("diagonal") << glm::normalize(Vec2{1.0, 1.0});
}

void TestDeviceFluid::stylusMovesFluidInPenDirection()
{
    QFETCH(Vec2, direction);
    DeviceFluid fluid(*m_device, settings(96, 48, 2.0, 1.0, 5e-4));
    const Vec2 center{1.0, 0.5};
    fluid.addStylus(center - 0.1 * direction, center + 0.1 * direction, 0.05, 0.1);  // 2 units/s
    fluid.step(kDt);
    const Vec2 velocity = fluid.readVelocity().sample(center);
    const double along = glm::dot(velocity, direction);
    const double across = std::abs(velocity.x * direction.y - velocity.y * direction.x);
    QVERIFY2(along > 0.05, qPrintable(QString("along the pen: %1").arg(along)));
    QVERIFY2(across < 0.01 * along, qPrintable(QString("across the pen: %1").arg(across)));
}

void TestDeviceFluid::viscosityDampsEnergy_data()
{
    QTest::addColumn<Advection>("advection");
    QTest::addColumn<double>("viscosity");
    for (const double viscosity : {5e-4, 0.05, 10.0}) {
        QTest::addRow("MacCormack, nu = %g", viscosity) << Advection::MacCormack << viscosity;
        QTest::addRow("semi-Lagrangian, nu = %g", viscosity)
            << Advection::SemiLagrangian << viscosity;
    }
}

void TestDeviceFluid::viscosityDampsEnergy()
{
    QFETCH(Advection, advection);
    QFETCH(double, viscosity);
    DeviceFluid fluid(*m_device, settings(32, 32, 1.0, 1.0, viscosity, advection));
    for (int k = 0; k < 6; ++k) {
        stir(fluid, k);
        fluid.step(kDt);
    }
    double energy = onReference(fluid).kineticEnergy();
    QVERIFY(energy > 0.0);
    for (int k = 0; k < 40; ++k) {
        fluid.step(kDt);
        const double next = onReference(fluid).kineticEnergy();
        QVERIFY2(next < energy,
                 qPrintable(QString("step %1: %2 -> %3").arg(k).arg(energy).arg(next)));
        energy = next;
    }
}

// "Shape design" (paper §5.2): at nu = 10 the motion dies right after the stroke (the reasoning
// is in tst_fluid.cpp).
void TestDeviceFluid::highViscosityStopsRightAfterStroke()
{
    DeviceFluid fluid(*m_device, settings(64, 64, 1.0, 1.0, 10.0));
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, 0.1);
    fluid.step(kDt);
    const double peak = onReference(fluid).maxSpeed();
    QVERIFY(peak > 0.0);
    for (int k = 0; k < 8; ++k)
        fluid.step(kDt);
    const double left = onReference(fluid).maxSpeed();
    QVERIFY2(left < 0.01 * peak, qPrintable(QString("%1 of the peak speed left").arg(left / peak)));
}

void TestDeviceFluid::degenerateStrokesDoNothing()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    DeviceFluid fluid(*m_device, settings(32, 32, 1.0, 1.0, 5e-4));
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, 0.0);  // a jump
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, -1.0);
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, nan);
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, nan, 0.1);
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.0, 0.1);
    fluid.addStylus({nan, 0.5}, {0.8, 0.5}, 0.05, 0.1);
    fluid.addStylus({0.2, 0.5}, {inf, 0.5}, 0.05, 0.1);
    fluid.addStylus({0.2, 0.5}, {0.8, 0.5}, 0.05, 1e-320);  // pen velocity overflows
    fluid.step(kDt);
    // Far outside the canvas, beyond float32: touches nothing either, and is safe.
    fluid.addStylus({1e300, -1e300}, {2e300, -1e300}, 1e299, 1.0);
    fluid.addStylus({1e30, 0.5}, {2e30, 0.5}, 0.05, 1e30);
    fluid.step(kDt);
    const MacVelocity m = fluid.readVelocity();
    QVERIFY(isZero(m.u));
    QVERIFY(isZero(m.v));
}

void TestDeviceFluid::deterministicAndSnapshotsReplay()
{
    const FluidSettings s = settings(96, 48, 2.0, 1.0, 5e-3);
    DeviceFluid a(*m_device, s), b(*m_device, s);
    run(a, 0, 10);
    run(b, 0, 10);
    const MacVelocity snapshot = a.readVelocity();
    QVERIFY(snapshot.u == b.readVelocity().u && snapshot.v == b.readVelocity().v);

    // A snapshot restored into a fresh solver and into the running one replays bit for bit.
    DeviceFluid restored(*m_device, s);
    restored.writeVelocity(snapshot);
    a.writeVelocity(snapshot);
    QVERIFY(restored.readVelocity().u == snapshot.u);
    run(a, 10, 10);
    run(restored, 10, 10);
    const MacVelocity replayed = a.readVelocity();
    QVERIFY(replayed.u == restored.readVelocity().u && replayed.v == restored.readVelocity().v);
    QVERIFY(!isZero(replayed.u));
}

void TestDeviceFluid::bindingHoldsStepStartAndEnd_data()
{
    QTest::addColumn<FluidPlacement>("placement");
    QTest::newRow("DeviceFluid") << FluidPlacement::Device;
    QTest::newRow("HostFluid") << FluidPlacement::Host;
}

// The contour kernels get the stream functions of the step's start, of its middle and of its end
// (sim/StreamFunction), in float32, wherever the fluid is solved.
void TestDeviceFluid::bindingHoldsStepStartAndEnd()
{
    QFETCH(FluidPlacement, placement);
    const FluidSettings s = settings(24, 16, 1.5, 1.0, 5e-4);
    const std::unique_ptr<opencl::Fluid> fluid = opencl::makeFluid(*m_device, s, placement);
    fluid->writeVelocity(waves(s, 0.3));
    const StreamField before = StreamField::of(fluid->readVelocity());
    const std::size_t corners = before.psi.size();
    FlowBinding b = fluid->binding(0.0, 0.0);
    std::vector<double> stream = readBuffer(*m_device, b.field, 3 * corners);
    for (int lattice = 0; lattice < 3; ++lattice)
        QVERIFY(streamDifference(stream, lattice, before) < 1e-6);

    stir(*fluid, 0);
    fluid->step(kDt);
    b = fluid->binding(1.0, 1.0 + kDt);
    const StreamField after = StreamField::of(fluid->readVelocity());
    stream = readBuffer(*m_device, b.field, 3 * corners);
    QVERIFY(streamDifference(stream, 2, before) > 1e-3);  // the step changed the field
    QVERIFY(streamDifference(stream, 0, before) < 1e-6);
    QVERIFY(streamDifference(stream, 1, StreamField::average(before, after)) < 1e-6);
    QVERIFY(streamDifference(stream, 2, after) < 1e-6);
    QCOMPARE(b.nx, s.nx);
    QCOMPARE(b.ny, s.ny);
    QCOMPARE(b.hx, float(s.width / s.nx));
    QCOMPARE(b.t0, 1.0);
    QCOMPARE(b.t1, 1.0 + kDt);
}

// The OpenCL backend with the fluid on the device (float32) and on the host (double) moves the
// same ink alike: a row of discs stirred by the pen, then left to flow. The two fluids differ by
// float32 rounding (agreesWithReference), so the contours should agree far within the spacing.
void TestDeviceFluid::contoursMoveAlikeWithEitherFluid()
{
    SimulationSettings s;
    s.tracking.maxSpacing = 0.004;
    std::vector<std::vector<Contour>> results;
    for (const FluidPlacement placement : {FluidPlacement::Device, FluidPlacement::Host}) {
        opencl::OpenClSimulation simulation(s, std::nullopt, placement);
        for (int k = 0; k < 5; ++k)
            simulation.addRegion({circle({0.2 + 0.15 * k, 0.5}, 0.06, s.tracking.maxSpacing)});
        for (int step = 0; step < 60; ++step) {
            if (step < 20)
                simulation.stylus({0.1 + 0.04 * step, 0.45}, {0.14 + 0.04 * step, 0.55}, 0.08, kDt);
            simulation.step(kDt);
        }
        results.push_back(simulation.contours());
    }
    const std::vector<Contour>& device = results[0];
    const std::vector<Contour>& host = results[1];
    QCOMPARE(device.size(), host.size());
    double moved = 0.0, apart = 0.0;
    std::size_t deviceVertices = 0, hostVertices = 0;
    for (std::size_t c = 0; c < device.size(); ++c) {
        const Polygon start = circle({0.2 + 0.15 * double(c), 0.5}, 0.06, s.tracking.maxSpacing);
        moved = std::max(moved, hausdorffDistance(start, host[c].positions));
        apart = std::max(apart, hausdorffDistance(device[c].positions, host[c].positions));
        deviceVertices += device[c].positions.size();
        hostVertices += host[c].positions.size();
    }
    // Refinement decides near its thresholds: single contours differ by a few vertices either way.
    QVERIFY2(std::abs(double(deviceVertices) / double(hostVertices) - 1.0) < 0.02,
             qPrintable(QString("%1 and %2 vertices").arg(deviceVertices).arg(hostVertices)));
    QVERIFY2(moved > 0.02, qPrintable(QString("the pen moved the ink only %1").arg(moved)));
    QVERIFY2(apart < 1e-4, qPrintable(QString("the two fluids moved the ink %1 apart").arg(apart)));
}

// flowVelocity and flowVorticity of flow_fluid.cl against StreamField::velocity and ::vorticity of
// the same float32 fields, blended in time as FluidFlow blends them: everywhere on the canvas,
// outside it (mirrored) and at times before, inside and after the step, and with t1 == t0 (the
// end field alone).
void TestDeviceFluid::flowSamplingMatchesReference()
{
    const FluidSettings s = settings(20, 12, 2.0, 0.75, 0.0);
    DeviceFluid fluid(*m_device, s);
    fluid.writeVelocity(waves(s, 0.0));
    const MacVelocity start = fluid.readVelocity();
    fluid.addStylus({0.5, 0.3}, {1.5, 0.4}, 0.2, 0.2);
    fluid.step(kDt);
    const MacVelocity end = fluid.readVelocity();
    const double speed = std::max(maxComponent(start), maxComponent(end));

    std::vector<float> points;  // x, y, t
    const double t0 = 0.25;
    for (int k = 0; k < 600; ++k) {
        const double x = -0.2 + 2.4 * (k % 29) / 28.0, y = -0.1 + 0.95 * (k % 31) / 30.0;
        points.insert(points.end(), {float(x), float(y), float(t0 + 0.05 * ((k % 7) - 1))});
    }
    for (const double t1 : {0.45, t0}) {
        // The samplers take how far through the span a time is; an empty span means its end.
        std::vector<float> fractions = points;
        for (std::size_t k = 2; k < fractions.size(); k += 3)
            fractions[k] = t1 > t0 ? float((points[k] - t0) / (t1 - t0)) : 0.0f;
        const std::vector<double> got = sampleOnDevice(fluid.binding(t0, t1), fractions);
        for (std::size_t k = 0; k < points.size(); k += 3) {
            const Vec2 p{points[k], points[k + 1]};
            const FlowSample expected = blended(start, end, t0, t1, p, points[k + 2]);
            const double velocityError = std::max(std::abs(got[k] - expected.velocity.x),
                                                  std::abs(got[k + 1] - expected.velocity.y));
            const double vorticityError = std::abs(got[k + 2] - expected.vorticity);
            QVERIFY2(velocityError < 1e-5 * speed && vorticityError < 1e-5 * speed / start.hx,
                     qPrintable(QString("at (%1, %2, t = %3), step [%4, %5]: velocity off by %6, "
                                        "vorticity by %7")
                                    .arg(p.x)
                                    .arg(p.y)
                                    .arg(points[k + 2])
                                    .arg(t0)
                                    .arg(t1)
                                    .arg(velocityError)
                                    .arg(vorticityError)));
        }
    }
}

// The flow and its vorticity at each (x, y, s) of `points`, s how far through the binding's span,
// sampled by flow_fluid.cl as the contour kernels sample it.
std::vector<double> TestDeviceFluid::sampleOnDevice(const FlowBinding& flow,
                                                    const std::vector<float>& points)
{
    return runSampler(flow, points, R"(
        __kernel void sample(FLOW_ARGS, __global const float* points, int n, __global float* out)
        {
            const int k = 3 * get_global_id(0);
            if (k >= 3 * n)
                return;
            const float2 p = (float2)(points[k], points[k + 1]);
            const float2 velocity = flowVelocity(FLOW_PASS, p, points[k + 2]);
            out[k] = velocity.x;
            out[k + 1] = velocity.y;
            out[k + 2] = flowVorticity(FLOW_PASS, p, points[k + 2]);
        })",
                      "sample", int(points.size() / 3));
}

// Builds `kernel` (named `name`, taking the flow, the points, the work-item count and the output)
// after flow_fluid.cl and runs it over `workItems` on `points`; returns what it wrote, as many
// floats as there are in `points`.
std::vector<double> TestDeviceFluid::runSampler(const FlowBinding& flow, const std::vector<float>& points,
                                                const char* kernel, const char* name, int workItems)
{
    const std::string source = opencl::joinedKernelSources({"flow.h.cl", "flow_fluid.cl"}) + kernel;
    cl::Kernel sample(m_device->build(source, std::string("the test kernel ") + name), name);
    const std::size_t bytes = points.size() * sizeof(float);
    cl::Buffer in(m_device->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bytes,
                  const_cast<float*>(points.data()));
    cl::Buffer out(m_device->context(), CL_MEM_WRITE_ONLY, bytes);
    opencl::launch(m_device->queue(), sample, std::size_t(workItems), flow, in, workItems, out);
    return readBuffer(*m_device, out, points.size());
}

// flowVelocityLanes and flowVorticityLanes, which advect the contours and set their spacing eight
// vertices at a time, give bit for bit what flowVelocity and flowVorticity give for each of their
// lanes, inside the canvas and clamped outside it (also from NaN, infinite and huge positions,
// which must stay on the lattice), at every s that RK4 asks for and between them.
void TestDeviceFluid::laneSamplingMatchesOnePoint()
{
    const FluidSettings s = settings(20, 12, 2.0, 0.75, 0.0);
    DeviceFluid fluid(*m_device, s);
    fluid.writeVelocity(waves(s, 0.0));
    fluid.addStylus({0.5, 0.3}, {1.5, 0.4}, 0.2, 0.2);
    fluid.step(kDt);
    const FlowBinding flow = fluid.binding(0.0, kDt);

    std::vector<float> points;  // x, y, s; the eight points of a lane group share their s
    const std::array<float, 5> fractions{0.0f, 0.5f, 1.0f, 0.25f, 1.5f};
    for (int k = 0; k < 8 * 40; ++k) {
        const double x = -0.2 + 2.4 * (k % 29) / 28.0, y = -0.1 + 0.95 * (k % 31) / 30.0;
        points.insert(points.end(), {float(x), float(y), fractions[std::size_t(k / 8) % fractions.size()]});
    }
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const std::array<std::array<float, 2>, 8> bad{{{nan, 0.3f}, {0.3f, nan}, {inf, 0.2f}, {-inf, 0.5f},
                                                  {1e30f, -1e30f}, {0.2f, inf}, {nan, nan}, {-1e30f, 0.4f}}};
    for (const float fraction : fractions)
        for (const auto& [x, y] : bad)
            points.insert(points.end(), {x, y, fraction});
    const std::vector<double> one = sampleOnDevice(flow, points), lanes = sampleLanesOnDevice(flow, points);
    for (std::size_t k = 0; k < points.size(); k += 3) {
        QVERIFY2(lanes[k] == one[k] && lanes[k + 1] == one[k + 1] && lanes[k + 2] == one[k + 2],
                 qPrintable(QString("at (%1, %2, s = %3): lanes give (%4, %5), vorticity %6; one point "
                                    "(%7, %8), vorticity %9")
                                .arg(points[k])
                                .arg(points[k + 1])
                                .arg(points[k + 2])
                                .arg(lanes[k])
                                .arg(lanes[k + 1])
                                .arg(lanes[k + 2])
                                .arg(one[k])
                                .arg(one[k + 1])
                                .arg(one[k + 2])));
    }
}

// The flow and its vorticity at each (x, y, s) of `points` (3 floats each, 8 points a group sharing
// the s of the first), sampled by flowVelocityLanes and flowVorticityLanes a group at a time.
std::vector<double> TestDeviceFluid::sampleLanesOnDevice(const FlowBinding& flow, const std::vector<float>& points)
{
    return runSampler(flow, points, R"(
        __kernel void sampleLanes(FLOW_ARGS, __global const float* points, int groups, __global float* out)
        {
            const int g = get_global_id(0);
            if (g >= groups)
                return;
            float xs[VF_LANES], ys[VF_LANES];
            for (int k = 0; k < VF_LANES; ++k) {
                xs[k] = points[3 * (VF_LANES * g + k)];
                ys[k] = points[3 * (VF_LANES * g + k) + 1];
            }
            const floatv x = VF_VLOAD(0, xs), y = VF_VLOAD(0, ys);
            const float s = points[3 * VF_LANES * g + 2];
            floatv u, v;
            flowVelocityLanes(FLOW_PASS, x, y, s, &u, &v);
            float us[VF_LANES], vs[VF_LANES], ws[VF_LANES];
            VF_VSTORE(u, 0, us);
            VF_VSTORE(v, 0, vs);
            VF_VSTORE(flowVorticityLanes(FLOW_PASS, x, y, s), 0, ws);
            for (int k = 0; k < VF_LANES; ++k) {
                out[3 * (VF_LANES * g + k)] = us[k];
                out[3 * (VF_LANES * g + k) + 1] = vs[k];
                out[3 * (VF_LANES * g + k) + 2] = ws[k];
            }
        })",
                      "sampleLanes", int(points.size() / 3 / opencl::lanes));
}

void TestDeviceFluid::badInputThrows()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto throwsFor = [&](auto change) {
        FluidSettings s;
        change(s);
        try {
            DeviceFluid fluid(*m_device, s);
        } catch (const std::invalid_argument& e) {
            return QString(e.what()).startsWith("FluidSettings: ");
        }
        return false;
    };
    QVERIFY(throwsFor([](FluidSettings& s) { s.nx = 3; }));
    QVERIFY(throwsFor([](FluidSettings& s) { s.ny = 100000; }));
    QVERIFY(throwsFor([&](FluidSettings& s) { s.width = nan; }));
    QVERIFY(throwsFor([](FluidSettings& s) { s.viscosity = -1e-6; }));
    QVERIFY(throwsFor([](FluidSettings& s) { s.pressureTolerance = 0.0; }));
    QVERIFY(!throwsFor([](FluidSettings& s) { s.nx = 4; s.ny = 4; s.viscosity = 0.0; }));

    DeviceFluid fluid(*m_device, settings(16, 8, 2.0, 1.0, 0.0));
    MacVelocity wrong = FluidSolver(settings(8, 16, 1.0, 2.0, 0.0)).velocity();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid.writeVelocity(wrong));
    wrong = fluid.readVelocity();
    wrong.u.pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid.writeVelocity(wrong));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid.step(0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fluid.step(nan));
}

QTEST_APPLESS_MAIN(TestDeviceFluid)
#include "tst_device_fluid.moc"
