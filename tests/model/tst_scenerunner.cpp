// SceneRunner: a scene's regions, drops and strokes reach the simulation at the right moments,
// and the picture it hands out carries the scene's names, colours and visibility.
#include "model/SceneRunner.h"

#include <QTest>

using namespace vf;
using namespace vf::model;

namespace {

Scene stillScene()
{
    Scene scene;
    scene.flow.type = FlowSpec::Type::Analytic;
    scene.flow.u = QStringLiteral("0");
    scene.flow.v = QStringLiteral("0");
    scene.time.dt = 0.01;
    scene.regions.push_back({QStringLiteral("drop 1"), QColor(10, 20, 30), false, CircleShape{{0.3, 0.3}, 0.1}});
    return scene;
}

DropStroke dropAt(double time, QString name = {})
{
    return DropStroke{time, {0.7, 0.7}, 0.05, QColor(200, 0, 0), std::move(name)};
}

} // namespace

class TestSceneRunner : public QObject {
    Q_OBJECT

private slots:
    void dropsLandAtTheirTime()
    {
        Scene scene = stillScene();
        scene.strokes.push_back(dropAt(0.0));
        scene.strokes.push_back(dropAt(0.045, QStringLiteral("late")));
        SceneRunner runner(scene);
        QCOMPARE(runner.simulation().regionCount(), 2);  // the t = 0 drop is part of the start
        for (int step = 0; step < 4; ++step)
            runner.step(0.01);
        QCOMPARE(runner.simulation().regionCount(), 2);
        runner.step(0.01);  // the step covering t = 0.045
        QCOMPARE(runner.simulation().regionCount(), 3);
    }

    void pictureCarriesTheSceneLook()
    {
        Scene scene = stillScene();
        scene.strokes.push_back(dropAt(0.0));
        const Drawing drawing = SceneRunner(scene).drawing();
        QCOMPARE(drawing.regions.size(), std::size_t(2));
        QCOMPARE(drawing.regions[0].name, QStringLiteral("drop 1"));
        QCOMPARE(drawing.regions[0].color, QColor(10, 20, 30));
        QVERIFY(!drawing.regions[0].visible);
        // The unnamed drop must not take the name the scene already gave a region.
        QCOMPARE(drawing.regions[1].name, QStringLiteral("drop 2"));
        QCOMPARE(drawing.regions[1].color, QColor(200, 0, 0));
        QCOMPARE(drawing.background, scene.canvas.background);
    }

    void stylusMovesOnlyWhileItIsDown()
    {
        Scene scene;  // fluid
        scene.regions.push_back({QStringLiteral("ink"), Qt::black, true, CircleShape{{0.5, 0.5}, 0.1}});
        StylusStroke stroke;
        stroke.radius = 0.05;
        stroke.points = {{0.2, 0.5}, {0.8, 0.5}};
        stroke.times = {0.02, 0.1};
        scene.strokes.push_back(stroke);
        SceneRunner runner(scene);
        const auto start = runner.simulation().regions()[0][0];
        runner.step(0.01);  // before the pen touches the water: only refinement, no motion
        QVERIFY(sim::hausdorffDistance(runner.simulation().regions()[0][0], start) < 1e-4);
        for (int step = 0; step < 10; ++step)
            runner.step(0.01);
        const auto moved = runner.simulation().regions()[0][0];
        QVERIFY2(sim::hausdorffDistance(moved, start) > 0.01, "the stroke through the ink must move it");
    }
};

QTEST_APPLESS_MAIN(TestSceneRunner)
#include "tst_scenerunner.moc"
