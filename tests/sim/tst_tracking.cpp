// Contour tracking accuracy (paper §3.1, §3.3; docs/method.md, "Accuracy"), on every backend.
#include "Backends.h"
#include "Flows.h"
#include "StillWater.h"

#include "sim/AnalyticFlow.h"
#include "sim/AreaCorrection.h"
#include "sim/ContourTracker.h"
#include "sim/Crossings.h"
#include "sim/SpacingField.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>
#include <numbers>
#include <set>

using namespace vf;
using sim::Polygon;
using sim::Vec2;

namespace {

double totalArea(const std::vector<Polygon>& contours)
{
    double a = 0.0;
    for (const Polygon& p : contours)
        a += sim::signedArea(p);
    return a;
}

// Runs `steps` steps of dt; returns the largest relative deviation of any edge from its band
// [d/2, d], as (worst shortfall below d/2, worst excess above d) relative to d.
struct SpacingViolation {
    double belowHalf = 0.0;
    double above = 0.0;
};

SpacingViolation spacingViolation(const sim::Simulation& simulation, const QString& backend)
{
    SpacingViolation worst;
    for (const sim::Contour& c : simulation.contours()) {
        const std::size_t n = c.positions.size();
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            const double d = 0.5 * (c.spacing[i] + c.spacing[j]);
            const double len = glm::distance(c.positions[i], c.positions[j]);
            worst.above = std::max(worst.above, len / d - 1.0);
            worst.belowHalf = std::max(worst.belowHalf, 0.5 - (len + test::shortEdgeSlack(backend, c.positions[i])) / d);
        }
    }
    return worst;
}

// Backend × {uniform, adaptive} spacing.
void addSpacingModeRows()
{
    test::addBackendColumn();
    QTest::addColumn<bool>("adaptive");
    for (const QString& b : test::backendNames()) {
        QTest::newRow(qPrintable(b + "/uniform")) << b << false;
        QTest::newRow(qPrintable(b + "/adaptive")) << b << true;
    }
}

// Mean distance from the vertices of `points` to the closed polyline `curve`.
double meanDistance(const Polygon& points, const Polygon& curve)
{
    double sum = 0.0;
    for (const Vec2& p : points)
        sum += sim::directedHausdorffDistance({p}, curve);
    return sum / points.size();
}

} // namespace

class TestTracking : public QObject {
    Q_OBJECT

private slots:
    void rungeKuttaIsFourthOrder();
    void recentringCorrectsOnce();

    void edgesStayWithinSpacing_data();
    void edgesStayWithinSpacing();

    void timeRewindingBeatsLinearMidpoint_data();
    void timeRewindingBeatsLinearMidpoint();

    void singleVortexReturns_data();
    void singleVortexReturns();

    void slottedDiskKeepsCorners_data();
    void slottedDiskKeepsCorners();

    void adaptiveSpacingSavesVertices_data();
    void adaptiveSpacingSavesVertices();

    void spacingIsRounded_data();
    void spacingIsRounded();

    void areaCorrectionIsAUniformOffset();
    void areaCorrectionHoldsASharpTip();
    void areaCorrectionHoldsBesideOtherInk_data() { test::addBackendRows(); }
    void areaCorrectionHoldsBesideOtherInk();

    void thinNeedlesAreTrimmed_data();
    void thinNeedlesAreTrimmed();

    void collapseSweepsOverNoInk_data();
    void collapseSweepsOverNoInk();
};

void TestTracking::rungeKuttaIsFourthOrder()
{
    // A quarter turn of solid rotation, at three step sizes; the error must fall by 2^4 per halving.
    const auto settings = test::rotation(1.0, 0.01, false);
    const sim::AnalyticFlow flow(settings.u, settings.v);
    const Vec2 start(0.8, 0.5);
    const Vec2 exact(0.5, 0.8);  // rotated by +90° about (0.5, 0.5) in the flow's sense
    std::vector<double> errors;
    for (int n : {8, 16, 32}) {
        Vec2 p = start;
        const double dt = 0.25 / n;
        for (int k = 0; k < n; ++k)
            p = sim::rungeKutta4(flow, p, k * dt, dt);
        errors.push_back(glm::distance(p, exact));
    }
    for (std::size_t i = 1; i < errors.size(); ++i) {
        const double order = std::log2(errors[i - 1] / errors[i]);
        QVERIFY2(order > 3.8 && order < 4.2, qPrintable(QStringLiteral("observed order %1").arg(order)));
    }
}

