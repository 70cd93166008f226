// Tests of the OpenCL fluid solver (sim/opencl/DeviceFluid) against the reference FluidSolver:
// agreement after strokes, the fields binding() hands to the contour kernels (from it and from
// HostFluid) and their sampling in flow_fluid.cl, contours moved by either fluid. The behaviour
// both solvers share (projection, walls, viscosity, the pen, determinism, bad input) is tested on
// both in tst_fluid.cpp.
// Skipped, with the reason, when no OpenCL device can be opened.
#include "Fluids.h"

#include "sim/FluidSolver.h"
#include "sim/StreamFunction.h"
#include "sim/TargetDrive.h"
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
using namespace vf::test;
using vf::sim::opencl::Device;
using vf::sim::opencl::DeviceError;
using vf::sim::opencl::DeviceFluid;
using vf::sim::opencl::FlowBinding;
using vf::sim::opencl::FluidPlacement;

Q_DECLARE_METATYPE(vf::sim::Advection)
Q_DECLARE_METATYPE(vf::sim::FluidSettings)
Q_DECLARE_METATYPE(vf::sim::opencl::FluidPlacement)

namespace {

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
    void bindingHoldsStepStartAndEnd_data();
    void bindingHoldsStepStartAndEnd();
    void bodyForceAgreesWithReference();
    void contoursMoveAlikeWithEitherFluid();
    void flowSamplingMatchesReference();
    void laneSamplingMatchesOnePoint();

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
    QTest::newRow("64x64, MacCormack") << fluidSettings(64, 64, 1.0, 1.0, 5e-4) << 50;
    QTest::newRow("64x64, semi-Lagrangian")
        << fluidSettings(64, 64, 1.0, 1.0, 5e-4, Advection::SemiLagrangian) << 50;
    QTest::newRow("64x64, inviscid") << fluidSettings(64, 64, 1.0, 1.0, 0.0) << 50;
    // The motion dies within a few steps of the last stroke: compared right after it.
    QTest::newRow("64x64, nu = 10") << fluidSettings(64, 64, 1.0, 1.0, 10.0) << 15;
    QTest::newRow("96x48 on 2x1, MacCormack") << fluidSettings(96, 48, 2.0, 1.0, 5e-4) << 50;
    QTest::newRow("96x48 on 2x1, semi-Lagrangian")
        << fluidSettings(96, 48, 2.0, 1.0, 5e-4, Advection::SemiLagrangian) << 50;
    QTest::newRow("128x128, nu = 0.05") << fluidSettings(128, 128, 1.0, 1.0, 0.05) << 50;
}

// Strokes in the first 15 steps: the float32 device and the double reference stay within 1e-3 of
// the largest velocity of each other (measured: a few 1e-6).
void TestDeviceFluid::agreesWithReference()
{
    QFETCH(FluidSettings, settings);
    QFETCH(int, steps);
    DeviceFluid device(*m_device, settings);
    FluidSolver reference(settings);
    stirAndRun(device, 0, steps);
    stirAndRun(reference, 0, steps);
    const MacVelocity expected = reference.velocity();
    const double error = maxDifference(device.readVelocity(), expected) / maxComponent(expected);
    QVERIFY(maxComponent(expected) > 0.1);
    QVERIFY2(error < 1e-3, qPrintable(QString("max difference %1 of max |u|").arg(error)));
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
    const FluidSettings s = fluidSettings(24, 16, 1.5, 1.0, 5e-4);
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
// A target drive's force (sim/TargetDrive) for 20 steps: the same field within 1e-3 of its
// largest velocity on the device and the reference, and none after the force stops but the decay.
void TestDeviceFluid::bodyForceAgreesWithReference()
{
    const FluidSettings settings = fluidSettings(64, 64, 1.0, 1.0, 5e-3);
    DeviceFluid device(*m_device, settings);
    FluidSolver reference(settings);
    const TargetDrive drive({{circle({0.7, 0.5}, 0.15, 0.01)}}, settings, {150.0, 3.0, 0.02});
    const BodyForce force = drive.force({{circle({0.3, 0.5}, 0.08, 0.01)}});
    for (int step = 0; step < 20; ++step) {
        device.addForce(force);
        reference.addForce(force);
        device.step(kDt);
        reference.step(kDt);
    }
    const MacVelocity expected = reference.velocity();
    QVERIFY2(maxComponent(expected) > 1e-3, qPrintable(QString::number(maxComponent(expected))));
    const double error = maxDifference(device.readVelocity(), expected) / maxComponent(expected);
    QVERIFY2(error < 1e-3, qPrintable(QString("max difference %1 of max |u|").arg(error)));
}

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
// outside it (the damped mirror image) and at times before, inside and after the step, and with t1 == t0 (the
// end field alone).
void TestDeviceFluid::flowSamplingMatchesReference()
{
    const FluidSettings s = fluidSettings(20, 12, 2.0, 0.75, 0.0);
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
    const FluidSettings s = fluidSettings(20, 12, 2.0, 0.75, 0.0);
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

QTEST_APPLESS_MAIN(TestDeviceFluid)
#include "tst_device_fluid.moc"
