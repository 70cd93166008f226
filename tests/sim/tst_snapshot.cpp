// Simulation::snapshot() and restore(): exact round trips, stepping on bit for bit, restoring into
// other settings and the other backend, and refusing states that cannot run. On every backend.
#include "Backends.h"
#include "Flows.h"
#include "sim/Comb.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

using namespace vf;
using sim::SimulationState;
using sim::Vec2;

namespace {

constexpr double kDt = 0.01;
constexpr double kSpacing = 0.008;

sim::SimulationSettings fluidSettings()
{
    sim::SimulationSettings s;  // fluid, 64×64, viscosity 5e-4, MacCormack
    s.tracking.maxSpacing = kSpacing;
    s.tracking.maxVertices = 20'000;
    return s;
}

// A pen crossing both inks over [0, 0.25] s, fed to whatever steps cover that time: a simulation
// restored mid-stroke gets the same input as the original.
void feedStroke(sim::Simulation& simulation)
{
    const Vec2 from(0.15, 0.45), to(0.85, 0.5);
    constexpr double start = 0.0, end = 0.25, radius = 0.04;
    const double a = std::max(simulation.time(), start), b = std::min(simulation.time() + kDt, end);
    if (b <= a)
        return;
    const auto at = [&](double t) { return from + (t - start) / (end - start) * (to - from); };
    simulation.stylus(at(a), at(b), radius, b - a);
}

void advance(sim::Simulation& simulation, int steps)
{
    for (int i = 0; i < steps; ++i) {
        feedStroke(simulation);
        simulation.step(kDt);
    }
}

// Two inks stirred by the pen, an ink drop among them, stirred on: moving fluid, stretched and
// refined contours, area targets raised by the drop, three regions. The pen is still moving.
std::unique_ptr<sim::Simulation> stirredScene(const QString& backend, const sim::SimulationSettings& settings)
{
    auto simulation = test::makeBackend(backend, settings);
    simulation->addRegion({sim::circle({0.35, 0.45}, 0.12, kSpacing)});
    simulation->addRegion({sim::circle({0.65, 0.45}, 0.12, kSpacing)});
    advance(*simulation, 8);
    simulation->drop({0.5, 0.6}, 0.06);
    advance(*simulation, 4);
    return simulation;
}

// Where two states first differ, or empty when they are equal bit for bit.
QString firstDifference(const SimulationState& a, const SimulationState& b)
{
    if (a.time != b.time)
        return QStringLiteral("time %1 vs %2").arg(a.time, 0, 'g', 17).arg(b.time, 0, 'g', 17);
    if (a.regionCount != b.regionCount)
        return QStringLiteral("region count %1 vs %2").arg(a.regionCount).arg(b.regionCount);
    if (a.contours.size() != b.contours.size())
        return QStringLiteral("%1 vs %2 contours").arg(a.contours.size()).arg(b.contours.size());
    for (std::size_t i = 0; i < a.contours.size(); ++i)
        if (a.contours[i] != b.contours[i])
            return QStringLiteral("contour %1 (%2 vs %3 vertices)")
                .arg(i)
                .arg(a.contours[i].positions.size())
                .arg(b.contours[i].positions.size());
    if (a.fluid != b.fluid)
        return QStringLiteral("fluid");
    if (a.pendingStylus != b.pendingStylus)
        return QStringLiteral("pending stylus");
    return {};
}

double largestMagnitude(const std::vector<double>& values)
{
    double m = 0.0;
    for (double x : values)
        m = std::max(m, std::abs(x));
    return m;
}

double largestDifference(const std::vector<double>& a, const std::vector<double>& b)
{
    double m = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        m = std::max(m, std::abs(a[i] - b[i]));
    return m;
}

std::size_t vertexCount(const SimulationState& state)
{
    std::size_t n = 0;
    for (const sim::Contour& c : state.contours)
        n += c.positions.size();
    return n;
}

double longestEdge(const std::vector<sim::Contour>& contours)
{
    double longest = 0.0;
    for (const sim::Contour& c : contours)
        for (std::size_t i = 0; i < c.positions.size(); ++i)
            longest = std::max(longest, glm::distance(c.positions[i], c.positions[(i + 1) % c.positions.size()]));
    return longest;
}

bool atRest(const sim::FluidState& fluid)
{
    return largestMagnitude(fluid.velocity.u) == 0.0 && largestMagnitude(fluid.velocity.v) == 0.0
           && largestMagnitude(fluid.pressure) == 0.0;
}

// The ways a state can be unfit to run, each applied to a valid state of fluidSettings().
using Defect = std::function<void(SimulationState&)>;

const std::map<QString, Defect>& defects()
{
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    constexpr double inf = std::numeric_limits<double>::infinity();
    static const std::map<QString, Defect> list{
        {"two vertices",
         [](SimulationState& s) {
             sim::Contour& c = s.contours[0];
             c.positions.resize(2);
             c.previous.resize(2);
             c.spacing.resize(2);
         }},
        {"short previous", [](SimulationState& s) { s.contours[0].previous.pop_back(); }},
        {"short spacing", [](SimulationState& s) { s.contours[1].spacing.pop_back(); }},
        {"NaN position", [](SimulationState& s) { s.contours[1].positions[5].x = nan; }},
        {"infinite previous", [](SimulationState& s) { s.contours[0].previous[0].y = inf; }},
        {"NaN target area", [](SimulationState& s) { s.contours[2].targetArea = nan; }},
        {"zero spacing", [](SimulationState& s) { s.contours[0].spacing[3] = 0.0; }},
        {"region past the count", [](SimulationState& s) { s.contours.back().region = s.regionCount; }},
        {"negative region", [](SimulationState& s) { s.contours[0].region = -1; }},
        {"negative region count",
         [](SimulationState& s) {
             s.contours.clear();
             s.regionCount = -1;
         }},
        {"NaN time", [](SimulationState& s) { s.time = nan; }},
        {"infinite time", [](SimulationState& s) { s.time = inf; }},
        {"fluid array size", [](SimulationState& s) { s.fluid->velocity.u.pop_back(); }},
        {"NaN fluid velocity", [](SimulationState& s) { s.fluid->velocity.v[100] = nan; }},
        {"infinite pressure", [](SimulationState& s) { s.fluid->pressure[7] = -inf; }},
    };
    return list;
}

} // namespace