// Recentring's one correction: a rewound midpoint that landed too near one end moves toward the
// other by how far it landed from the middle of what both ends allow.
void TestTracking::recentringCorrectsOnce()
{
    QCOMPARE(sim::recentredFraction(0.5, 0.1, 0.9, 0.3, 0.3), 0.9);     // landed at 0.1 of the way, aim 0.5
    QCOMPARE(sim::recentredFraction(0.5, 0.5, 0.5, 0.2, 0.2), 0.5);     // already in the middle
    QCOMPARE(sim::recentredFraction(0.7, 0.9, 0.1, 0.05, 0.7), 0.1);    // aim 0.3: the middle is too near b
    QCOMPARE(sim::recentredFraction(0.5, 0.2, 0.8, 0.75, 0.75), 0.8);   // needs longer than the edge: in proportion
    QCOMPARE(sim::recentredFraction(0.9, 0.0, 1.0, 0.3, 0.3), 1.0);     // never past the edge's end
    QCOMPARE(sim::recentredFraction(0.4, 0.0, 0.0, 0.3, 0.3), 0.4);     // nothing to go by
}

void TestTracking::edgesStayWithinSpacing_data()
{
    addSpacingModeRows();
}

void TestTracking::edgesStayWithinSpacing()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    QFETCH(bool, adaptive);
    auto simulation = test::makeBackend(backend, test::singleVortex(8.0, 1.0 / 128, adaptive));
    simulation->addRegion({sim::circle({0.5, 0.75}, 0.15, 1.0 / 128)});
    SpacingViolation worst;
    for (int step = 0; step < 150; ++step) {
        simulation->step(0.02);
        const SpacingViolation v = spacingViolation(*simulation, backend);
        worst.above = std::max(worst.above, v.above);
        worst.belowHalf = std::max(worst.belowHalf, v.belowHalf);
    }
    qInfo() << "vertices" << simulation->vertexCount() << "worst excess" << worst.above << "worst shortfall" << worst.belowHalf;
    const double epsilon = test::positionEpsilon(backend);
    QVERIFY2(worst.above <= epsilon, qPrintable(QStringLiteral("an edge exceeded d_i by %1").arg(worst.above)));
    QVERIFY2(worst.belowHalf <= epsilon, qPrintable(QStringLiteral("an edge fell below d_i/2 by %1").arg(worst.belowHalf)));
}

void TestTracking::timeRewindingBeatsLinearMidpoint_data()
{
    test::addBackendRows();
}

void TestTracking::timeRewindingBeatsLinearMidpoint()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    // Coarse spacing and large steps (no substeps) in the curved single-vortex flow, where one
    // step stretches and bends edges far. The reference tracks the same flow with the same step
    // very finely, so RK4's time error is common to both and what differs is where split vertices
    // land: on the advected curve (eq. 2) or on the chord.
    constexpr double dt = 0.2;
    auto run = [&](double spacing, bool rewind) {
        auto settings = test::singleVortex(8.0, spacing, false);
        settings.tracking.timeRewinding = rewind;
        settings.tracking.maxSubsteps = 1;
        auto simulation = test::makeBackend(backend, settings);
        simulation->addRegion({sim::circle({0.5, 0.75}, 0.15, spacing)});
        for (int step = 0; step < 15; ++step)
            simulation->step(dt);
        return simulation->regions()[0][0];
    };
    const Polygon reference = run(1.0 / 2048, true);
    const Polygon rewoundRun = run(1.0 / 32, true), linearRun = run(1.0 / 32, false);
    const double rewound = meanDistance(rewoundRun, reference), linear = meanDistance(linearRun, reference);
    qInfo() << "mean vertex distance to reference: rewinding" << rewound << "linear midpoint" << linear
            << "max" << sim::directedHausdorffDistance(rewoundRun, reference) << sim::directedHausdorffDistance(linearRun, reference);
    QVERIFY2(rewound < 0.8 * linear, qPrintable(QStringLiteral("rewinding %1 vs linear %2").arg(rewound).arg(linear)));
}

