// Analytic flows on the device: the translation of muparser expressions to OpenCL C must mean
// exactly what muparser means, on the host and in a kernel.
#include "sim/AnalyticFlow.h"
#include "sim/opencl/AnalyticSource.h"
#include "sim/opencl/Device.h"
#include "sim/opencl/KernelSources.h"

#include <QTest>

#include <random>

using namespace vf;
using sim::opencl::Expression;

namespace {

const char* const supported[] = {
    "-sin(pi*x)^2*sin(2*pi*y)*cos(pi*t/8)",
    "sin(pi*y)^2*sin(2*pi*x)*cos(pi*t/8)",
    "-(2*pi/3)*(y-0.5)",
    "2^3^0.5 - x^2 + -y^3",
    "exp(-((x-0.5)^2+(y-0.5)^2)/0.01)*abs(t-1)",
    "sqrt(x*x + y*y) / (1 + tan(0.3*x)) - 4e-2*x*-y",
    "+x - -y",
};

std::vector<std::array<double, 3>> samplePoints()
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<std::array<double, 3>> points;
    for (int i = 0; i < 64; ++i)
        points.push_back({unit(random), unit(random), 4.0 * unit(random)});
    return points;
}

} // namespace

class TestAnalyticSource : public QObject {
    Q_OBJECT

private slots:
    void meansWhatMuparserMeans_data()
    {
        QTest::addColumn<QString>("expression");
        for (const char* e : supported)
            QTest::newRow(e) << QString::fromLatin1(e);
    }

    void meansWhatMuparserMeans()
    {
        QFETCH(QString, expression);
        const std::string text = expression.toStdString();
        const sim::AnalyticFlow muparser(text, "0");
        const Expression translated = Expression::parse(text);
        for (const auto& [x, y, t] : samplePoints()) {
            const double expected = muparser.velocity({x, y}, t).x;
            QVERIFY2(std::abs(translated.evaluate(x, y, t) - expected) <= 1e-12 * (1 + std::abs(expected)),
                     qPrintable(QStringLiteral("at (%1, %2, %3)").arg(x).arg(y).arg(t)));
        }
    }

    void refusesWhatItCannotTranslate_data()
    {
        QTest::addColumn<QString>("expression");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("function") << "log(x)" << "'log'";
        QTest::newRow("two arguments") << "min(x, y)" << "'min'";
        QTest::newRow("ternary") << "x > 0.5 ? 1 : 0" << "'>'";
        QTest::newRow("unknown variable") << "z*2" << "'z'";
        QTest::newRow("unbalanced") << "sin(x" << "')'";
    }

    void refusesWhatItCannotTranslate()
    {
        QFETCH(QString, expression);
        QFETCH(QString, mentions);
        try {
            Expression::parse(expression.toStdString());
            QFAIL("expected UnsupportedExpression");
        } catch (const sim::opencl::UnsupportedExpression& e) {
            QVERIFY2(QString::fromUtf8(e.what()).contains(mentions), e.what());
        }
    }

    void kernelAgreesWithTheHost()
    {
        std::optional<sim::opencl::Device> device;
        try {
            device = sim::opencl::Device::open();
        } catch (const sim::opencl::DeviceError& e) {
            QSKIP(qPrintable(QStringLiteral("no OpenCL device: %1").arg(QString::fromUtf8(e.what()))));
        }
        const std::string u = supported[0], v = supported[4];
        const std::string source = sim::opencl::joinedKernelSources({"flow.h.cl"}) + sim::opencl::analyticFlowSource(u, v) +
                                   "__kernel void sample(FLOW_ARGS, __global const float4* in, __global float2* out)\n"
                                   "{ const size_t i = get_global_id(0);\n"
                                   "  out[i] = flowVelocity(FLOW_PASS, in[i].xy, in[i].z); }\n";
        cl::Program program = device->build(source, "analytic test flow");
        const auto points = samplePoints();
        std::vector<cl_float4> in;
        for (const auto& [x, y, t] : points)
            in.push_back({{float(x), float(y), float(t), 0.0f}});
        cl::Buffer input(device->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, in.size() * sizeof(cl_float4), in.data());
        cl::Buffer output(device->context(), CL_MEM_WRITE_ONLY, in.size() * sizeof(cl_float2));
        cl::Buffer placeholder(device->context(), CL_MEM_READ_ONLY, sizeof(float));
        cl::Kernel kernel(program, "sample");
        cl_uint arg = 0;
        kernel.setArg(arg++, placeholder);  // the flow's field, which an analytic flow ignores
        for (int i : {1, 1})
            kernel.setArg(arg++, i);
        for (float f : {1.0f, 1.0f, 0.0f, 1.0f})  // hx, hy, and the span [0, 1]: s is the time itself
            kernel.setArg(arg++, f);
        kernel.setArg(arg++, input);
        kernel.setArg(arg++, output);
        device->queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(in.size()));
        std::vector<cl_float2> out(in.size());
        device->queue().enqueueReadBuffer(output, CL_TRUE, 0, out.size() * sizeof(cl_float2), out.data());
        const Expression eu = Expression::parse(u), ev = Expression::parse(v);
        for (std::size_t i = 0; i < points.size(); ++i) {
            const auto& [x, y, t] = points[i];
            QVERIFY(std::abs(out[i].s[0] - eu.evaluate(x, y, t)) <= 1e-5 * (1 + std::abs(eu.evaluate(x, y, t))));
            QVERIFY(std::abs(out[i].s[1] - ev.evaluate(x, y, t)) <= 1e-5 * (1 + std::abs(ev.evaluate(x, y, t))));
        }
    }
};

QTEST_APPLESS_MAIN(TestAnalyticSource)
#include "tst_analytic_source.moc"