class TestSnapshot : public QObject {
    Q_OBJECT

private slots:
    void roundTripIsExact_data() { test::addBackendRows(); }
    void roundTripIsExact();

    void restoredStepsOnIdentically_data() { test::addBackendRows(); }
    void restoredStepsOnIdentically();

    void pendingStylusIsKept_data() { test::addBackendRows(); }
    void pendingStylusIsKept();

    void analyticTimeIsRestored_data() { test::addBackendRows(); }
    void analyticTimeIsRestored();

    void otherBackendRestoresWithinRounding_data();
    void otherBackendRestoresWithinRounding();

    void otherTrackingRefinesOnNextStep_data() { test::addBackendRows(); }
    void otherTrackingRefinesOnNextStep();

    void otherFlowStartsAtRest_data() { test::addBackendRows(); }
    void otherFlowStartsAtRest();

    void statePastTheVertexLimitRestores_data() { test::addBackendRows(); }
    void statePastTheVertexLimitRestores();

    void regionsCopyIsItsMoment_data() { test::addBackendRows(); }
    void regionsCopyIsItsMoment();

    void invalidStateIsRefused_data();
    void invalidStateIsRefused();
};

void TestSnapshot::roundTripIsExact()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    auto original = stirredScene(backend, fluidSettings());
    feedStroke(*original);  // given, not yet stepped
    const SimulationState state = original->snapshot();
    QCOMPARE(state.regionCount, 3);
    QVERIFY2(state.fluid && largestMagnitude(state.fluid->velocity.u) > 0.01, "the pen must have stirred the fluid");
    QVERIFY(largestMagnitude(state.fluid->pressure) > 0.0);
    QCOMPARE(state.pendingStylus.size(), std::size_t(1));
    QVERIFY2(original->contours()[0].positions != original->contours()[0].previous, "the contours must have moved");
    for (const sim::Contour& c : state.contours)
        QVERIFY2(c.previous == c.positions, "a snapshot takes previous positions as the positions");

    auto restored = test::makeBackend(backend, fluidSettings());
    restored->restore(state);
    QCOMPARE(firstDifference(restored->snapshot(), state), QString());
    QCOMPARE(firstDifference(original->snapshot(), state), QString());  // taking it changed nothing
    QCOMPARE(restored->vertexCount(), original->vertexCount());
    QCOMPARE(restored->regionCount(), 3);
    QCOMPARE(restored->time(), original->time());
    QVERIFY(restored->contours() == state.contours);
}