void TestTracking::singleVortexReturns_data()
{
    test::addBackendColumn();
    QTest::addColumn<bool>("areaCorrection");
    QTest::addColumn<double>("areaTolerance");
    for (const QString& b : test::backendNames()) {
        QTest::newRow(qPrintable(b)) << b << false << 1e-3;
        QTest::newRow(qPrintable(b + "/area-correction")) << b << true << 1e-6;
    }
}

void TestTracking::singleVortexReturns()
{
    // The accuracy bar (docs/method.md, "Accuracy"): circle r = 0.15 at (0.5, 0.75), period 8, uniform spacing 1/256.
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    QFETCH(bool, areaCorrection);
    QFETCH(double, areaTolerance);
    auto settings = test::singleVortex(8.0, 1.0 / 256, false);
    settings.tracking.areaCorrection = areaCorrection;
    auto simulation = test::makeBackend(backend, settings);
    const Polygon start = sim::circle({0.5, 0.75}, 0.15, 1.0 / 256);
    simulation->addRegion({start});
    const double startArea = totalArea(simulation->regions()[0]);
    double worstArea = 0.0;
    const double dt = 0.01;
    for (int step = 0; step < 800; ++step) {
        simulation->step(dt);
        worstArea = std::max(worstArea, std::abs(totalArea(simulation->regions()[0]) / startArea - 1.0));
    }
    const double shape = sim::hausdorffDistance(simulation->regions()[0][0], start);
    qInfo() << "worst relative area error" << worstArea << "shape return" << shape << "vertices" << simulation->vertexCount();
    QVERIFY2(worstArea < areaTolerance, qPrintable(QStringLiteral("area error %1").arg(worstArea)));
    QVERIFY2(shape < 0.002, qPrintable(QStringLiteral("shape return %1").arg(shape)));
}

void TestTracking::slottedDiskKeepsCorners_data()
{
    addSpacingModeRows();
}

void TestTracking::slottedDiskKeepsCorners()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    QFETCH(bool, adaptive);
    // One revolution of rigid rotation must bring every corner of the slot back.
    auto simulation = test::makeBackend(backend, test::rotation(2.0, 1.0 / 256, adaptive));
    const Polygon start = test::slottedDisk(1.0 / 256);
    QVERIFY(sim::signedArea(start) > 0.0);
    simulation->addRegion({start});
    for (int step = 0; step < 200; ++step)
        simulation->step(0.01);
    const double distance = sim::hausdorffDistance(simulation->regions()[0][0], start);
    qInfo() << "Hausdorff distance after one revolution" << distance;
    QVERIFY2(distance < 0.002, qPrintable(QStringLiteral("Hausdorff %1").arg(distance)));
}

void TestTracking::adaptiveSpacingSavesVertices_data()
{
    test::addBackendRows();
}

