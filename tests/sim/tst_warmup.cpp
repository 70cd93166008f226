// The OpenCL kernels' warm-up (sim/opencl/WarmUp.h): after it, a session of the kinds users make
// compiles no kernel, which on PoCL shows in its cache, a folder per kernel and local size. The
// test gives PoCL a cache folder of its own, so the warm-up starts from nothing.
#include "Backends.h"

#include "sim/Comb.h"
#include "sim/Whirl.h"
#include "sim/opencl/Device.h"
#include "sim/opencl/KernelSources.h"
#include "sim/opencl/OpenClSimulation.h"
#include "sim/opencl/WarmUp.h"

#include <QDirIterator>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

using namespace vf;

class TestWarmUp : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_cache;

    // The kernels PoCL has compiled for a launch: its <program>/<kernel>/<local size>/<kernel>.so files.
    QSet<QString> compiledKernels() const
    {
        QSet<QString> found;
        for (QDirIterator it(m_cache.path(), {QStringLiteral("*.so")}, QDir::Files, QDirIterator::Subdirectories); it.hasNext();) {
            const QString path = it.next();
            if (!path.contains(QStringLiteral("/0-0-0/")))  // a build for any local size, not a launch's
                found.insert(QDir(m_cache.path()).relativeFilePath(path));
        }
        return found;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_cache.isValid());
        qputenv("POCL_CACHE_DIR", m_cache.path().toLocal8Bit());  // before PoCL starts, at the first device
    }

    void init() { VF_REQUIRE_BACKEND(QStringLiteral("opencl")); }

    void identityNamesTheDeviceAndTheSources()
    {
        const std::string identity = sim::opencl::kernelIdentity(std::nullopt);
        QVERIFY(identity == sim::opencl::kernelIdentity(std::nullopt));
        const std::string_view digest = sim::opencl::kernelSourcesDigest();
        QCOMPARE(digest.size(), std::size_t(40));  // SHA-1, in hexadecimal
        QVERIFY2(identity.starts_with(digest), identity.c_str());
        QVERIFY2(identity.find(sim::opencl::Device::open().name()) != std::string::npos, identity.c_str());
    }

    void aStoppedWarmUpDoesNothing()
    {
        const std::atomic<bool> stop(true);
        sim::opencl::warmUpKernels(std::nullopt, stop);
        QVERIFY(compiledKernels().isEmpty());
    }

    void aSessionAfterTheWarmUpCompilesNoKernel()
    {
        if (!isPocl())
            QSKIP("the device is not PoCL's: only PoCL compiles at launch and shows its cache");
        sim::opencl::warmUpKernels(std::nullopt, std::atomic<bool>(false));
        const QSet<QString> warmed = compiledKernels();
        QVERIFY2(warmed.size() >= 15, qPrintable(QStringList(warmed.values()).join(' ')));

        // Default settings (area correction off), as a new scene has them, and one with it on.
        for (const bool areaCorrection : {false, true}) {
            sim::SimulationSettings settings;
            settings.tracking.areaCorrection = areaCorrection;
            sim::opencl::OpenClSimulation s(settings, std::nullopt);
            s.addRegion({sim::circle({0.3, 0.3}, 0.1, settings.tracking.maxSpacing)});
            const double h = 1e-7;  // an hourglass with a waist the pinch check cuts
            s.addRegion({{{0.7, 0.05}, {0.9, 0.05}, {0.8 + h, 0.15}, {0.9, 0.25}, {0.7, 0.25}, {0.8 - h, 0.15}}});
            s.drop({0.6, 0.5}, 0.1);
            s.drop({0.6, 0.5}, 0.05);
            for (int k = 0; k < 30; ++k) {
                s.stylus({0.1 + 0.02 * k, 0.5}, {0.12 + 0.02 * k, 0.5}, 0.03, 0.01);
                s.step(0.01);
            }
            s.applyMap(sim::Comb{{0.1, 0.4}, {0.9, 0.45}, 5, 0.05, 0.01});
            s.applyMap(sim::CircularComb{{0.5, 0.5}, 0.1, 3, 0.05, 0.01, 2.0});
            s.applyMap(sim::Swirl{{0.5, 0.5}, 0.3, 3.0});
            s.restore(s.snapshot());
            s.step(0.01);
            s.requestRegions();
            QVERIFY(s.takeRegions(true).has_value());
            QVERIFY(s.contours().size() >= 4);  // the circle, the two drops and the hourglass's halves
        }
        const QSet<QString> compiledLater = compiledKernels() - warmed;
        QVERIFY2(compiledLater.isEmpty(), qPrintable(QStringList(compiledLater.values()).join(' ')));
    }

private:
    static bool isPocl()
    {
        const cl::Platform platform(sim::opencl::Device::open().device().getInfo<CL_DEVICE_PLATFORM>());
        return platform.getInfo<CL_PLATFORM_NAME>().find("Portable Computing Language") != std::string::npos;
    }
};

QTEST_GUILESS_MAIN(TestWarmUp)
#include "tst_warmup.moc"
