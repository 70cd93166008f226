// The OpenCL backend's fault paths: each gives one clear first line (and, for a failed build, the
// compiler's log below it) as a DeviceError, which the callers turn into a fallback.
#include "Backends.h"
#include "Flows.h"

#include "sim/Geometry.h"
#include "sim/opencl/Device.h"
#include "sim/opencl/OpenClSimulation.h"

#include <QTest>

#include <cstdlib>

using namespace vf;
using sim::opencl::DeviceError;

namespace {

// What a DeviceError thrown by `action` says; empty when nothing was thrown.
template <typename Action>
QString failureOf(Action action)
{
    try {
        action();
    } catch (const DeviceError& e) {
        return QString::fromUtf8(e.what());
    }
    return {};
}

} // namespace

class TestOpenClFaults : public QObject {
    Q_OBJECT

private slots:
    void init() { VF_REQUIRE_BACKEND(QStringLiteral("opencl")); }

    void brokenKernelReportsItsLog()
    {
        const QString what = failureOf([] { sim::opencl::Device::open().build("__kernel void k(global float* x) { x[0] = ; }", "broken.cl"); });
        QVERIFY2(what.section('\n', 0, 0).contains(QStringLiteral("OpenCL kernel build failed for broken.cl")), qPrintable(what));
        QVERIFY2(what.section('\n', 1).contains(QStringLiteral("error")), "the compiler's log must follow the first line");
    }

    void missingDeviceIsNamed()
    {
        const QString what = failureOf([] { sim::opencl::Device::open(999); });
        QVERIFY2(what.startsWith(QStringLiteral("there is no OpenCL device 999")), qPrintable(what));
        QVERIFY(!what.contains('\n'));
    }

    void badDeviceVariableIsNamed()
    {
        qputenv("VF_OPENCL_DEVICE", "first");
        const QString what = failureOf([] { sim::opencl::Device::open(); });
        qunsetenv("VF_OPENCL_DEVICE");
        QVERIFY2(what.contains(QStringLiteral("VF_OPENCL_DEVICE='first'")), qPrintable(what));
    }

    // VF_OPENCL_MAX_VERTICES makes the device's limit small: refinement past it stops as at
    // max_vertices (valid contours, the step says so), and a contour past it is one clear line.
    void deviceLimitStopsRefinement()
    {
        qputenv("VF_OPENCL_MAX_VERTICES", "150");
        sim::opencl::OpenClSimulation sim(test::singleVortex(8.0, 0.01, false), std::nullopt);
        qunsetenv("VF_OPENCL_MAX_VERTICES");
        QCOMPARE(sim.hardwareVertexLimit(), std::size_t(150));
        QVERIFY(sim.settings().tracking.maxVertices > 150);
        sim.addRegion({sim::circle({0.5, 0.75}, 0.15, 0.01)});  // about 95 vertices; the vortex stretches it
        bool stopped = false;
        for (int step = 0; step < 200 && !stopped; ++step)
            stopped = sim.step(0.02).vertexLimitReached;
        QVERIFY(stopped);
        QVERIFY(sim.vertexCount() <= 150);
        for (const sim::Contour& c : sim.contours())
            QVERIFY(c.positions.size() >= 3);

        const QString what = failureOf([&] { sim.addRegion({sim::circle({0.3, 0.3}, 0.1, 0.01)}); });
        QVERIFY2(what.startsWith(QStringLiteral("the OpenCL device cannot hold")), qPrintable(what));
        QVERIFY(!what.contains('\n'));
    }

    // A region whose contours the device cannot all hold is not added at all: no contour of it is
    // left behind (its region index would not exist), and the simulation goes on as before.
    void regionPastTheLimitIsNotAddedInPart()
    {
        qputenv("VF_OPENCL_MAX_VERTICES", "150");
        sim::opencl::OpenClSimulation sim(test::rotation(1.0, 0.01, false), std::nullopt);
        qunsetenv("VF_OPENCL_MAX_VERTICES");
        sim.addRegion({sim::circle({0.5, 0.5}, 0.05, 0.01)});  // about 32 vertices
        const sim::SimulationState before = sim.snapshot();
        const QString what = failureOf([&] {
            sim.addRegion({sim::circle({0.3, 0.3}, 0.05, 0.01), sim::circle({0.7, 0.7}, 0.15, 0.01)});  // 32 + 95
        });
        QVERIFY2(what.startsWith(QStringLiteral("the OpenCL device cannot hold")), qPrintable(what));
        QCOMPARE(sim.regionCount(), 1);
        QVERIFY(sim.snapshot() == before);
        sim.requestRegions();
        const auto copy = sim.takeRegions(true);
        QVERIFY(copy);
        QCOMPARE(copy->regions.size(), std::size_t(1));
        sim.step(0.02);
        QCOMPARE(sim.regionCount(), 1);
    }

    void badVertexCapIsNamed()
    {
        qputenv("VF_OPENCL_MAX_VERTICES", "lots");
        const QString what = failureOf([] { sim::opencl::OpenClSimulation(test::rotation(1.0, 0.01, false), std::nullopt); });
        qunsetenv("VF_OPENCL_MAX_VERTICES");
        QVERIFY2(what.contains(QStringLiteral("VF_OPENCL_MAX_VERTICES='lots' is not a positive vertex count")),
                 qPrintable(what));
    }

    void untranslatableExpressionIsNamed()
    {
        const QString what = failureOf([] { sim::opencl::OpenClSimulation(test::analyticSettings("log(x + 1)", "0", 0.01, true), std::nullopt); });
        QVERIFY2(what.contains(QStringLiteral("'log' is not supported by the OpenCL backend")), qPrintable(what));
    }
};

QTEST_APPLESS_MAIN(TestOpenClFaults)
#include "tst_opencl_faults.moc"