void TestSnapshot::restoredStepsOnIdentically()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    auto original = stirredScene(backend, fluidSettings());
    const SimulationState state = original->snapshot();
    // Stroke, drop, comb and stroke again, on both: every path through a step after the restore,
    // the original from its live previous positions, the restored one from the settled ones.
    const auto goOn = [](sim::Simulation& s) {
        advance(s, 5);
        s.drop({0.3, 0.3}, 0.05);
        advance(s, 2);
        QVERIFY(s.applyMap(sim::Comb{{0.2, 0.5}, {0.3, 0.52}, 2, 0.1, 0.02}));
        advance(s, 3);
    };
    goOn(*original);
    auto restored = test::makeBackend(backend, fluidSettings());
    restored->restore(state);
    goOn(*restored);
    const std::vector<sim::Contour> contours = original->contours();
    QVERIFY2(contours.size() == state.contours.size() + 1 && contours[0] != state.contours[0],
             "the steps after the snapshot must have changed the contours");
    QVERIFY2(restored->contours() == contours, "the contours must step on bit for bit alike");
    QCOMPARE(firstDifference(restored->snapshot(), original->snapshot()), QString());
}

void TestSnapshot::pendingStylusIsKept()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    auto original = stirredScene(backend, fluidSettings());
    const sim::StylusSegment pen{{0.2, 0.2}, {0.8, 0.3}, 0.05, kDt};
    original->stylus(pen.from, pen.to, pen.radius, pen.duration);
    const SimulationState state = original->snapshot();
    QVERIFY(!state.pendingStylus.empty());
    QCOMPARE(state.pendingStylus.back(), pen);

    auto restored = test::makeBackend(backend, fluidSettings());
    restored->restore(state);
    SimulationState withoutPen = state;
    withoutPen.pendingStylus.clear();
    auto penless = test::makeBackend(backend, fluidSettings());
    penless->restore(withoutPen);
    for (sim::Simulation* s : {original.get(), restored.get(), penless.get()})
        s->step(kDt);
    QCOMPARE(firstDifference(restored->snapshot(), original->snapshot()), QString());
    QVERIFY2(penless->snapshot().fluid != original->snapshot().fluid, "the pending pen must have acted");
}

void TestSnapshot::analyticTimeIsRestored()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    const sim::SimulationSettings settings = test::singleVortex(4.0, 0.01, true);  // reverses at t = 2
    auto original = test::makeBackend(backend, settings);
    original->addRegion({sim::circle({0.5, 0.75}, 0.15, 0.01)});
    for (int i = 0; i < 30; ++i)
        original->step(0.05);
    const SimulationState state = original->snapshot();
    QVERIFY(!state.fluid);
    QCOMPARE(state.time, original->time());

    auto restored = test::makeBackend(backend, settings);
    restored->restore(state);
    QCOMPARE(restored->time(), state.time);
    SimulationState atZero = state;
    atZero.time = 0.0;
    auto restarted = test::makeBackend(backend, settings);
    restarted->restore(atZero);
    for (int i = 0; i < 10; ++i)
        for (sim::Simulation* s : {original.get(), restored.get(), restarted.get()})
            s->step(0.05);
    QCOMPARE(firstDifference(restored->snapshot(), original->snapshot()), QString());
    // The flow reverses between t = 1.5 and 2: from t = 0 it would not, so time must carry over.
    QVERIFY(restarted->contours() != original->contours());
}

void TestSnapshot::otherBackendRestoresWithinRounding_data()
{
    QTest::addColumn<QString>("from");
    QTest::addColumn<QString>("to");
    QTest::newRow("reference to opencl") << "reference" << "opencl";
    QTest::newRow("opencl to reference") << "opencl" << "reference";
}