void TestTracking::adaptiveSpacingSavesVertices()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    // The curly scene: the single vortex wound up to t = T/4. Eqs. 3-7 spend vertices where
    // curvature, vorticity and nearby contours need them; uniform spacing must be finer
    // everywhere to match that shape error. Adaptive at d_max = h against uniform at h/2: at least
    // as accurate against a finely tracked reference, with at least 40% fewer vertices.
    auto run = [&](double maxSpacing, bool adaptive) {
        auto simulation = test::makeBackend(backend, test::singleVortex(8.0, maxSpacing, adaptive));
        simulation->addRegion({sim::circle({0.5, 0.75}, 0.15, maxSpacing)});
        for (int step = 0; step < 100; ++step)
            simulation->step(0.02);
        return simulation->regions()[0][0];
    };
    const Polygon reference = run(1.0 / 1024, false);
    const Polygon adaptive = run(1.0 / 256, true), uniform = run(1.0 / 512, false);
    const double adaptiveError = sim::hausdorffDistance(adaptive, reference);
    const double uniformError = sim::hausdorffDistance(uniform, reference);
    qInfo() << "adaptive (d_max 1/256):" << adaptive.size() << "vertices, error" << adaptiveError
            << "| uniform (1/512):" << uniform.size() << "vertices, error" << uniformError;
    QVERIFY2(adaptiveError <= uniformError, "adaptive spacing lost accuracy against uniform spacing");
    QVERIFY2(adaptive.size() <= 0.6 * uniform.size(),
             qPrintable(QStringLiteral("%1 adaptive vs %2 uniform vertices").arg(adaptive.size()).arg(uniform.size())));
}

void TestTracking::spacingIsRounded_data()
{
    test::addBackendRows();
}

// d_i keeps spacingFractionBits (10) bits after the binary point, rounded to nearest, on both
// backends, and still follows the curve (adaptive spacing takes many values).
void TestTracking::spacingIsRounded()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    QCOMPARE(sim::spacingFractionBits, 10);
    QCOMPARE(sim::roundedSpacing(0.75), 0.75);
    QCOMPARE(sim::roundedSpacing(1.0 + std::ldexp(1.0, -12)), 1.0);                     // a quarter of the last bit: down
    QCOMPARE(sim::roundedSpacing(1.0 + 3 * std::ldexp(1.0, -12)), 1.0 + std::ldexp(1.0, -10));  // three quarters: up
    QCOMPARE(sim::roundedSpacing(2.0 - std::ldexp(1.0, -12)), 2.0);                     // up into the next power of two
    QCOMPARE(sim::roundedSpacing(std::ldexp(1.0 + std::ldexp(1.0, -9), -8)), std::ldexp(1.0 + std::ldexp(1.0, -9), -8));

    auto simulation = test::makeBackend(backend, test::singleVortex(8.0, 1.0 / 256, true));
    simulation->addRegion({sim::circle({0.5, 0.75}, 0.15, 1.0 / 256)});
    for (int step = 0; step < 20; ++step)
        simulation->step(0.02);
    std::set<double> values;
    for (const sim::Contour& c : simulation->contours())
        for (double d : c.spacing) {
            QCOMPARE(sim::roundedSpacing(d), d);
            values.insert(d);
        }
    QVERIFY2(values.size() > 20, qPrintable(QStringLiteral("%1 distinct spacings").arg(values.size())));
}

// The correction offsets a contour by one distance everywhere, whether its edges are fine or coarse
// (how far a vertex moves is how close other ink may come), and moves a vertex between edges far
// shorter than the offset by less than those edges (no fold at a crease).
void TestTracking::areaCorrectionIsAUniformOffset()
{
    const Vec2 centre(0.5, 0.5);
    constexpr double radius = 0.1, shortEdge = 2.5e-4;
    auto on = [&](double angle) { return centre + radius * Vec2(std::cos(angle), std::sin(angle)); };
    Polygon circle;
    for (double a = 0.0; a < std::numbers::pi; a += 0.01)  // edges of 1e-3
        circle.push_back(on(a));
    for (double a = std::numbers::pi; a < 2.0 * std::numbers::pi - 0.05; a += 0.1)  // edges of 1e-2
        circle.push_back(on(a));
    const std::size_t cluster = 50;  // three vertices 1e-8 apart, as at a crease
    circle.insert(circle.begin() + cluster + 1, {on(0.5 + 1e-7), on(0.5 + 2e-7)});
    Polygon corrected = circle;
    const double target = sim::signedArea(circle) + 2.0 * std::numbers::pi * radius * 1e-6;
    sim::correctArea(corrected, target, shortEdge, std::vector<bool>(circle.size(), false), 1.0);
    QVERIFY(std::abs(sim::signedArea(corrected) - target) < 1e-15);
    const double fine = glm::distance(corrected[10], circle[10]), coarse = glm::distance(corrected.back(), circle.back());
    QVERIFY2(std::abs(fine / coarse - 1.0) < 1e-6, qPrintable(QStringLiteral("fine %1, coarse %2").arg(fine).arg(coarse)));
    QVERIFY(std::abs(coarse - 1e-6) < 1e-8);
    for (std::size_t i = 0; i < circle.size(); ++i)
        QVERIFY(glm::distance(corrected[i], circle[i]) <= coarse * (1.0 + 1e-9));
    QVERIFY(glm::distance(corrected[cluster + 1], circle[cluster + 1]) < 0.1 * glm::distance(circle[cluster + 1], circle[cluster]));
}

