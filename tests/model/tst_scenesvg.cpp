// SVG shapes in scene files ({"svg": "FILE"}): the regions are what File > Import SVG makes, found
// beside the scene, named and coloured as docs/scene-format.md says, in paint order where the scene
// region stands; a scene file writes the reference back, a project's scene carries the SVG itself.
// The bad cases are rows of tests/data/bad/EXPECTED.tsv.
#include "model/SceneFile.h"
#include "model/SceneJson.h"
#include "model/SceneRunner.h"
#include "model/SceneScript.h"

#include "../TestFiles.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>

using namespace vf;
using namespace vf::model;
using namespace Qt::StringLiterals;

namespace {

// A rectangle without an id and a ring (a hole in it) with one, half transparent.
const QByteArray kLogo = "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 100 100'>"
                         "<rect x='10' y='10' width='30' height='20' fill='#ff0000'/>"
                         "<path id='ring' fill='#0000ff' fill-opacity='0.5'"
                         " d='M70 20 A15 15 0 1 1 69.99 20 Z M70 28 A7 7 0 1 0 70.01 28 Z'/></svg>";
constexpr double kSpacing = 0.01;

// JSON is written with single quotes here, to keep the literals readable (and moc cannot read
// raw string literals).
QByteArray jsonText(QByteArray text) { return text.replace('\'', '"'); }

QByteArray sceneJson(const QByteArray& regions, const QByteArray& strokes = "[]")
{
    return jsonText("{'vectorfluid': 1, 'canvas': {'width': 2.0, 'height': 1.0}, 'tracking': {'max_spacing': 0.01}, 'regions': ")
           + regions + jsonText(", 'strokes': ") + strokes + "}";
}

QStringList names(const RegionTable& looks)
{
    QStringList list;
    for (const RegionLook& look : looks)
        list << look.name;
    return list;
}

} // namespace

