// The engine held to the kinds of sessions designers make (sessions/, small enough for a test):
// marbling (drops, comb passes, cross passes), fine detail (small circles at a fine uniform
// spacing, a fast stroke) and shape design (letters in a viscous fluid, short strokes), on every
// backend and for several seeds. Contours never cross, every region keeps its area, and the
// backends agree on how many vertices it takes.
#include "../sim/Backends.h"

#include "model/SceneRunner.h"
#include "sessions/Sessions.h"
#include "sim/Crossings.h"

#include <QtTest>

#include <cmath>
#include <map>

using namespace vf;

namespace {

struct Outcome {
    std::size_t crossings = 0;
    std::int64_t firstCrossingStep = -1;
    double worstAreaError = 0.0;
    std::size_t vertices = 0;
};

// Plays `scene` on `backend`, checking every `every` steps: crossings between contours that did not
// cross when they appeared, and each region's area against its target.
Outcome play(const model::Scene& scene, const QString& backend, int every)
{
    model::SceneRunner runner(scene, [&](const sim::SimulationSettings& s) { return test::makeBackend(backend, s); });
    Outcome outcome;
    std::size_t known = 0;
    for (std::int64_t step = 1; step <= scene.time.steps; ++step) {
        runner.step(scene.time.dt);
        if (step % every != 0 && step != scene.time.steps)
            continue;
        const std::vector<sim::Contour> contours = runner.simulation().contours();
        std::vector<const sim::Polygon*> polygons;
        std::map<int, std::pair<double, double>> regions;  // area, target
        for (const sim::Contour& c : contours) {
            polygons.push_back(&c.positions);
            regions[c.region].first += sim::signedArea(c.positions);
            regions[c.region].second += c.targetArea;
        }
        for (const sim::EdgeCrossing& x : sim::findCrossings(polygons)) {
            if (x.polygonA == x.polygonB || x.polygonB < known) {
                ++outcome.crossings;
                if (outcome.firstCrossingStep < 0)
                    outcome.firstCrossingStep = step;
            }
        }
        known = contours.size();
        for (const auto& [region, area] : regions)
            outcome.worstAreaError =
                std::max(outcome.worstAreaError, std::abs(area.first - area.second) / std::abs(area.second));
    }
    outcome.vertices = runner.simulation().vertexCount();
    return outcome;
}

model::Scene smallMarbling(std::uint32_t seed)
{
    sessions::MarblingOptions o;
    o.dropsPerSide = 3;
    o.dropRadius = 0.1;
    o.tines = 6;
    o.combPasses = 2;
    o.crossPasses = 1;
    o.maxSpacing = 0.004;
    o.steps = 330;
    return sessions::marbling(o, seed);
}

model::Scene smallFineDetail(std::uint32_t seed)
{
    sessions::FineDetailOptions o;
    o.circlesPerSide = 4;
    o.radius = 0.08;
    o.spacing = 0.0008;
    o.steps = 40;
    return sessions::fineDetail(o, seed);
}

model::Scene smallShapeDesign(std::uint32_t seed)
{
    sessions::ShapeDesignOptions o;
    o.maxSpacing = 0.002;
    o.steps = 200;
    o.strokes = 3;
    return sessions::shapeDesign(o, sessions::designLetters(o.maxSpacing), seed);
}

} // namespace

class TestSessions : public QObject {
    Q_OBJECT

private slots:
    void sessionsKeepTopologyAndArea_data()
    {
        test::addBackendColumn();
        QTest::addColumn<QString>("session");
        QTest::addColumn<std::uint32_t>("seed");
        for (const QString& b : test::backendNames())
            for (const char* session : {"marbling", "fine-detail", "shape-design"})
                for (std::uint32_t seed : {1u, 2u})
                    QTest::newRow(qPrintable(QStringLiteral("%1/%2/%3").arg(b, session).arg(seed))) << b << session << seed;
    }

    void sessionsKeepTopologyAndArea()
    {
        QFETCH(QString, backend);
        QFETCH(QString, session);
        QFETCH(std::uint32_t, seed);
        VF_REQUIRE_BACKEND(backend);
        const model::Scene scene = session == QLatin1String("marbling")      ? smallMarbling(seed)
                                   : session == QLatin1String("fine-detail") ? smallFineDetail(seed)
                                                                             : smallShapeDesign(seed);
        const Outcome o = play(scene, backend, 10);
        qInfo() << "vertices" << o.vertices << "crossings" << o.crossings << "worst area error" << o.worstAreaError;
        QVERIFY2(o.vertices > 2000, "the session should have made some work");
        QVERIFY2(o.crossings == 0, qPrintable(QStringLiteral("first crossing at step %1").arg(o.firstCrossingStep)));
        // Default settings (no area correction): the flow itself keeps the areas (divergence-free).
        QVERIFY2(o.worstAreaError < 1e-3, qPrintable(QString::number(o.worstAreaError)));
    }

    // The backends take about as many vertices for the same session (float32 on the device against
    // double, and collapses made in colour classes instead of along each ring).
    void backendsAgreeOnVertexCounts()
    {
        VF_REQUIRE_BACKEND(QStringLiteral("opencl"));
        for (const model::Scene& scene : {smallMarbling(3), smallFineDetail(3)}) {
            const double reference = double(play(scene, QStringLiteral("reference"), 1000).vertices);
            const double device = double(play(scene, QStringLiteral("opencl"), 1000).vertices);
            qInfo() << "reference" << reference << "opencl" << device;
            QVERIFY2(std::abs(device - reference) <= 0.02 * reference,
                     qPrintable(QStringLiteral("%1 against %2").arg(device).arg(reference)));
        }
    }
};

QTEST_MAIN(TestSessions)
#include "tst_sessions.moc"