// The app switches backends by restoring one's state into the other. The state's doubles go into
// the backend's own precision: float32 on OpenCL, exact on the reference.
void TestSnapshot::otherBackendRestoresWithinRounding()
{
    QFETCH(QString, from);
    QFETCH(QString, to);
    VF_REQUIRE_BACKEND(QStringLiteral("opencl"));
    const SimulationState state = stirredScene(from, fluidSettings())->snapshot();
    auto target = test::makeBackend(to, fluidSettings());
    target->restore(state);
    const SimulationState got = target->snapshot();
    const double epsilon = test::positionEpsilon(to);

    QCOMPARE(got.time, state.time);
    QCOMPARE(got.regionCount, state.regionCount);
    QVERIFY(got.pendingStylus == state.pendingStylus);
    QCOMPARE(target->vertexCount(), vertexCount(state));
    QCOMPARE(got.contours.size(), state.contours.size());
    double position = 0.0, spacing = 0.0, area = 0.0;
    for (std::size_t i = 0; i < state.contours.size(); ++i) {
        const sim::Contour &a = state.contours[i], &b = got.contours[i];
        QCOMPARE(b.region, a.region);
        QCOMPARE(b.positions.size(), a.positions.size());
        for (std::size_t k = 0; k < a.positions.size(); ++k) {
            position = std::max({position, glm::distance(a.positions[k], b.positions[k]),
                                 glm::distance(a.previous[k], b.previous[k])});
            spacing = std::max(spacing, std::abs(b.spacing[k] / a.spacing[k] - 1.0));
        }
        area = std::max(area, std::abs(b.targetArea / a.targetArea - 1.0));
    }
    QVERIFY2(position <= epsilon, qPrintable(QStringLiteral("positions moved by %1").arg(position)));
    QVERIFY2(spacing <= epsilon, qPrintable(QStringLiteral("spacing changed by %1").arg(spacing)));
    QVERIFY2(area <= epsilon, qPrintable(QStringLiteral("target areas changed by %1").arg(area)));

    QVERIFY(got.fluid);
    const sim::MacVelocity &u0 = state.fluid->velocity, &u1 = got.fluid->velocity;
    const double speed = std::max(largestMagnitude(u0.u), largestMagnitude(u0.v));
    QVERIFY(largestDifference(u0.u, u1.u) <= epsilon * speed);
    QVERIFY(largestDifference(u0.v, u1.v) <= epsilon * speed);
    QVERIFY(largestDifference(state.fluid->pressure, got.fluid->pressure)
            <= epsilon * largestMagnitude(state.fluid->pressure));
}

void TestSnapshot::otherTrackingRefinesOnNextStep()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    const SimulationState state = stirredScene(backend, fluidSettings())->snapshot();
    sim::SimulationSettings finer = fluidSettings();
    finer.tracking.maxSpacing = kSpacing / 2;
    finer.tracking.maxVertices = 100'000;
    auto restored = test::makeBackend(backend, finer);
    restored->restore(state);
    QVERIFY2(restored->contours() == state.contours, "contours are taken as they are");
    QVERIFY(longestEdge(state.contours) > finer.tracking.maxSpacing);
    restored->step(kDt);
    const std::vector<sim::Contour> refined = restored->contours();
    QVERIFY(restored->vertexCount() > vertexCount(state) * 3 / 2);
    QVERIFY2(longestEdge(refined) <= finer.tracking.maxSpacing * (1 + test::positionEpsilon(backend)),
             qPrintable(QStringLiteral("edge of %1 after the step").arg(longestEdge(refined))));
}

void TestSnapshot::statePastTheVertexLimitRestores()
{
    // A drop may take a scene past max_vertices; the app's undo history then holds that state and
    // redo must restore it, so the limit stops growth but not a restore.
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    const SimulationState state = stirredScene(backend, fluidSettings())->snapshot();
    sim::SimulationSettings tight = fluidSettings();
    tight.tracking.maxVertices = vertexCount(state) / 2;
    auto restored = test::makeBackend(backend, tight);
    restored->restore(state);
    QVERIFY(restored->snapshot() == state);
}

