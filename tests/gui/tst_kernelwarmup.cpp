// A first launch on an OpenCL device whose kernels are not compiled yet (app/KernelWarmUp.h), as a
// new user has it: the window runs the reference backend and says so in the status bar while they
// compile, then moves to the device with the ink as it was; the next launch starts on the device.
#include "FindChild.h"
#include "WindowTest.h"
#include "app/KernelWarmUp.h"
#include "app/MainWindow.h"
#include "model/SceneFile.h"
#include "sim/opencl/Device.h"

#include <QDir>
#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

using namespace vf;
using namespace vf::app;

class TestKernelWarmUp : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_scenePath;

    // The window on the scene, paused, with its first frame shown.
    std::unique_ptr<MainWindow> openWindow()
    {
        auto w = std::make_unique<MainWindow>();
        if (!test::showActive(*w) || !w->openFile(m_scenePath))
            return nullptr;
        w->simulation().setPlaying(false);
        w->simulation().sync();
        return w;
    }

    static QString backendShown(MainWindow& w) { return test::child<QLabel>(w, "backendInUse")->text(); }

private slots:
    void initTestCase()
    {
        try {
            sim::opencl::Device::open();
        } catch (const sim::opencl::DeviceError& e) {
            QSKIP(qPrintable(QStringLiteral("no OpenCL device, so no kernels to compile: ") + QString::fromUtf8(e.what())));
        }
        QVERIFY(m_dir.isValid());
        test::useTestSettings("tst_kernelwarmup", m_dir);
        QSettings().setValue(QStringLiteral("simulation/backend"), QStringLiteral("opencl"));
        QDir(QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/kernels")).removeRecursively();
        model::Scene scene;
        scene.flow.gridX = scene.flow.gridY = 32;
        scene.tracking.maxSpacing = 0.01;
        scene.regions.push_back({QStringLiteral("ink"), QColor(0x1d, 0x35, 0x57), true, model::CircleShape{{0.5, 0.5}, 0.2}});
        m_scenePath = m_dir.filePath(QStringLiteral("small.vfscene"));
        QCOMPARE(model::writeSceneFile(scene, m_scenePath), QString());
    }

    void firstLaunchRunsOnTheReferenceUntilTheKernelsAreCompiled()
    {
        QVERIFY(!KernelWarmUp::isReady(std::nullopt));
        const std::unique_ptr<MainWindow> w = openWindow();
        QVERIFY(w);
        QSignalSpy messages(w->statusBar(), &QStatusBar::messageChanged);
        const std::size_t vertices = w->simulation().frame()->regions.at(0).at(0).size();
        QVERIFY2(backendShown(*w).startsWith(QStringLiteral("reference, until the OpenCL kernels are compiled")),
                 qPrintable(backendShown(*w)));

        QTRY_VERIFY_WITH_TIMEOUT(backendShown(*w).startsWith(QStringLiteral("opencl")), 180'000);
        QCOMPARE(w->simulation().frame()->regions.at(0).at(0).size(), vertices);  // the same ink, moved over
        QVERIFY(std::any_of(messages.begin(), messages.end(), [](const QList<QVariant>& m) {
            return m.front().toString().startsWith(QStringLiteral("OpenCL kernels compiled: running on opencl"));
        }));
        QVERIFY(KernelWarmUp::isReady(std::nullopt));
    }

    void laterLaunchesStartOnTheDevice()
    {
        const std::unique_ptr<MainWindow> w = openWindow();
        QVERIFY(w);
        QVERIFY2(backendShown(*w).startsWith(QStringLiteral("opencl")), qPrintable(backendShown(*w)));
    }
};

QTEST_MAIN(TestKernelWarmUp)
#include "tst_kernelwarmup.moc"