class TestSceneSvg : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        m_dir = std::make_unique<QTemporaryDir>();
        QVERIFY(QDir(m_dir->path()).mkpath(u"art"_s));
        QVERIFY(test::writeFile(logoPath(), kLogo));
    }

    void regionsAreWhatImportSvgMakes()
    {
        const Scene scene = read(jsonText("[{'name': 'logo', 'shape': {'svg': 'art/logo.svg'}}]"));
        const SvgImport imported = importSvgFile(logoPath(), 2.0, 1.0, kSpacing);
        QVERIFY2(imported.ok(), qPrintable(imported.error));
        const std::vector<StartingRegion> regions = startingRegions(scene.regions.at(0), kSpacing);
        QCOMPARE(regions.size(), std::size_t(2));
        QCOMPARE(regions[0].name, u"logo/rect 1"_s);
        QCOMPARE(regions[1].name, u"logo/ring"_s);
        for (std::size_t i = 0; i < regions.size(); ++i) {
            QCOMPARE(regions[i].color, imported.shapes[i].color);
            QVERIFY(regions[i].contours == imported.shapes[i].contours);
            QVERIFY(regions[i].visible);
        }
        QCOMPARE(regions[0].color, QColor(255, 0, 0));
        QCOMPARE(regions[1].contours.size(), std::size_t(2));  // the ring and its hole
    }

    void regionColourPaintsEveryShape()
    {
        const Scene scene = read(jsonText("[{'name': 'logo', 'color': '#123456', 'visible': false, 'shape': {'svg': 'art/logo.svg'}}]"));
        for (const StartingRegion& look : startingLooks(scene.regions.at(0))) {
            QCOMPARE(look.color, QColor(0x12, 0x34, 0x56));
            QVERIFY(!look.visible);
        }
    }

    void absolutePathIsAllowed()
    {
        const QString elsewhere = m_dir->filePath(u"scenes/deeper"_s);
        QVERIFY(QDir().mkpath(elsewhere));
        const QString path = elsewhere + u"/scene.vfscene"_s;
        const QByteArray reference = QJsonDocument(QJsonArray{logoPath()}).toJson(QJsonDocument::Compact).mid(1).chopped(1);
        QVERIFY(test::writeFile(path, sceneJson(jsonText("[{'name': 'logo', 'shape': {'svg': ") + reference + "}}]")));
        const SceneReadResult result = readSceneFile(path);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QCOMPARE(startingLooks(result.scene.regions.at(0)).size(), std::size_t(2));
    }

    // The shapes take the scene region's place: what comes after it moves up, drops included.
    void laterRegionsAndDropsMoveUp()
    {
        const Scene scene = read(jsonText("[{'name': 'below', 'color': '#000000', 'shape': {'circle': {'center': [0.2, 0.8], 'radius': 0.05}}},"
                                      "{'name': 'logo', 'shape': {'svg': 'art/logo.svg'}},"
                                      "{'name': 'above', 'color': '#000000', 'shape': {'circle': {'center': [1.8, 0.8], 'radius': 0.05}}}]"),
                                 jsonText("[{'tool': 'drop', 'time': 0.001, 'center': [1.0, 0.8], 'radius': 0.05, 'color': '#00ff00'}]"));
        const SceneScript script(scene);
        QCOMPARE(names(script.looks()), (QStringList{u"below"_s, u"logo/rect 1"_s, u"logo/ring"_s, u"above"_s, u"drop 1"_s}));
        QCOMPARE(script.startingRegionCount(), 4);
        SceneRunner runner(scene);
        QCOMPARE(runner.simulation().regions().size(), std::size_t(4));
        QCOMPARE(runner.regionName(2), u"logo/ring"_s);
        runner.step(0.002);
        QCOMPARE(runner.regionName(4), u"drop 1"_s);
    }

    void writtenBackAsTheReference()
    {
        const Scene scene = read(jsonText("[{'name': 'logo', 'shape': {'svg': 'art/logo.svg'}}]"));
        const QString path = m_dir->filePath(u"again.vfscene"_s);
        QCOMPARE(writeSceneFile(scene, path), QString());
        const QJsonObject region = QJsonDocument::fromJson(test::readAll(path)).object()[u"regions"_s].toArray()[0].toObject();
        QCOMPARE(region[u"shape"_s].toObject(), (QJsonObject{{u"svg"_s, u"art/logo.svg"_s}}));
        QVERIFY(!region.contains(u"color"_s));  // the file's colours stay the file's
        const SceneReadResult again = readSceneFile(path);
        QVERIFY2(again.ok(), qPrintable(again.error));
        QVERIFY(again.scene == scene);
    }

    void projectSceneCarriesTheSvg()
    {
        const Scene scene = read(jsonText("[{'name': 'logo', 'shape': {'svg': 'art/logo.svg'}}]"));
        const QJsonObject embedded = sceneToJsonObject(scene, SvgShapes::Embedded);
        QVERIFY(QFile::remove(logoPath()));
        const Scene again = readSceneObject(json::Field(embedded, json::KeyPath()), {});
        QVERIFY(again == scene);
        const auto& before = std::get<SvgShape>(scene.regions[0].shape).shapes;
        const auto& after = std::get<SvgShape>(again.regions[0].shape).shapes;
        QCOMPARE(after.size(), before.size());
        for (std::size_t i = 0; i < before.size(); ++i)
            QVERIFY(after[i].contours == before[i].contours);
    }

    void referenceNeedsAFolder()
    {
        const SceneReadResult result = parseScene(sceneJson(jsonText("[{'name': 'logo', 'shape': {'svg': 'art/logo.svg'}}]")), u"clip"_s);
        QVERIFY(result.error.startsWith(u"clip: regions[0].shape.svg: the SVG's contents are missing"_s));
    }

    // The reader refuses scenes over tracking.max_vertices with this bound, before any step.
    void vertexBoundHolds()
    {
        const Scene scene = read(jsonText("[{'name': 'logo', 'shape': {'svg': 'art/logo.svg'}}]"));
        std::size_t vertices = 0;
        for (const StartingRegion& region : startingRegions(scene.regions[0], kSpacing))
            for (const sim::Polygon& contour : region.contours)
                vertices += contour.size();
        QVERIFY(vertices > 0);
        QVERIFY(shapeVertexBound(scene.regions[0].shape, kSpacing) >= double(vertices));
    }

private:
    QString logoPath() const { return m_dir->filePath(u"art/logo.svg"_s); }

    Scene read(const QByteArray& regions, const QByteArray& strokes = "[]")
    {
        const SceneReadResult result = parseScene(sceneJson(regions, strokes), u"scene"_s, m_dir->path());
        if (!result.ok())
            qWarning("%s", qPrintable(result.error));
        return result.scene;
    }

    std::unique_ptr<QTemporaryDir> m_dir;
};

QTEST_GUILESS_MAIN(TestSceneSvg)
#include "tst_scenesvg.moc"
