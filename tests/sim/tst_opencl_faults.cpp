// The OpenCL backend's fault paths: each gives one clear first line (and, for a failed build, the
// compiler's log below it) as a DeviceError, which the callers turn into a fallback.
#include "Backends.h"
#include "Flows.h"

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

    void untranslatableExpressionIsNamed()
    {
        const QString what = failureOf([] { sim::opencl::OpenClSimulation(test::analyticSettings("log(x + 1)", "0", 0.01, true), std::nullopt); });
        QVERIFY2(what.contains(QStringLiteral("'log' is not supported by the OpenCL backend")), qPrintable(what));
    }
};

QTEST_APPLESS_MAIN(TestOpenClFaults)
#include "tst_opencl_faults.moc"
