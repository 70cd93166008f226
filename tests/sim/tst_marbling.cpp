// Fluid-driven tracking as a marbler uses it: stylus strokes through several inks, ink drops, and
// the vertex limit. On every backend.
#include "Backends.h"
#include "Flows.h"
#include "sim/Crossings.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>
#include <numbers>

using namespace vf;
using sim::Polygon;
using sim::Vec2;

namespace {

std::size_t crossings(const sim::Simulation& simulation)
{
    const auto regions = simulation.regions();
    std::vector<const Polygon*> all;
    for (const auto& region : regions)
        for (const Polygon& p : region)
            all.push_back(&p);
    return sim::countCrossings(all);
}

double regionArea(const sim::Simulation& simulation, int region)
{
    double area = 0.0;
    const auto regions = simulation.regions();
    for (const Polygon& p : regions[region])
        area += sim::signedArea(p);
    return area;
}

sim::SimulationSettings marblingSettings()
{
    sim::SimulationSettings s;  // fluid, 64×64, viscosity 5e-4, MacCormack
    s.tracking.maxSpacing = 0.004;
    return s;
}

// A pen moving in a straight line from `from` to `to` over [start, end], fed step by step.
struct Stroke {
    Vec2 from, to;
    double start, end, radius;

    void feed(sim::Simulation& simulation, double t, double dt) const
    {
        const double a = std::max(t, start), b = std::min(t + dt, end);
        if (b <= a)
            return;
        auto at = [&](double s) { return from + (s - start) / (end - start) * (to - from); };
        simulation.stylus(at(a), at(b), radius, b - a);
    }
};

} // namespace

class TestMarbling : public QObject {
    Q_OBJECT

private slots:
    void crossingStrokesKeepTopology_data();
    void crossingStrokesKeepTopology();

    void dropPushesInkOutwardAndKeepsArea_data();
    void dropPushesInkOutwardAndKeepsArea();

    void vertexLimitStopsCleanly_data();
    void vertexLimitStopsCleanly();
};

void TestMarbling::crossingStrokesKeepTopology_data()
{
    test::addBackendRows();
}

void TestMarbling::crossingStrokesKeepTopology()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    auto simulation = test::makeBackend(backend, marblingSettings());
    simulation->addRegion({sim::circle({0.35, 0.4}, 0.12, 0.004)});
    simulation->addRegion({sim::circle({0.65, 0.4}, 0.12, 0.004)});
    simulation->addRegion({sim::resample({{0.3, 0.62}, {0.7, 0.62}, {0.7, 0.72}, {0.3, 0.72}}, 0.004)});
    // Two diagonal strokes that cross in the middle, through all three regions, one after the other.
    const Stroke strokes[] = {{{0.2, 0.25}, {0.8, 0.75}, 0.0, 0.35, 0.035}, {{0.8, 0.25}, {0.2, 0.75}, 0.35, 0.7, 0.035}};
    const double dt = 0.004;
    std::size_t worst = 0;
    for (int step = 0; step < 200; ++step) {
        for (const Stroke& s : strokes)
            s.feed(*simulation, simulation->time(), dt);
        simulation->step(dt);
        if (step % 25 == 24)
            worst = std::max(worst, crossings(*simulation));
    }
    qInfo() << "vertices" << simulation->vertexCount() << "crossings (worst checkpoint)" << worst;
    QCOMPARE(worst, std::size_t(0));
    QCOMPARE(crossings(*simulation), std::size_t(0));
    QVERIFY2(simulation->vertexCount() > 3000, "the strokes should have stretched the contours");
}

void TestMarbling::dropPushesInkOutwardAndKeepsArea_data()
{
    test::addBackendColumn();
    QTest::addColumn<bool>("areaCorrection");
    QTest::addColumn<double>("tolerance");
    for (const QString& b : test::backendNames()) {
        QTest::newRow(qPrintable(b)) << b << false << 1e-3;
        // Exact to rounding: of doubles on the reference, of float32 positions on OpenCL.
        QTest::newRow(qPrintable(b + "/area-correction")) << b << true << (b == QLatin1String("opencl") ? 1e-6 : 1e-9);
    }
}

void TestMarbling::dropPushesInkOutwardAndKeepsArea()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    QFETCH(bool, areaCorrection);
    QFETCH(double, tolerance);
    auto settings = test::analyticSettings("0", "0", 0.004, true);  // still water: only drops move ink
    settings.tracking.areaCorrection = areaCorrection;
    auto simulation = test::makeBackend(backend, settings);
    const int ink = simulation->addRegion({sim::circle({0.32, 0.5}, 0.1, 0.004)});
    const double inkArea = regionArea(*simulation, ink);
    // Concentric drops at one centre, as in sumi-nagashi. Each later drop lands inside the earlier
    // ones, which become rings around it: painted in order, what shows of drop k is its contour's
    // area minus that of drop k + 1, and that must be the drop's true area π r² (its contour grows
    // by exactly what the push adds; the polygon of the newest drop is its chords' area).
    const Vec2 centre(0.5, 0.5);
    constexpr double radius = 0.06;
    std::vector<int> drops;
    std::vector<double> droppedArea;
    for (int k = 0; k < 3; ++k) {
        drops.push_back(simulation->drop(centre, radius).region);
        droppedArea.push_back(regionArea(*simulation, drops.back()));
    }
    const double outermost = std::sqrt(3.0) * radius;  // three discs of radius r fill radius r·√3
    const auto regions = simulation->regions();
    for (const Polygon& p : regions[ink])
        for (const Vec2& v : p)
            QVERIFY2(glm::distance(v, centre) >= outermost * (1 - 1e-3), "old ink must be pushed out of the drops");
    auto check = [&](const char* what, double area, double expected) {
        QVERIFY2(std::abs(area / expected - 1) < tolerance,
                 qPrintable(QStringLiteral("%1 area changed by %2").arg(what).arg(area / expected - 1)));
    };
    check("ink", regionArea(*simulation, ink), inkArea);
    for (std::size_t k = 0; k + 1 < drops.size(); ++k)
        check("ring", regionArea(*simulation, drops[k]) - regionArea(*simulation, drops[k + 1]),
              std::numbers::pi * radius * radius);
    check("innermost drop", regionArea(*simulation, drops.back()), droppedArea.back());
    QCOMPARE(crossings(*simulation), std::size_t(0));
}

void TestMarbling::vertexLimitStopsCleanly_data()
{
    test::addBackendRows();
}

void TestMarbling::vertexLimitStopsCleanly()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    auto settings = test::singleVortex(8.0, 1.0 / 256, false);
    settings.tracking.maxVertices = 600;
    auto simulation = test::makeBackend(backend, settings);
    simulation->addRegion({sim::circle({0.5, 0.75}, 0.15, 1.0 / 256)});
    bool reached = false;
    int steps = 0;
    while (!reached && steps < 400) {
        reached = simulation->step(0.02).vertexLimitReached;
        ++steps;
        QVERIFY(simulation->vertexCount() <= settings.tracking.maxVertices);
    }
    QVERIFY2(reached, "the stretching vortex must hit a 600-vertex limit");
    const Polygon contour = simulation->regions()[0][0];
    QCOMPARE(contour.size(), simulation->vertexCount());
    QVERIFY(sim::isSimple(contour));
}

QTEST_APPLESS_MAIN(TestMarbling)
#include "tst_marbling.moc"