// A notch cut to a sharp tip, as a comb's crease folds a V: the tip and its two neighbours stay
// where they are (the offset's direction there is no normal of the curve, and the V's sides lie
// nearer each other than the offset beside the tip), and the rest makes the area up.
void TestTracking::areaCorrectionHoldsASharpTip()
{
    const Vec2 tip(0.4, 0.25);
    const Polygon notched = sim::resample({{0.2, 0.2}, {0.6, 0.2}, {0.6, 0.6}, {0.401, 0.6}, tip, {0.399, 0.6}, {0.2, 0.6}}, 0.01);
    const auto at = std::find(notched.begin(), notched.end(), tip);
    QVERIFY(at != notched.end());
    const std::size_t n = notched.size(), t = std::size_t(at - notched.begin());
    Polygon corrected = notched;
    const double target = sim::signedArea(notched) + 1e-6;
    sim::correctArea(corrected, target, 2.5e-4, std::vector<bool>(n, false), 1.0);
    QVERIFY(std::abs(sim::signedArea(corrected) - target) < 1e-15);
    for (std::size_t i : {(t + n - 1) % n, t, (t + 1) % n})
        QCOMPARE(corrected[i], notched[i]);
    QVERIFY(glm::distance(corrected[(t + 2) % n], notched[(t + 2) % n]) > 0.0);
    QVERIFY(glm::distance(corrected.front(), notched.front()) > 0.0);
}

// Two inks a micrometre apart, the left one short of its area target by four micrometres of offset:
// the correction makes the area up where no other ink is near and leaves the side facing the
// other ink where it is (a uniform offset would carry it across).
void TestTracking::areaCorrectionHoldsBesideOtherInk()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    auto simulation = test::stillWater(backend, true);
    constexpr double gap = 1e-6, shortfall = 4e-6;
    auto rectangle = [](double left, double right) {
        return Polygon{{left, 0.3}, {right, 0.3}, {right, 0.7}, {left, 0.7}};
    };
    simulation->addRegion({rectangle(0.3, 0.5)});
    simulation->addRegion({rectangle(0.5 + gap, 0.7)});
    sim::SimulationState state = simulation->snapshot();
    const double start = sim::signedArea(state.contours[0].positions);
    const double target = start + shortfall * 0.8;  // the perimeter times the offset
    state.contours[0].targetArea = target;
    simulation->restore(state);
    for (int step = 0; step < 3; ++step) {
        simulation->step(0.01);
        QCOMPARE(test::crossings(test::outlines(*simulation)), std::size_t(0));
    }
    const Polygon left = simulation->contours()[0].positions;
    double right = 0.0;
    for (const Vec2& v : left)
        right = std::max(right, v.x);
    QVERIFY2(right <= 0.5 + 1e-7, qPrintable(QStringLiteral("the side facing the other ink moved to x = %1").arg(right, 0, 'g', 10)));
    const double made = (sim::signedArea(left) - start) / (target - start);
    QVERIFY2(std::abs(made - 1.0) < 0.02, qPrintable(QStringLiteral("%1 of the shortfall made up").arg(made)));
}

