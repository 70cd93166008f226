// The OpenCL backend against the reference: the same scenes, analytic and fluid, with strokes and
// drops, must give the same picture (Hausdorff within 1e-3 canvas units per contour) with vertex
// counts within 2%.
#include "Backends.h"
#include "Flows.h"

#include <QTest>

#include <functional>

using namespace vf;
using sim::Polygon;
using sim::Vec2;

namespace {

// A scene: settings, and what happens at each step (strokes, drops) before it is taken.
struct Scene {
    sim::SimulationSettings settings;
    std::function<void(sim::Simulation&)> setUp;
    std::function<void(sim::Simulation&, int step)> beforeStep = [](sim::Simulation&, int) {};
    int steps = 0;
    double dt = 0.0;
};

std::vector<std::vector<Polygon>> play(const QString& backend, const Scene& scene)
{
    auto simulation = test::makeBackend(backend, scene.settings);
    scene.setUp(*simulation);
    for (int step = 0; step < scene.steps; ++step) {
        scene.beforeStep(*simulation, step);
        simulation->step(scene.dt);
    }
    return simulation->regions();
}

sim::SimulationSettings stirredFluid()
{
    sim::SimulationSettings s;  // 64×64, viscosity 5e-4, MacCormack
    s.tracking.maxSpacing = 0.004;
    return s;
}

// A pen drawn straight from `from` to `to` during steps [first, last).
std::function<void(sim::Simulation&, int)> pen(Vec2 from, Vec2 to, int first, int last, double dt, double radius)
{
    return [=](sim::Simulation& s, int step) {
        if (step < first || step >= last)
            return;
        const double a = double(step - first) / (last - first), b = double(step + 1 - first) / (last - first);
        s.stylus(from + a * (to - from), from + b * (to - from), radius, dt);
    };
}

} // namespace

class TestEquivalence : public QObject {
    Q_OBJECT

private slots:
    void backendsAgree_data()
    {
        QTest::addColumn<int>("scene");
        QTest::newRow("slotted disk, rotation") << 0;
        QTest::newRow("single vortex to t = 2") << 1;
        QTest::newRow("drops on circles, still water") << 2;
        QTest::newRow("fluid, one stroke through two inks") << 3;
        QTest::newRow("fluid, drop then stroke") << 4;
    }

    void backendsAgree()
    {
        VF_REQUIRE_BACKEND(QStringLiteral("opencl"));
        QFETCH(int, scene);
        const Scene scenes[] = {
            {test::rotation(2.0, 1.0 / 256, true),
             [](sim::Simulation& s) { s.addRegion({sim::resample({{0.4, 0.6}, {0.6, 0.6}, {0.6, 0.9}, {0.52, 0.9}, {0.52, 0.7}, {0.48, 0.7}, {0.48, 0.9}, {0.4, 0.9}}, 1.0 / 256)}); },
             [](sim::Simulation&, int) {}, 100, 0.01},
            {test::singleVortex(8.0, 1.0 / 128, true),
             [](sim::Simulation& s) { s.addRegion({sim::circle({0.5, 0.75}, 0.15, 1.0 / 128)}); },
             [](sim::Simulation&, int) {}, 100, 0.02},
            {test::analyticSettings("0", "0", 0.004, true),
             [](sim::Simulation& s) {
                 s.addRegion({sim::circle({0.3, 0.5}, 0.1, 0.004)});
                 s.addRegion({sim::circle({0.7, 0.45}, 0.08, 0.004)});
                 s.drop({0.5, 0.5}, 0.08);
                 s.drop({0.5, 0.55}, 0.05);
             },
             [](sim::Simulation&, int) {}, 2, 0.01},
            {stirredFluid(),
             [](sim::Simulation& s) {
                 s.addRegion({sim::circle({0.4, 0.5}, 0.1, 0.004)});
                 s.addRegion({sim::circle({0.62, 0.5}, 0.08, 0.004)});
             },
             pen({0.2, 0.45}, {0.8, 0.55}, 0, 40, 0.005, 0.03), 60, 0.005},
            {stirredFluid(),
             [](sim::Simulation& s) {
                 s.addRegion({sim::circle({0.5, 0.5}, 0.12, 0.004)});
                 s.drop({0.5, 0.5}, 0.06);
             },
             pen({0.5, 0.2}, {0.5, 0.8}, 0, 40, 0.005, 0.03), 60, 0.005},
        };
        const auto reference = play(QStringLiteral("reference"), scenes[scene]);
        const auto device = play(QStringLiteral("opencl"), scenes[scene]);
        QCOMPARE(device.size(), reference.size());
        std::size_t referenceCount = 0, deviceCount = 0;
        double worst = 0.0;
        for (std::size_t r = 0; r < reference.size(); ++r) {
            QCOMPARE(device[r].size(), reference[r].size());
            for (std::size_t c = 0; c < reference[r].size(); ++c) {
                worst = std::max(worst, sim::hausdorffDistance(device[r][c], reference[r][c]));
                referenceCount += reference[r][c].size();
                deviceCount += device[r][c].size();
            }
        }
        const double countDifference = std::abs(double(deviceCount) / referenceCount - 1.0);
        qInfo() << "Hausdorff" << worst << "vertices" << referenceCount << "reference," << deviceCount << "opencl";
        QVERIFY2(worst <= 1e-3, qPrintable(QStringLiteral("Hausdorff %1").arg(worst)));
        QVERIFY2(countDifference <= 0.02, qPrintable(QStringLiteral("vertex counts differ by %1").arg(countDifference)));
    }
};

QTEST_APPLESS_MAIN(TestEquivalence)
#include "tst_equivalence.moc"
