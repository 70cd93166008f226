// Engine to file: scenes played by model::SceneRunner, exported by render::exportDrawing in polyline
// mode, and the SVG read back must hold the engine's polygons (docs/writing-files.md, "Coordinates":
// coordinates rounded to 1e-6 of the canvas, no vertex dropped on these scenes), named after the
// regions, with no crossings and no repeated vertex: real marbled contours come close together,
// and rounding must not make them touch.
#include "SvgReadBack.h"

#include "model/SceneFile.h"
#include "model/SceneRunner.h"
#include "render/Exporter.h"
#include "render/XmlNames.h"
#include "sim/Crossings.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace vf;

namespace {

// Largest coordinate difference of two polygons, vertex by vertex; infinite when sizes differ.
double maxDifference(const sim::Polygon& a, const sim::Polygon& b)
{
    if (a.size() != b.size())
        return std::numeric_limits<double>::infinity();
    double worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max({worst, std::abs(a[i].x - b[i].x), std::abs(a[i].y - b[i].y)});
    return worst;
}

std::size_t vertexCount(const model::Drawing& drawing)
{
    std::size_t count = 0;
    for (const model::DrawnRegion& region : drawing.regions)
        for (const sim::Polygon& p : region.contours)
            count += p.size();
    return count;
}

} // namespace

class TestEngineExport : public QObject {
    Q_OBJECT

private slots:
    void polylineSvgReadsBackAsTheEngineGeometry_data();
    void polylineSvgReadsBackAsTheEngineGeometry();
};

void TestEngineExport::polylineSvgReadsBackAsTheEngineGeometry_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("steps");
    QTest::addColumn<int>("regions");  // after the steps: the drops that landed are regions too
    const QString stirred = QStringLiteral(VF_TEST_DATA "/scenes/stirred.vfscene");
    const QString sumi = QStringLiteral(VF_SOURCE_DIR "/resources/scenes/sumi-nagashi.vfscene");
    QTest::newRow("stirred, start") << stirred << 0 << 2;
    QTest::newRow("stirred, stylus and drop") << stirred << 50 << 3;
    QTest::newRow("sumi-nagashi demo, nested drops") << sumi << 64 << 7;
}

void TestEngineExport::polylineSvgReadsBackAsTheEngineGeometry()
{
    QFETCH(QString, scene);
    QFETCH(int, steps);
    QFETCH(int, regions);
    const model::SceneReadResult read = model::readSceneFile(scene);
    QVERIFY2(read.ok(), qPrintable(read.error));
    model::SceneRunner runner(read.scene);
    const model::Drawing start = runner.drawing();
    for (int i = 0; i < steps; ++i)
        QVERIFY(!runner.step(read.scene.time.dt).vertexLimitReached);
    const model::Drawing drawing = runner.drawing();
    QCOMPARE(drawing.regions.size(), std::size_t(regions));
    if (steps > 0)
        QVERIFY(vertexCount(drawing) != vertexCount(start));  // the flow did work on the geometry

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("engine.svg"));
    render::ExportOptions options;
    options.bezier = false;
    const QString error = render::exportDrawing(drawing, file, options);
    QVERIFY2(error.isEmpty(), qPrintable(error));

    const test::ParsedSvg svg = test::parseSvg(file);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    const std::vector<const test::ParsedPath*> paths = test::regionPaths(svg);
    QCOMPARE(paths.size(), drawing.regions.size());
    std::vector<sim::Polygon> readBack;
    for (std::size_t r = 0; r < paths.size(); ++r) {
        const model::DrawnRegion& region = drawing.regions[r];
        QCOMPARE(paths[r]->label, region.name);
        QCOMPARE(paths[r]->id, render::sanitizedXmlId(region.name));
        QCOMPARE(paths[r]->fill, region.color.name());
        QCOMPARE(paths[r]->fillRule, QStringLiteral("evenodd"));
        const std::vector<sim::Polygon> polygons = test::polygonsOf(*paths[r]);
        QCOMPARE(polygons.size(), region.contours.size());
        for (std::size_t c = 0; c < polygons.size(); ++c) {
            const double difference = maxDifference(polygons[c], region.contours[c]);
            QVERIFY2(difference <= 0.5e-6 * (1 + 1e-9), qPrintable(QStringLiteral("%1 contour %2: %3").arg(region.name).arg(c).arg(difference)));
        }
        for (const sim::Polygon& p : polygons)
            for (std::size_t i = 0; i < p.size(); ++i)
                QVERIFY(p[i] != p[(i + 1) % p.size()]);
        readBack.insert(readBack.end(), polygons.begin(), polygons.end());
    }

    std::vector<const sim::Polygon*> all;
    for (const sim::Polygon& p : readBack)
        all.push_back(&p);
    QCOMPARE(sim::countCrossings(all), std::size_t(0));
}

QTEST_GUILESS_MAIN(TestEngineExport)
#include "tst_engine_export.moc"