void TestSnapshot::otherFlowStartsAtRest()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    const SimulationState stirred = stirredScene(backend, fluidSettings())->snapshot();

    sim::SimulationSettings coarser = fluidSettings();
    coarser.fluid.nx = coarser.fluid.ny = 32;
    auto coarse = test::makeBackend(backend, coarser);
    coarse->restore(stirred);
    const SimulationState onCoarse = coarse->snapshot();
    QVERIFY(onCoarse.fluid && onCoarse.fluid->velocity.nx == 32 && atRest(*onCoarse.fluid));
    QVERIFY(onCoarse.contours == stirred.contours);
    QCOMPARE(onCoarse.time, stirred.time);

    // A fluid state into an analytic flow: the fluid and the pen are ignored, the rest is kept.
    const sim::SimulationSettings rotating = test::rotation(4.0, kSpacing, true);
    auto analytic = test::makeBackend(backend, rotating);
    analytic->restore(stirred);
    const SimulationState onAnalytic = analytic->snapshot();
    QVERIFY(!onAnalytic.fluid);
    QVERIFY(onAnalytic.pendingStylus.empty());
    QVERIFY(onAnalytic.contours == stirred.contours);
    QCOMPARE(onAnalytic.time, stirred.time);

    // And back: a state without a fluid leaves the fluid at rest.
    auto fluid = stirredScene(backend, fluidSettings());
    fluid->restore(onAnalytic);
    const SimulationState back = fluid->snapshot();
    QVERIFY(back.fluid && atRest(*back.fluid));
    QVERIFY(back.contours == stirred.contours);
}

// requestRegions()/takeRegions(), the app's frames: a copy shows the geometry of the moment it
// was requested, also when a step has run since; the newest request wins and each copy is taken
// once; restore() drops the copies requested before it.
void TestSnapshot::regionsCopyIsItsMoment()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    auto simulation = stirredScene(backend, fluidSettings());
    QVERIFY(!simulation->takeRegions(true));
    const auto before = simulation->regions();
    const std::uint64_t first = simulation->requestRegions();
    advance(*simulation, 1);
    const auto after = simulation->regions();
    QVERIFY(after != before);
    std::optional<sim::RegionsCopy> copy = simulation->takeRegions(true);
    QVERIFY(copy);
    QCOMPARE(copy->request, first);
    QVERIFY(copy->regions == before);
    QVERIFY(!simulation->takeRegions(true));

    simulation->requestRegions();
    const std::uint64_t newest = simulation->requestRegions();
    QVERIFY(newest > first);
    copy = simulation->takeRegions(true);
    QVERIFY(copy);
    QCOMPARE(copy->request, newest);
    QVERIFY(copy->regions == after);
    QVERIFY(!simulation->takeRegions(true));  // the older request is superseded

    const SimulationState state = simulation->snapshot();
    simulation->requestRegions();
    simulation->restore(state);
    QVERIFY(!simulation->takeRegions(true));
}

void TestSnapshot::invalidStateIsRefused_data()
{
    test::addBackendColumn();
    QTest::addColumn<QString>("defect");
    for (const QString& b : test::backendNames())
        for (const auto& [name, spoil] : defects())
            QTest::newRow(qPrintable(b + "/" + name)) << b << name;
}

void TestSnapshot::invalidStateIsRefused()
{
    QFETCH(QString, backend);
    QFETCH(QString, defect);
    VF_REQUIRE_BACKEND(backend);
    auto simulation = stirredScene(backend, fluidSettings());
    QVERIFY(simulation->vertexCount() < fluidSettings().tracking.maxVertices);
    SimulationState bad = simulation->snapshot();
    advance(*simulation, 2);  // so that a restore that went part way would show
    const SimulationState before = simulation->snapshot();
    defects().at(defect)(bad);
    try {
        simulation->restore(bad);
        QFAIL("the state was accepted");
    } catch (const std::invalid_argument& e) {
        const QString message = QString::fromUtf8(e.what());
        qInfo() << message;
        QVERIFY(!message.isEmpty() && !message.contains('\n'));
    }
    QCOMPARE(firstDifference(simulation->snapshot(), before), QString());
    QCOMPARE(simulation->vertexCount(), vertexCount(before));
    QCOMPARE(simulation->regionCount(), before.regionCount);
}

QTEST_APPLESS_MAIN(TestSnapshot)
#include "tst_snapshot.moc"