void TestTracking::thinNeedlesAreTrimmed_data()
{
    test::addBackendColumn();
    QTest::addColumn<double>("width");
    QTest::addColumn<bool>("trimmed");
    for (const QString& b : test::backendNames()) {
        QTest::addRow("%s, 1e-9 wide", qPrintable(b)) << b << 1e-9 << true;  // float32: both sides on one line
        QTest::addRow("%s, 2e-5 wide", qPrintable(b)) << b << 2e-5 << true;
        QTest::addRow("%s, a spacing wide", qPrintable(b)) << b << 1.0 / 256 << false;
    }
}

void TestTracking::thinNeedlesAreTrimmed()
{
    QFETCH(QString, backend);
    VF_REQUIRE_BACKEND(backend);
    QFETCH(double, width);
    QFETCH(bool, trimmed);
    // A square with a needle 0.15 long standing on its top edge, in still water: thinner than a
    // hundredth of the spacing, collapse eats it from the tip down; wider, it stays.
    const double spacing = 1.0 / 256;
    auto simulation = test::makeBackend(backend, test::analyticSettings("0", "0", spacing, false));
    const Polygon needle{{0.3, 0.3}, {0.6, 0.3}, {0.6, 0.6}, {0.45 + 0.5 * width, 0.6}, {0.45, 0.75},
                         {0.45 - 0.5 * width, 0.6}, {0.3, 0.6}};
    simulation->addRegion({needle});
    for (int step = 0; step < 5; ++step)
        simulation->step(0.01);
    const Polygon contour = simulation->regions()[0][0];
    double top = 0.0;
    for (const Vec2& p : contour)
        top = std::max(top, p.y);
    QVERIFY2(sim::isSimple(contour), qPrintable(QStringLiteral("top %1, %2 vertices").arg(top).arg(contour.size())));
    if (trimmed)
        QVERIFY2(top < 0.6 + spacing, qPrintable(QStringLiteral("the needle reaches %1").arg(top)));
    else
        QVERIFY2(top > 0.75 - spacing, qPrintable(QStringLiteral("the needle was cut to %1").arg(top)));
    QVERIFY(std::abs(sim::signedArea(contour) - 0.09) < 0.15 * width + 0.09 * test::positionEpsilon(backend));
}

void TestTracking::collapseSweepsOverNoInk_data()
{
    test::addBackendColumn();
    QTest::addColumn<double>("tipBelowBump");
    for (const QString& b : test::backendNames()) {
        QTest::addRow("%s, tip beneath", qPrintable(b)) << b << 5e-6;
        QTest::addRow("%s, tip touching", qPrintable(b)) << b << 0.0;
    }
}

// A vertex 7.6e-6 proud of a straight edge, 1.2e-4 from a corner: its edge to the corner is short, and
// it is the straighter end, so collapse would remove it, and the joining chord would pass under the
// tip of another ink that pokes up beneath it, or that touches it there (a second vertex at the
// bump's place, which the sweep must not take for the bump itself). It must stay.
void TestTracking::collapseSweepsOverNoInk()
{
    QFETCH(QString, backend);
    QFETCH(double, tipBelowBump);
    VF_REQUIRE_BACKEND(backend);
    constexpr double spacing = 1e-3;
    auto simulation = test::makeBackend(backend, test::analyticSettings("0", "0", spacing, false));
    // Places a float holds, so that the tip touches the bump on every backend.
    const Vec2 bump(0.5, 0.5 + 0x1p-17), corner(0.5 + 0x1p-13, 0.5);
    simulation->addRegion({Polygon{{0.3, 0.5}, {0.5 - 4e-4, 0.5}, bump, corner, {corner.x, 0.7}, {0.3, 0.7}}});
    simulation->addRegion({Polygon{{0.45, 0.3}, {0.55, 0.3}, bump - Vec2(0.0, tipBelowBump)}});
    QCOMPARE(test::crossings(test::outlines(*simulation)), std::size_t(0));
    for (int step = 0; step < 3; ++step)
        simulation->step(0.01);
    QCOMPARE(test::crossings(test::outlines(*simulation)), std::size_t(0));
}

QTEST_APPLESS_MAIN(TestTracking)
#include "tst_tracking.moc"
