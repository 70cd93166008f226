// The device prefix sum (sim/opencl/Scan) against the host's: one work-group in one launch for
// short arrays, blocks and levels for long ones, and the sizes around each boundary, for the counts
// (uint) and for the accumulation type (the arc lengths' sums: double where the device has fp64).
#include "sim/opencl/Device.h"
#include "sim/opencl/Launch.h"
#include "sim/opencl/Scan.h"

#include <QTest>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

using namespace vf::sim::opencl;

class TestDeviceScan : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void matchesHostPrefixSums_data();
    void matchesHostPrefixSums();

private:
    std::optional<Device> m_device;
};

void TestDeviceScan::initTestCase()
{
    try {
        m_device.emplace(Device::open());
    } catch (const DeviceError& e) {
        QSKIP(qPrintable(QStringLiteral("no OpenCL device: %1").arg(e.what())));
    }
}

void TestDeviceScan::matchesHostPrefixSums_data()
{
    QTest::addColumn<int>("count");
    QTest::addColumn<bool>("accumulation");  // the accumulation type rather than uint
    for (const bool accumulation : {false, true})
        for (const int count : {1, 2, 63, 64, 65, 511, 512, 513, 4096, 32767, 32768, 32769, 100000, 1 << 20})
            QTest::newRow(qPrintable(QStringLiteral("%1 %2").arg(accumulation ? "acc" : "uint").arg(count)))
                << count << accumulation;
}

namespace {

// `counts` scanned on the device as `type` (T on the host).
template <typename T>
std::vector<T> scanned(Device& device, const std::vector<cl_uint>& counts, const std::string& type)
{
    std::vector<T> values(counts.begin(), counts.end());
    cl::Buffer data(device.context(), CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, values.size() * sizeof(T),
                    values.data());
    Scan scan(device, type, sizeof(T), commonBuildOptions(device.hasFp64()));
    scan.exclusive(data, values.size());
    device.queue().enqueueReadBuffer(data, CL_TRUE, 0, values.size() * sizeof(T), values.data());
    return values;
}

} // namespace

// Exclusive sums in place of pseudo-random counts (0–9, as the counting kernels produce), the
// entry after the last one summed set to 0 so that it receives the total, as the callers do.
void TestDeviceScan::matchesHostPrefixSums()
{
    QFETCH(int, count);
    QFETCH(bool, accumulation);
    std::vector<cl_uint> values(std::size_t(count) + 1);
    std::uint32_t state = 12345;
    for (int i = 0; i < count; ++i) {
        state = state * 1664525u + 1013904223u;
        values[std::size_t(i)] = (state >> 16) % 10;
    }
    values.back() = 0;
    // Sums of at most 9·2^20 counts are exact in float and double too.
    std::vector<double> got;
    if (!accumulation) {
        const std::vector<cl_uint> sums = scanned<cl_uint>(*m_device, values, "uint");
        got.assign(sums.begin(), sums.end());
    } else if (m_device->hasFp64()) {
        got = scanned<double>(*m_device, values, "double");
    } else {
        const std::vector<float> sums = scanned<float>(*m_device, values, "float");
        got.assign(sums.begin(), sums.end());
    }
    double sum = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        QVERIFY2(got[i] == sum, qPrintable(QStringLiteral("entry %1: %2, expected %3").arg(i).arg(got[i]).arg(sum)));
        sum += values[i];
    }
}

QTEST_APPLESS_MAIN(TestDeviceScan)
#include "tst_device_scan.moc"
