// The Shape Design mode's defaults do what the mode promises: a stroke carries the ink under the
// pen along with it, and the water is still within half a second of the pen's release. Marbling's
// defaults keep moving, and a high viscosity alone does not carry the ink, which shows that each
// measurement can fail.
#include "../sim/Backends.h"
#include "model/EngineSettings.h"
#include "model/SceneRunner.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace vf;

namespace {

constexpr double kDt = 0.005;           // a new document's step in the app
constexpr double kStrokeLength = 0.3;   // canvas units, across the middle of the unit canvas
constexpr double kSettleSeconds = 0.5;  // how long after the release the water must be still

struct StrokeResult {
    double carried;          // how far the ink under the pen's start moved along the stroke, / length
    double velocityAfter;    // largest fluid velocity kSettleSeconds after release, / the pen's speed
};

double largestVelocity(const sim::Simulation& simulation)
{
    const sim::MacVelocity v = *simulation.velocity();
    double largest = 0.0;
    for (const std::vector<double>* component : {&v.u, &v.v})
        for (const double x : *component)
            largest = std::max(largest, std::abs(x));
    return largest;
}

double centroidX(const sim::Polygon& contour)
{
    double sum = 0.0;
    for (const sim::Vec2& p : contour)
        sum += p.x;
    return sum / double(contour.size());
}

// A disc of ink half the pen's radius where the stroke starts, then a straight stroke at `speed`
// (canvas units/s), one segment per step as the app sends the pointer's motion.
StrokeResult strokeThroughInk(const QString& backend, const model::FlowSpec& flow, double speed)
{
    model::Scene scene;
    scene.flow = flow;
    const double radius = scene.flow.stylusRadius;
    const auto simulation = test::makeBackend(backend, model::simulationSettings(scene));
    const sim::Vec2 start{0.35, 0.5};
    const sim::Vec2 end = start + sim::Vec2{kStrokeLength, 0.0};
    sim::Polygon ink;
    for (int i = 0; i < 64; ++i) {
        const double angle = -2.0 * std::numbers::pi * i / 64;
        ink.push_back(start + 0.5 * radius * sim::Vec2{std::cos(angle), std::sin(angle)});
    }
    simulation->addRegion({ink});
    const double before = centroidX(simulation->regions()[0][0]);

    const int strokeSteps = int(std::lround(kStrokeLength / speed / kDt));
    for (int k = 0; k < strokeSteps; ++k) {
        const sim::Vec2 from = start + (end - start) * (double(k) / strokeSteps);
        const sim::Vec2 to = start + (end - start) * (double(k + 1) / strokeSteps);
        simulation->stylus(from, to, radius, kDt);
        simulation->step(kDt);
    }
    const double carried = (centroidX(simulation->regions()[0][0]) - before) / kStrokeLength;
    for (int k = 0; k < int(std::lround(kSettleSeconds / kDt)); ++k)
        simulation->step(kDt);
    return {carried, largestVelocity(*simulation) / speed};
}

} // namespace

class TestShapeDesign : public QObject {
    Q_OBJECT

private slots:
    void strokeCarriesTheInkAndStops_data();
    void strokeCarriesTheInkAndStops();
    void marblingKeepsMoving();
    void viscosityAloneDoesNotCarry();
};

void TestShapeDesign::strokeCarriesTheInkAndStops_data()
{
    test::addBackendColumn();
    QTest::addColumn<double>("speed");
    for (const QString& backend : test::backendNames())
        for (const double speed : {0.25, 0.5, 1.0})  // a slow, an ordinary and a fast stroke
            QTest::addRow("%s %g/s", qPrintable(backend), speed) << backend << speed;
}

void TestShapeDesign::strokeCarriesTheInkAndStops()
{
    QFETCH(QString, backend);
    QFETCH(double, speed);
    VF_REQUIRE_BACKEND(backend);
    model::FlowSpec shapeDesign;
    model::applyPreset(shapeDesign, model::FluidMode::ShapeDesign);
    const StrokeResult r = strokeThroughInk(backend, shapeDesign, speed);
    qInfo("ink carried %.3f of the stroke; largest velocity %.4f of the pen's 0.5 s after", r.carried, r.velocityAfter);
    QVERIFY2(r.carried >= 0.5, qPrintable(QStringLiteral("ink carried %1 of the stroke").arg(r.carried)));
    QVERIFY2(r.velocityAfter < 0.05, qPrintable(QStringLiteral("velocity %1 of the pen's after 0.5 s").arg(r.velocityAfter)));
}

void TestShapeDesign::marblingKeepsMoving()
{
    model::FlowSpec marbling;
    model::applyPreset(marbling, model::FluidMode::Marbling);
    const StrokeResult r = strokeThroughInk(QStringLiteral("reference"), marbling, 0.5);
    QVERIFY2(r.velocityAfter >= 0.05, qPrintable(QString::number(r.velocityAfter)));
}

// A viscosity high enough to stop the ink at once, stirred by marbling's gentle pen.
void TestShapeDesign::viscosityAloneDoesNotCarry()
{
    model::FlowSpec viscous;
    model::applyPreset(viscous, model::FluidMode::Marbling);
    viscous.viscosity = 1.0;
    const StrokeResult r = strokeThroughInk(QStringLiteral("reference"), viscous, 0.5);
    QVERIFY2(r.carried < 0.5, qPrintable(QString::number(r.carried)));
}

QTEST_GUILESS_MAIN(TestShapeDesign)
#include "tst_shapedesign.moc"
