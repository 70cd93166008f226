// The headless command line (docs/command-line.md), run as the real `vectorfluid` binary
// through QProcess: exit codes, the one-line error contract, what is (and is not) written, the
// files read back by an XML parser and by the real readers (qpdf, Ghostscript, pdftoppm), the
// stats JSON against the geometry, and determinism of the reference backend.
// One file past 500 lines: every case runs the same binary through the helpers below.
#include "../TestFiles.h"
#include "CliRun.h"
#include "../render/SvgReadBack.h"
#include "../render/TestGeometry.h"

#include "model/SceneFile.h"
#include "sim/Crossings.h"

#include <QDir>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numeric>

using namespace vf;
using namespace vf::test;

namespace {

const QString kBadDir = QStringLiteral(VF_TEST_DATA "/bad");

// Two circles, a stylus stroke and a drop ("splash" at t = 0.1) in a 32×32 fluid: 50 steps of
// dt 0.01: under a second with sanitizers, a tenth of that in Release.
const QString kStirred = QStringLiteral(VF_TEST_DATA "/scenes/stirred.vfscene");
// The rounding of polyline SVG coordinates on a canvas whose larger side is 1 (render/SvgRounding.h).
constexpr double kSvgStep = 1e-6;
const qint64 kStirredSteps = 50;
// One circle in a steady single vortex, uniform spacing, max_vertices 200: the stretching needs more.
const QString kVertexLimit = QStringLiteral(VF_TEST_DATA "/scenes/vertex-limit.vfscene");
const qint64 kVertexLimitMax = 200;
const qint64 kVertexLimitSteps = 200;

// Exit 0 and a quiet stderr: nothing, or on a machine where no OpenCL device can run the scene,
// only the one line that says the reference backend runs instead.
QString checkDone(const CliResult& r)
{
    const bool quiet = r.err.isEmpty()
                       || (r.err.count('\n') == 1 && r.err.startsWith("vectorfluid: OpenCL backend unavailable (no OpenCL device"));
    return r.exitCode == 0 && quiet ? QString() : QStringLiteral("expected success: ") + describe(r);
}

using test::readAll;
using test::writeFile;

QJsonObject readJson(const QString& fileName) { return QJsonDocument::fromJson(readAll(fileName)).object(); }

// A copy of `scene` with its "time" replaced where steps >= 0 and dt > 0, written into `dir`.
QString sceneWithTime(const QString& scene, const QString& dir, qint64 steps, double dt)
{
    QJsonObject root = readJson(scene);
    QJsonObject time = root.value(QStringLiteral("time")).toObject();
    if (steps >= 0)
        time[QStringLiteral("steps")] = steps;
    if (dt > 0)
        time[QStringLiteral("dt")] = dt;
    root[QStringLiteral("time")] = time;
    const QString path = QDir(dir).filePath(QStringLiteral("edited.vfscene"));
    return writeFile(path, QJsonDocument(root).toJson()) ? path : QString();
}

qint64 vertexCount(const std::vector<sim::Polygon>& polygons)
{
    return std::accumulate(polygons.begin(), polygons.end(), qint64(0),
                           [](qint64 sum, const sim::Polygon& p) { return sum + qint64(p.size()); });
}

qint64 vertexCount(const test::ParsedSvg& svg)
{
    qint64 count = 0;
    for (const test::ParsedPath* path : test::regionPaths(svg))
        count += vertexCount(test::polygonsOf(*path));
    return count;
}

// Crossing pairs of edges among all the region paths of a polyline SVG we wrote.
std::size_t crossingsIn(const QString& svgFile)
{
    const test::ParsedSvg svg = test::parseSvg(svgFile);
    std::vector<sim::Polygon> polygons;
    for (const test::ParsedPath* region : test::regionPaths(svg))
        for (sim::Polygon& p : test::polygonsOf(*region))
            polygons.push_back(std::move(p));
    std::vector<const sim::Polygon*> contours;
    for (const sim::Polygon& p : polygons)
        contours.push_back(&p);
    return sim::countCrossings(contours);
}

// The stats file's shape and internal consistency (docs/command-line.md, "Stats").
QString checkStats(const QJsonObject& stats, qint64 steps)
{
    const QJsonArray regions = stats.value(QStringLiteral("regions")).toArray();
    const QJsonObject totals = stats.value(QStringLiteral("totals")).toObject();
    if (regions.isEmpty() || totals.isEmpty())
        return QStringLiteral("no regions[] or totals");
    qint64 sum = 0;
    for (const QJsonValue& value : regions) {
        const QJsonObject r = value.toObject();
        if (!r.value(QStringLiteral("name")).isString() || r.value(QStringLiteral("vertices")).toInteger() < 3
            || !(r.value(QStringLiteral("area")).toDouble() > 0) || !(r.value(QStringLiteral("perimeter")).toDouble() > 0))
            return QStringLiteral("bad region entry ") + QString::fromUtf8(QJsonDocument(r).toJson(QJsonDocument::Compact));
        sum += r.value(QStringLiteral("vertices")).toInteger();
    }
    const qint64 vertexSteps = totals.value(QStringLiteral("vertex_steps")).toInteger(-1);
    const double simSeconds = totals.value(QStringLiteral("sim_seconds")).toDouble(-1);
    if (totals.value(QStringLiteral("steps")).toInteger(-1) != steps)
        return QStringLiteral("totals.steps is not %1").arg(steps);
    if (totals.value(QStringLiteral("vertices")).toInteger(-1) != sum)
        return QStringLiteral("totals.vertices is not the regions' sum %1").arg(sum);
    if (steps == 0 ? vertexSteps != 0 : vertexSteps < steps * 3)
        return QStringLiteral("totals.vertex_steps %1 is impossible for %2 steps").arg(vertexSteps).arg(steps);
    if (!std::isfinite(simSeconds) || (steps == 0 ? simSeconds != 0 : !(simSeconds > 0)))
        return QStringLiteral("totals.sim_seconds %1 for %2 steps").arg(simSeconds).arg(steps);
    return {};
}

// The same contours and vertex counts, each coordinate within kSvgStep / 2 of the original.
bool roundedFrom(const std::vector<sim::Polygon>& svg, const std::vector<sim::Polygon>& original)
{
    if (svg.size() != original.size())
        return false;
    for (std::size_t c = 0; c < svg.size(); ++c) {
        if (svg[c].size() != original[c].size())
            return false;
        for (std::size_t i = 0; i < svg[c].size(); ++i)
            if (std::abs(svg[c][i].x - original[c][i].x) > 0.5 * kSvgStep * (1 + 1e-9)
                || std::abs(svg[c][i].y - original[c][i].y) > 0.5 * kSvgStep * (1 + 1e-9))
                return false;
    }
    return true;
}

// The contour with its segment ends rounded as a polyline SVG rounds vertices: to the double
// nearest the multiple of kSvgStep (Bézier SVGs are written exact).
render::FittedContour endsRounded(render::FittedContour contour)
{
    const auto rounded = [](sim::Vec2 p) {
        return sim::Vec2(std::nearbyint(p.x * 1e6) / 1e6, std::nearbyint(p.y * 1e6) / 1e6);  // 1e6 = 1 / kSvgStep
    };
    contour.start = rounded(contour.start);
    for (render::PathSegment& segment : contour.segments)
        segment.end = rounded(segment.end);
    return contour;
}

// Stats regions against a polyline SVG of the same state: names, vertex counts, areas, perimeters.
// The SVG's vertices are rounded to kSvgStep (the test scenes' canvases are at most 1 wide), each
// coordinate by at most half of it: a point moves at most step / √2, so each edge's length changes
// by at most √2·step and the area by at most about step / √2 per unit of perimeter (plus step²
// per vertex, bounded here by one step of perimeter each).
QString compareStatsWithSvg(const QJsonObject& stats, const test::ParsedSvg& svg)
{
    const QJsonArray regions = stats.value(QStringLiteral("regions")).toArray();
    const std::vector<const test::ParsedPath*> paths = test::regionPaths(svg);
    if (std::size_t(regions.size()) != paths.size())
        return QStringLiteral("%1 stats regions, %2 SVG paths").arg(regions.size()).arg(paths.size());
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const QJsonObject r = regions[qsizetype(i)].toObject();
        const std::vector<sim::Polygon> polygons = test::polygonsOf(*paths[i]);
        const double area = sim::filledArea(polygons);
        double length = 0;
        for (const sim::Polygon& p : polygons)
            length += sim::perimeter(p);
        const double vertices = double(vertexCount(polygons));
        const double areaBound = kSvgStep * (length + vertices * kSvgStep), lengthBound = std::sqrt(2.0) * kSvgStep * vertices;
        if (r.value(QStringLiteral("name")).toString() != paths[i]->label
            || r.value(QStringLiteral("vertices")).toInteger() != vertexCount(polygons)
            || std::abs(r.value(QStringLiteral("area")).toDouble() - area) > areaBound
            || std::abs(r.value(QStringLiteral("perimeter")).toDouble() - length) > lengthBound)
            return QStringLiteral("region %1 (%2) differs from the SVG").arg(i).arg(paths[i]->label);
    }
    return {};
}

// Some pixel within 3 levels of each colour: each region shows in the raster, not just its frame.
QString checkColoursPresent(const QImage& image, const QList<QColor>& colours)
{
    if (image.isNull())
        return QStringLiteral("no image");
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    for (const QColor& colour : colours) {
        bool found = false;
        for (int y = 0; y < rgb.height() && !found; ++y) {
            const QRgb* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
            for (int x = 0; x < rgb.width() && !found; ++x)
                found = std::abs(qRed(line[x]) - colour.red()) <= 3 && std::abs(qGreen(line[x]) - colour.green()) <= 3
                        && std::abs(qBlue(line[x]) - colour.blue()) <= 3;
        }
        if (!found)
            return QStringLiteral("colour %1 is nowhere in the image").arg(colour.name());
    }
    return {};
}

const QList<QColor> kStirredColours{QColor(0xfd, 0xf8, 0xef), QColor(0x1d, 0x35, 0x57), QColor(0xe6, 0x39, 0x46),
                                    QColor(0xf1, 0xc4, 0x0f)};
const QStringList kStirredRegions{QStringLiteral("ink"), QStringLiteral("madder"), QStringLiteral("splash")};

#define REQUIRE_TOOL(variable, name)                                                                     \
    const QString variable = QStandardPaths::findExecutable(QStringLiteral(name));                       \
    if (variable.isEmpty())                                                                              \
        QSKIP(name " is not installed");

} // namespace

class TestCli : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();

    // bad input: exit 2, one line, nothing written
    void badSceneIsRefused_data();
    void badSceneIsRefused();
    void badCommandLineIsRefused_data();
    void badCommandLineIsRefused();
    void writeFailureLeavesOtherFilesAlone_data();
    void writeFailureLeavesOtherFilesAlone();

    // one run of the stirred scene into every format, checked per output
    void allOutputsExist();
    void svgIsOnePathPerRegion();
    void pdfPassesQpdfAndRenders();
    void epsRendersInGhostscript();
    void pngLoads();
    void dpiSetsPngSize();
    void statsAreConsistent();
    void framesEveryKSteps();

    void overridesEqualEditedScene_data();
    void overridesEqualEditedScene();
    void zeroStepsGivesStartingShapes();
    void vertexStepsSumsEveryStep();
    void sameSceneTwiceIsByteIdentical();
    void polylineHasOnlyLinesBezierIsShorter();
    void vertexLimitExitsThreeAndWrites();
    void dropsOverTheLimitExitThree();
    void deviceLimitExitsThree();
    void brokenTopologyExitsFourAndWrites_data();
    void brokenTopologyExitsFourAndWrites();
    void overlappingStartPassesTopologyCheck();
    void nonFiniteFlowIsOneLine_data();
    void nonFiniteFlowIsOneLine();

    void backendChoiceAndFallback_data();
    void backendChoiceAndFallback();
    void devicesListsSomething();
    void helpOnEveryCommand_data();
    void helpOnEveryCommand();
    void versionOnEveryCommand_data();
    void versionOnEveryCommand();
    void renderWithoutOutputsWritesSvgBesideScene();

private:
    QString path(const QString& name) const { return m_dir->filePath(name); }
    QString full(const QString& name) const { return m_full.filePath(name); }

    QTemporaryDir m_full;  // the all-formats run of initTestCase
    CliResult m_fullRun;
    std::unique_ptr<QTemporaryDir> m_dir;  // fresh per test function
};

void TestCli::initTestCase()
{
    QVERIFY2(QFileInfo(kBinary).isExecutable(), qPrintable(kBinary));
    QVERIFY(m_full.isValid());
    m_fullRun = runCli({QStringLiteral("render"), kStirred, QStringLiteral("--out"), full(QStringLiteral("a.svg")),
                        QStringLiteral("--out"), full(QStringLiteral("a.pdf")), QStringLiteral("--out"),
                        full(QStringLiteral("a.eps")), QStringLiteral("--out"), full(QStringLiteral("a.png")),
                        QStringLiteral("--stats"), full(QStringLiteral("s.json")), QStringLiteral("--frames"),
                        full(QStringLiteral("frames")), QStringLiteral("--every"), QStringLiteral("10")});
}

void TestCli::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
}

// ---- bad input ---------------------------------------------------------------------------------

void TestCli::badSceneIsRefused_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QString>("expected");
    // EXPECTED.tsv: "file<TAB>substring" per line.
    const QList<QByteArray> lines = readAll(kBadDir + QStringLiteral("/EXPECTED.tsv")).split('\n');
    int rows = 0;
    for (const QByteArray& line : lines) {
        const QList<QByteArray> fields = line.split('\t');
        if (fields.size() != 2)
            continue;
        const QString file = QString::fromUtf8(fields[0]);
        QTest::newRow(fields[0].constData()) << kBadDir + u'/' + file << QString::fromUtf8(fields[1]);
        ++rows;
    }
    QVERIFY2(rows >= 41, "EXPECTED.tsv is missing or short");
    QTest::newRow("missing file") << kBadDir + QStringLiteral("/no-such-scene.vfscene") << QStringLiteral("cannot open");
}

void TestCli::badSceneIsRefused()
{
    QFETCH(QString, scene);
    QFETCH(QString, expected);
    const CliResult r = runCli({QStringLiteral("render"), scene, QStringLiteral("--out"), path(QStringLiteral("X.svg")),
                                QStringLiteral("--stats"), path(QStringLiteral("S.json")), QStringLiteral("--frames"),
                                path(QStringLiteral("frames"))});
    CHECK_OK(checkOneLineError(r, {scene, expected}));
    QCOMPARE(QDir(m_dir->path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden), QStringList());
}

void TestCli::badCommandLineIsRefused_data()
{
    QTest::addColumn<QStringList>("arguments");  // "@scene" stands for a good scene, "@dir" for the folder
    QTest::addColumn<QString>("expected");
    const QString render = QStringLiteral("render");
    QTest::newRow("unknown option last") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--bogus")}
                                         << QStringLiteral("unknown option --bogus");
    QTest::newRow("unknown option first") << QStringList{render, QStringLiteral("--bogus"), QStringLiteral("@scene")}
                                          << QStringLiteral("unknown option --bogus");
    QTest::newRow("negative steps") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--steps"), QStringLiteral("-1")}
                                    << QStringLiteral("--steps: '-1'");
    QTest::newRow("fractional steps") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--steps"), QStringLiteral("2.5")}
                                      << QStringLiteral("--steps: '2.5'");
    QTest::newRow("steps without value") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--steps")}
                                         << QStringLiteral("--steps needs a value");
    QTest::newRow("zero dt") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--dt"), QStringLiteral("0")}
                             << QStringLiteral("--dt: '0'");
    QTest::newRow("nan dt") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--dt"), QStringLiteral("nan")}
                            << QStringLiteral("--dt: 'nan'");
    QTest::newRow("infinite dt") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--dt"), QStringLiteral("inf")}
                                 << QStringLiteral("--dt: 'inf'");
    QTest::newRow("unknown format") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--out"), QStringLiteral("@dir/file.xyz")}
                                    << QStringLiteral("file.xyz");
    QTest::newRow("zero dpi") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--dpi"), QStringLiteral("0")}
                              << QStringLiteral("--dpi: '0'");
    QTest::newRow("unknown backend") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--backend"), QStringLiteral("cuda")}
                                     << QStringLiteral("--backend: 'cuda'");
    QTest::newRow("every without frames") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--every"), QStringLiteral("3")}
                                          << QStringLiteral("--every needs --frames");
    QTest::newRow("every zero") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("--frames"), QStringLiteral("@dir/f"),
                                               QStringLiteral("--every"), QStringLiteral("0")}
                                << QStringLiteral("--every: '0'");
    QTest::newRow("no scene") << QStringList{render} << QStringLiteral("no scene file given");
    // Qt's file engine adds "QFSFileEngine::open: No file name specified" of its own.
    QTest::newRow("empty scene name") << QStringList{render, QString()} << QStringLiteral(": cannot open: No file name specified");
    QTest::newRow("scene is a folder") << QStringList{render, QStringLiteral("@dir")} << QStringLiteral("cannot open");
    QTest::newRow("two scenes") << QStringList{render, QStringLiteral("@scene"), QStringLiteral("@scene")}
                                << QStringLiteral("only one scene file");
    QTest::newRow("devices with an argument") << QStringList{QStringLiteral("devices"), QStringLiteral("--all")}
                                              << QStringLiteral("devices takes no arguments");
    QTest::newRow("unknown command") << QStringList{QStringLiteral("frobnicate")} << QStringLiteral("frobnicate");
    QTest::newRow("unknown program option") << QStringList{QStringLiteral("--bogus")} << QStringLiteral("unknown option --bogus");
}

void TestCli::badCommandLineIsRefused()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, expected);
    arguments.replaceInStrings(QStringLiteral("@scene"), kStirred);
    arguments.replaceInStrings(QStringLiteral("@dir"), m_dir->path());
    // Good outputs ahead of the fault: none of them may appear.
    if (arguments.front() == QLatin1String("render"))
        arguments = QStringList{arguments.front(), QStringLiteral("--out"), path(QStringLiteral("a.svg")),
                                QStringLiteral("--stats"), path(QStringLiteral("s.json"))}
                    + arguments.mid(1);
    const CliResult r = runCli(arguments);
    CHECK_OK(checkOneLineError(r, {expected}));
    QCOMPARE(QDir(m_dir->path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden), QStringList());
}

void TestCli::writeFailureLeavesOtherFilesAlone_data()
{
    QTest::addColumn<QStringList>("arguments");  // "@dir" stands for the folder holding keep.svg, keep.json
    QTest::addColumn<QString>("culprit");
    const QString out = QStringLiteral("--out"), stats = QStringLiteral("--stats");
    const QString keepSvg = QStringLiteral("@dir/keep.svg"), keepJson = QStringLiteral("@dir/keep.json");
    QTest::newRow("--out into a missing folder")
        << QStringList{out, QStringLiteral("@dir/no-such-dir/x.svg"), out, keepSvg, stats, keepJson}
        << QStringLiteral("@dir/no-such-dir/x.svg");
    QTest::newRow("--out into an absolute missing folder")
        << QStringList{out, QStringLiteral("/nonexistent-dir/x.svg"), out, keepSvg, stats, keepJson}
        << QStringLiteral("/nonexistent-dir/x.svg");
    QTest::newRow("--out into a missing folder after a good one")
        << QStringList{out, keepSvg, stats, keepJson, out, QStringLiteral("@dir/no-such-dir/x.svg")}
        << QStringLiteral("@dir/no-such-dir/x.svg");
    QTest::newRow("--stats into a missing folder")
        << QStringList{stats, QStringLiteral("@dir/no-such-dir/s.json")} << QStringLiteral("@dir/no-such-dir/s.json");
    QTest::newRow("--frames under a file")
        << QStringList{QStringLiteral("--frames"), QStringLiteral("@dir/keep.json/frames"), out, keepSvg, stats, keepJson}
        << QStringLiteral("@dir/keep.json/frames");
}

void TestCli::writeFailureLeavesOtherFilesAlone()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, culprit);
    const QByteArray keepSvg = "<svg>the previous picture</svg>\n", keepJson = "{\"previous\": true}\n";
    QVERIFY(writeFile(path(QStringLiteral("keep.svg")), keepSvg));
    QVERIFY(writeFile(path(QStringLiteral("keep.json")), keepJson));
    arguments.replaceInStrings(QStringLiteral("@dir"), m_dir->path());
    culprit.replace(QStringLiteral("@dir"), m_dir->path());

    const CliResult r = runCli(QStringList{QStringLiteral("render"), kStirred, QStringLiteral("--steps"), QStringLiteral("3")} + arguments);
    CHECK_OK(checkOneLineError(r, {culprit}));
    QCOMPARE(readAll(path(QStringLiteral("keep.svg"))), keepSvg);
    QCOMPARE(readAll(path(QStringLiteral("keep.json"))), keepJson);
    QCOMPARE(QDir(m_dir->path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden),
             (QStringList{QStringLiteral("keep.json"), QStringLiteral("keep.svg")}));  // no temporaries left
    QVERIFY(!QFileInfo::exists(QStringLiteral("/nonexistent-dir")));
}

// ---- the all-formats run -----------------------------------------------------------------------

void TestCli::allOutputsExist()
{
    QCOMPARE(m_fullRun.exitCode, 0);
    QVERIFY2(m_fullRun.err.isEmpty(), m_fullRun.err.constData());
    for (const char* name : {"a.svg", "a.pdf", "a.eps", "a.png", "s.json"})
        QVERIFY2(QFileInfo(full(QLatin1String(name))).size() > 0, name);
}

void TestCli::svgIsOnePathPerRegion()
{
    const test::ParsedSvg svg = test::parseSvg(full(QStringLiteral("a.svg")));
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QCOMPARE(svg.viewBox, QStringLiteral("0 0 1 0.8"));
    QCOMPARE(svg.backgroundFill, kStirredColours.front().name());
    QCOMPARE(svg.layers.size(), std::size_t(kStirredRegions.size() + 1));  // + the background layer
    for (qsizetype i = 0; i < kStirredRegions.size(); ++i) {
        const test::ParsedLayer& layer = svg.layers[std::size_t(i) + 1];
        QCOMPARE(layer.paths.size(), std::size_t(1));
        QCOMPARE(layer.paths.front().label, kStirredRegions[i]);
        QCOMPARE(layer.paths.front().id, kStirredRegions[i]);
        QCOMPARE(layer.paths.front().fill, kStirredColours[i + 1].name());
        QCOMPARE(layer.paths.front().fillRule, QStringLiteral("evenodd"));
        QVERIFY(!layer.paths.front().contours.empty());
    }
}

void TestCli::pdfPassesQpdfAndRenders()
{
    REQUIRE_TOOL(qpdf, "qpdf");
    REQUIRE_TOOL(pdftoppm, "pdftoppm");
    const CliResult check = runProgram(qpdf, {QStringLiteral("--check"), full(QStringLiteral("a.pdf"))});
    QVERIFY2(check.exitCode == 0, check.out.constData());
    const CliResult raster = runProgram(pdftoppm, {QStringLiteral("-png"), QStringLiteral("-r"), QStringLiteral("36"),
                                                   QStringLiteral("-singlefile"), full(QStringLiteral("a.pdf")),
                                                   path(QStringLiteral("pdf"))});
    QVERIFY2(raster.exitCode == 0, raster.err.constData());
    CHECK_OK(checkColoursPresent(QImage(path(QStringLiteral("pdf.png"))), kStirredColours));
}

void TestCli::epsRendersInGhostscript()
{
    REQUIRE_TOOL(gs, "gs");
    const QString png = path(QStringLiteral("eps.png"));
    const CliResult r = runProgram(gs, {QStringLiteral("-q"), QStringLiteral("-dSAFER"), QStringLiteral("-dBATCH"),
                                        QStringLiteral("-dNOPAUSE"), QStringLiteral("-sDEVICE=png16m"),
                                        QStringLiteral("-dEPSCrop"), QStringLiteral("-r36"),
                                        QStringLiteral("-sOutputFile=") + png, full(QStringLiteral("a.eps"))});
    QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
    CHECK_OK(checkColoursPresent(QImage(png), kStirredColours));
}

void TestCli::pngLoads()
{
    const QImage image(full(QStringLiteral("a.png")));
    QCOMPARE(image.size(), QSize(1200, 960));  // 576 pt at 150 dpi, the canvas' 1 : 0.8 aspect
    CHECK_OK(checkColoursPresent(image, kStirredColours));
}

void TestCli::dpiSetsPngSize()
{
    const QString png = path(QStringLiteral("a.png"));
    CHECK_OK(checkDone(runCli({QStringLiteral("render"), kStirred, QStringLiteral("--steps"), QStringLiteral("0"),
                               QStringLiteral("--dpi"), QStringLiteral("36"), QStringLiteral("--out"), png})));
    QCOMPARE(QImage(png).size(), QSize(288, 230));  // 576 × 460.8 pt at half a pixel per point
}

void TestCli::statsAreConsistent()
{
    const QJsonObject stats = readJson(full(QStringLiteral("s.json")));
    CHECK_OK(checkStats(stats, kStirredSteps));
    QStringList names;
    for (const QJsonValue& r : stats.value(QStringLiteral("regions")).toArray())
        names << r.toObject().value(QStringLiteral("name")).toString();
    QCOMPARE(names, kStirredRegions);
    QCOMPARE(stats.value(QStringLiteral("limit_reached")).toBool(true), false);
}

void TestCli::framesEveryKSteps()
{
    QStringList expected;
    for (qint64 step = 0; step <= kStirredSteps; step += 10)
        expected << QStringLiteral("frame-%1.svg").arg(step, 6, 10, QLatin1Char('0'));
    QCOMPARE(QDir(full(QStringLiteral("frames"))).entryList(QDir::AllEntries | QDir::NoDotAndDotDot, QDir::Name), expected);
    for (const QString& frame : expected) {
        const test::ParsedSvg svg = test::parseSvg(full(QStringLiteral("frames/") + frame));
        QVERIFY2(svg.error.isEmpty(), qPrintable(frame + QStringLiteral(": ") + svg.error));
    }
    // The last frame is the final state, exported with the same options as --out.
    QCOMPARE(readAll(full(QStringLiteral("frames/") + expected.back())), readAll(full(QStringLiteral("a.svg"))));
}

// ---- time overrides, determinism, modes --------------------------------------------------------

void TestCli::overridesEqualEditedScene_data()
{
    QTest::addColumn<qint64>("steps");  // -1: not overridden
    QTest::addColumn<double>("dt");     // 0: not overridden
    QTest::newRow("--steps") << qint64(17) << 0.0;
    QTest::newRow("--dt") << qint64(-1) << 0.004;
    QTest::newRow("--steps --dt") << qint64(23) << 0.015;
}

// `render scene --steps N --dt S` must equal rendering the scene edited to say N and S, and differ
// from the scene as it is (the all-formats run).
void TestCli::overridesEqualEditedScene()
{
    QFETCH(qint64, steps);
    QFETCH(double, dt);
    const QString edited = sceneWithTime(kStirred, m_dir->path(), steps, dt);
    QVERIFY(!edited.isEmpty());
    QStringList overrides;
    if (steps >= 0)
        overrides << QStringLiteral("--steps") << QString::number(steps);
    if (dt > 0)
        overrides << QStringLiteral("--dt") << QString::number(dt, 'g', 17);

    const auto render = [&](const QString& scene, const QStringList& extra, const QString& name) {
        return runCli(QStringList{QStringLiteral("render"), scene, QStringLiteral("--out"), path(name + QStringLiteral(".svg")),
                                  QStringLiteral("--stats"), path(name + QStringLiteral(".json"))}
                      + extra);
    };
    CHECK_OK(checkDone(render(kStirred, overrides, QStringLiteral("override"))));
    CHECK_OK(checkDone(render(edited, {}, QStringLiteral("edited"))));

    CHECK_OK(checkStats(readJson(path(QStringLiteral("override.json"))), steps >= 0 ? steps : kStirredSteps));
    const QByteArray overridden = readAll(path(QStringLiteral("override.svg")));
    QVERIFY(!overridden.isEmpty());
    QCOMPARE(overridden, readAll(path(QStringLiteral("edited.svg"))));
    QVERIFY(overridden != readAll(full(QStringLiteral("a.svg"))));  // the override did change something
}

void TestCli::zeroStepsGivesStartingShapes()
{
    // The reference backend keeps the starting shapes' doubles exactly (OpenCL holds float32).
    const CliResult r = runCli({QStringLiteral("render"), kStirred, QStringLiteral("--steps"), QStringLiteral("0"),
                                QStringLiteral("--backend"), QStringLiteral("reference"),
                                QStringLiteral("--polyline"), QStringLiteral("--out"), path(QStringLiteral("a.svg")),
                                QStringLiteral("--stats"), path(QStringLiteral("s.json"))});
    CHECK_OK(checkDone(r));
    CHECK_OK(checkStats(readJson(path(QStringLiteral("s.json"))), 0));

    const model::SceneReadResult scene = model::readSceneFile(kStirred);
    QVERIFY2(scene.ok(), qPrintable(scene.error));
    const test::ParsedSvg svg = test::parseSvg(path(QStringLiteral("a.svg")));
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    const std::vector<const test::ParsedPath*> paths = test::regionPaths(svg);
    QCOMPARE(paths.size(), scene.scene.regions.size());  // the drop at t = 0.1 has not landed
    for (std::size_t i = 0; i < paths.size(); ++i) {
        QCOMPARE(paths[i]->label, scene.scene.regions[i].name);
        QVERIFY(roundedFrom(test::polygonsOf(*paths[i]),
                            model::shapeContours(scene.scene.regions[i].shape, scene.scene.tracking.maxSpacing)));
    }
}

// vertex_steps is the sum over steps of the vertex count after the step: read it off every frame.
void TestCli::vertexStepsSumsEveryStep()
{
    const qint64 steps = 20;
    const QString frames = path(QStringLiteral("frames"));
    const CliResult r = runCli({QStringLiteral("render"), kStirred, QStringLiteral("--steps"), QString::number(steps),
                                QStringLiteral("--polyline"), QStringLiteral("--frames"), frames, QStringLiteral("--every"),
                                QStringLiteral("1"), QStringLiteral("--stats"), path(QStringLiteral("s.json"))});
    CHECK_OK(checkDone(r));
    qint64 sum = 0;
    test::ParsedSvg last;
    for (qint64 step = 1; step <= steps; ++step) {
        last = test::parseSvg(QDir(frames).filePath(QStringLiteral("frame-%1.svg").arg(step, 6, 10, QLatin1Char('0'))));
        QVERIFY2(last.error.isEmpty(), qPrintable(last.error));
        sum += vertexCount(last);
    }
    const QJsonObject stats = readJson(path(QStringLiteral("s.json")));
    CHECK_OK(checkStats(stats, steps));
    const QJsonObject totals = stats.value(QStringLiteral("totals")).toObject();
    QCOMPARE(totals.value(QStringLiteral("vertex_steps")).toInteger(), sum);
    QCOMPARE(totals.value(QStringLiteral("vertices")).toInteger(), vertexCount(last));
    CHECK_OK(compareStatsWithSvg(stats, last));
}

// A second run of the all-formats scene, without the other outputs: the same bytes and numbers.
void TestCli::sameSceneTwiceIsByteIdentical()
{
    const QString svgFile = path(QStringLiteral("again.svg")), statsFile = path(QStringLiteral("again.json"));
    CHECK_OK(checkDone(runCli({QStringLiteral("render"), kStirred, QStringLiteral("--out"), svgFile, QStringLiteral("--stats"), statsFile})));
    const QByteArray svg = readAll(svgFile);
    QVERIFY(svg.size() > 1000);
    QVERIFY2(svg == readAll(full(QStringLiteral("a.svg"))), "two runs of the same scene differ");

    const QJsonObject again = readJson(statsFile), first = readJson(full(QStringLiteral("s.json")));
    QCOMPARE(again.value(QStringLiteral("regions")), first.value(QStringLiteral("regions")));
    for (const char* key : {"steps", "vertices", "vertex_steps"}) {
        const auto total = [key](const QJsonObject& stats) {
            return stats.value(QStringLiteral("totals")).toObject().value(QLatin1String(key)).toInteger(-1);
        };
        QCOMPARE(total(again), total(first));
    }
}

// The same state in both modes: --polyline writes every vertex as a line, the default fits Béziers
// whose segments end on those vertices, with far fewer segments.
void TestCli::polylineHasOnlyLinesBezierIsShorter()
{
    const QString polylineFile = path(QStringLiteral("polyline.svg"));
    CHECK_OK(checkDone(runCli({QStringLiteral("render"), kStirred, QStringLiteral("--polyline"), QStringLiteral("--out"), polylineFile})));
    const test::ParsedSvg polyline = test::parseSvg(polylineFile), bezier = test::parseSvg(full(QStringLiteral("a.svg")));
    QVERIFY2(polyline.error.isEmpty(), qPrintable(polyline.error));
    QVERIFY2(bezier.error.isEmpty(), qPrintable(bezier.error));

    const auto count = [](const test::ParsedSvg& svg, bool curves) {
        qsizetype n = 0;
        for (const test::ParsedPath* p : test::regionPaths(svg))
            for (const render::FittedContour& c : p->contours)
                n += std::count_if(c.segments.begin(), c.segments.end(),
                                   [curves](const render::PathSegment& s) { return !curves || !s.isLine; });
        return n;
    };
    QCOMPARE(count(polyline, true), 0);
    QVERIFY(count(bezier, true) > 0);
    QVERIFY2(count(bezier, false) < count(polyline, false) / 2,
             qPrintable(QStringLiteral("%1 Bézier segments vs %2 polyline").arg(count(bezier, false)).arg(count(polyline, false))));

    const std::vector<const test::ParsedPath*> lines = test::regionPaths(polyline), curves = test::regionPaths(bezier);
    QCOMPARE(lines.size(), curves.size());
    for (std::size_t r = 0; r < lines.size(); ++r) {
        QCOMPARE(curves[r]->contours.size(), lines[r]->contours.size());
        for (std::size_t c = 0; c < lines[r]->contours.size(); ++c)
            QVERIFY(test::endsFollowVertices(endsRounded(curves[r]->contours[c]), test::verticesOf(lines[r]->contours[c])));
    }
}

void TestCli::vertexLimitExitsThreeAndWrites()
{
    const QString svgFile = path(QStringLiteral("a.svg")), pngFile = path(QStringLiteral("a.png")),
                  statsFile = path(QStringLiteral("s.json"));
    const CliResult r = runCli({QStringLiteral("render"), kVertexLimit, QStringLiteral("--polyline"), QStringLiteral("--out"),
                                svgFile, QStringLiteral("--out"), pngFile, QStringLiteral("--stats"), statsFile});
    CHECK_OK(checkOneLineError(r, {kVertexLimit, QStringLiteral("max_vertices")}, 3));

    const QJsonObject stats = readJson(statsFile);
    const qint64 steps = stats.value(QStringLiteral("totals")).toObject().value(QStringLiteral("steps")).toInteger(-1);
    QVERIFY2(steps > 0 && steps < kVertexLimitSteps, qPrintable(QString::number(steps)));
    CHECK_OK(checkStats(stats, steps));
    QCOMPARE(stats.value(QStringLiteral("limit_reached")).toBool(), true);
    QVERIFY(r.err.contains(QByteArray::number(steps)));  // says where it stopped

    const test::ParsedSvg svg = test::parseSvg(svgFile);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    CHECK_OK(compareStatsWithSvg(stats, svg));  // the files hold the same state
    QVERIFY(vertexCount(svg) <= kVertexLimitMax);
    QVERIFY(!QImage(pngFile).isNull());
}

void TestCli::dropsOverTheLimitExitThree()
{
    // Two large drops at t = 0 take the vertex count over max_vertices before any step.
    const QString scene = QStringLiteral(VF_TEST_DATA "/scenes/drop-limit.vfscene");
    const QString svgFile = path(QStringLiteral("a.svg")), statsFile = path(QStringLiteral("s.json"));
    const CliResult r = runCli({QStringLiteral("render"), scene, QStringLiteral("--out"), svgFile, QStringLiteral("--stats"), statsFile});
    CHECK_OK(checkOneLineError(r, {scene, QStringLiteral("max_vertices (520) reached at step 0")}, 3));
    QCOMPARE(readJson(statsFile).value(QStringLiteral("limit_reached")).toBool(), true);
    QVERIFY(QFileInfo::exists(svgFile));
}

void TestCli::deviceLimitExitsThree()
{
    // The OpenCL device's vertex limit made smaller than the scene's max_vertices (200): the run
    // stops there with exit 3 and one line naming that limit, and the files hold the state.
    if (runCli({QStringLiteral("devices")}).out.startsWith("no OpenCL devices"))
        QSKIP("no OpenCL device on this machine");
    const QString svgFile = path(QStringLiteral("a.svg")), statsFile = path(QStringLiteral("s.json"));
    qputenv("VF_OPENCL_MAX_VERTICES", "150");
    const CliResult r = runCli({QStringLiteral("render"), kVertexLimit, QStringLiteral("--backend"), QStringLiteral("opencl"),
                                QStringLiteral("--polyline"), QStringLiteral("--out"), svgFile, QStringLiteral("--stats"),
                                statsFile});
    qunsetenv("VF_OPENCL_MAX_VERTICES");
    CHECK_OK(checkOneLineError(r, {kVertexLimit, QStringLiteral("the OpenCL device's vertex limit (150) reached at step")}, 3));
    QCOMPARE(readJson(statsFile).value(QStringLiteral("limit_reached")).toBool(), true);
    const test::ParsedSvg svg = test::parseSvg(svgFile);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QVERIFY(vertexCount(svg) <= 150);
}

void TestCli::brokenTopologyExitsFourAndWrites_data()
{
    QTest::addColumn<QString>("backend");
    QTest::newRow("reference") << QStringLiteral("reference");
    QTest::newRow("default") << QString();
}

// Steps of 2 s through a fast single vortex (a step the engine cannot keep simple: RK4 is not
// one to one at that size): the check names the step, the regions and the point, and the files
// hold that step. (The first crossing listed is one of the ink's own: the step's contour surgery
// cut loops where the ink already crossed itself.)
void TestCli::brokenTopologyExitsFourAndWrites()
{
    QFETCH(QString, backend);
    const QString scene = QStringLiteral(VF_TEST_DATA "/scenes/broken-topology.vfscene");
    const QString svgFile = path(QStringLiteral("a.svg")), statsFile = path(QStringLiteral("s.json"));
    QStringList arguments{QStringLiteral("render"), scene, QStringLiteral("--check-topology"), QStringLiteral("1"),
                          QStringLiteral("--polyline"), QStringLiteral("--out"), svgFile, QStringLiteral("--stats"), statsFile};
    if (!backend.isEmpty())
        arguments << QStringLiteral("--backend") << backend;
    const CliResult r = runCli(arguments);
    CHECK_OK(checkOneLineError(r, {scene, QStringLiteral("contours cross at step 1 (t = 2 s)"), QStringLiteral("'ink'")}, 4));
    QCOMPARE(readJson(statsFile).value(QStringLiteral("totals")).toObject().value(QStringLiteral("steps")).toInteger(), 1);
    QVERIFY(crossingsIn(svgFile) > 0);  // the crossing it reported is in the file
}

// Regions that overlap from the start cross from the start; that is the scene, not the engine.
void TestCli::overlappingStartPassesTopologyCheck()
{
    const QString svgFile = path(QStringLiteral("a.svg"));
    CHECK_OK(checkDone(runCli({QStringLiteral("render"), QStringLiteral(VF_TEST_DATA "/scenes/overlapping.vfscene"),
                               QStringLiteral("--check-topology"), QStringLiteral("1"), QStringLiteral("--polyline"),
                               QStringLiteral("--out"), svgFile})));
    QVERIFY(crossingsIn(svgFile) > 0);  // still overlapping
}

void TestCli::nonFiniteFlowIsOneLine_data()
{
    QTest::addColumn<QString>("backend");
    QTest::newRow("reference") << QStringLiteral("reference");
    QTest::newRow("default") << QString();
}

void TestCli::nonFiniteFlowIsOneLine()
{
    // A flow that is not a number left of x = 0.45, where the ink is: one line naming the scene,
    // and nothing written, whichever backend runs it.
    QFETCH(QString, backend);
    const QString scene = QStringLiteral(VF_TEST_DATA "/scenes/singular-flow.vfscene");
    QStringList arguments{QStringLiteral("render"), scene, QStringLiteral("--out"), path(QStringLiteral("a.svg"))};
    if (!backend.isEmpty())
        arguments << QStringLiteral("--backend") << backend;
    const CliResult r = runCli(arguments);
    CHECK_OK(checkOneLineError(r, {scene, QStringLiteral("non-finite")}));
    QVERIFY(!QFileInfo::exists(path(QStringLiteral("a.svg"))));
}

// ---- the other commands ------------------------------------------------------------------------

void TestCli::devicesListsSomething()
{
    const CliResult r = runCli({QStringLiteral("devices")});
    QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
    QVERIFY2(!r.out.trimmed().isEmpty() && r.out.endsWith('\n'), qPrintable(describe(r)));
}

void TestCli::backendChoiceAndFallback_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<QString>("backend");
    QTest::addColumn<bool>("needsDevice");
    QTest::addColumn<QString>("saysOnStderr");
    QTest::newRow("default") << kStirred << QStringList() << QStringLiteral("opencl") << true << QString();
    QTest::newRow("reference") << kStirred << QStringList{QStringLiteral("--backend"), QStringLiteral("reference")}
                               << QStringLiteral("reference") << false << QString();
    QTest::newRow("no such device") << kStirred << QStringList{QStringLiteral("--device"), QStringLiteral("999")}
                                    << QStringLiteral("reference") << false
                                    << QStringLiteral("OpenCL backend unavailable (there is no OpenCL device 999");
    QTest::newRow("expression OpenCL cannot compile")
        << QStringLiteral(VF_TEST_DATA "/scenes/log-flow.vfscene") << QStringList() << QStringLiteral("reference") << true
        << QStringLiteral("'log' is not supported by the OpenCL backend");
}

void TestCli::backendChoiceAndFallback()
{
    QFETCH(QString, scene);
    QFETCH(QStringList, options);
    QFETCH(QString, backend);
    QFETCH(bool, needsDevice);
    QFETCH(QString, saysOnStderr);
    if (needsDevice && runCli({QStringLiteral("devices")}).out.startsWith("no OpenCL devices"))
        QSKIP("no OpenCL device on this machine");
    const CliResult r = runCli(QStringList{QStringLiteral("render"), scene, QStringLiteral("--steps"), QStringLiteral("5"),
                                           QStringLiteral("--stats"), path(QStringLiteral("s.json"))}
                               + options);
    QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
    if (saysOnStderr.isEmpty()) {
        QVERIFY2(r.err.isEmpty(), qPrintable(describe(r)));
    } else {
        QVERIFY2(r.err.count('\n') == 1 && QString::fromUtf8(r.err).contains(saysOnStderr), qPrintable(describe(r)));
    }
    QCOMPARE(readJson(path(QStringLiteral("s.json")))[QStringLiteral("backend")].toString(), backend);
}

void TestCli::helpOnEveryCommand_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QStringList>("mentions");  // what the help must say
    const QStringList program{QStringLiteral("vectorfluid render SCENE"), QStringLiteral("vectorfluid animate SCENE"),
                              QStringLiteral("vectorfluid devices"), QStringLiteral("--version")};
    const QStringList render{QStringLiteral("vectorfluid render SCENE"), QStringLiteral("--check-topology <K>"),
                             QStringLiteral("--polyline"), QStringLiteral("beside it")};
    const QStringList animate{QStringLiteral("usage: vectorfluid animate SCENE|PROJECT (--out FILE | --frames DIR"), QStringLiteral("--fps <N>"),
                              QStringLiteral("--transparent"), QStringLiteral("Lottie")};
    const QStringList devices{QStringLiteral("usage: vectorfluid devices"), QStringLiteral("--help")};
    for (const QString& help : {QStringLiteral("--help"), QStringLiteral("-h")}) {
        QTest::addRow("vectorfluid %s", qPrintable(help)) << QStringList{help} << program;
        QTest::addRow("render %s", qPrintable(help)) << QStringList{QStringLiteral("render"), help} << render;
        QTest::addRow("render SCENE %s", qPrintable(help)) << QStringList{QStringLiteral("render"), kStirred, help} << render;
        QTest::addRow("animate %s", qPrintable(help)) << QStringList{QStringLiteral("animate"), help} << animate;
        QTest::addRow("devices %s", qPrintable(help)) << QStringList{QStringLiteral("devices"), help} << devices;
    }
}

// Help goes to stdout with exit 0, and nothing is run or written.
void TestCli::helpOnEveryCommand()
{
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, mentions);
    const CliResult r = runCli(arguments);
    QVERIFY2(r.exitCode == 0 && r.err.isEmpty(), qPrintable(describe(r)));
    for (const QString& mention : mentions)
        QVERIFY2(r.out.contains(mention.toUtf8()), qPrintable(mention + QStringLiteral(" is not in: ") + describe(r)));
    QVERIFY(!QFileInfo::exists(QStringLiteral(VF_TEST_DATA "/scenes/stirred.svg")));
}

void TestCli::versionOnEveryCommand_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("vectorfluid") << QStringList{QStringLiteral("--version")};
    QTest::newRow("render") << QStringList{QStringLiteral("render"), QStringLiteral("--version")};
    QTest::newRow("devices") << QStringList{QStringLiteral("devices"), QStringLiteral("--version")};
}

void TestCli::versionOnEveryCommand()
{
    QFETCH(QStringList, arguments);
    const CliResult r = runCli(arguments);
    QVERIFY2(r.exitCode == 0 && r.err.isEmpty(), qPrintable(describe(r)));
    QVERIFY2(QRegularExpression(QStringLiteral("^vectorfluid \\d+\\.\\d+\\.\\d+\n$")).match(QString::fromUtf8(r.out)).hasMatch(),
             qPrintable(describe(r)));
}

// `render SCENE` alone writes SCENE's name with .svg beside the scene and says so.
void TestCli::renderWithoutOutputsWritesSvgBesideScene()
{
    const QString scene = path(QStringLiteral("my scene.v1.vfscene"));
    QVERIFY(QFile::copy(kStirred, scene));
    const CliResult r = runCli({QStringLiteral("render"), scene, QStringLiteral("--steps"), QStringLiteral("15")});
    CHECK_OK(checkDone(r));
    const QString svgFile = path(QStringLiteral("my scene.v1.svg"));
    QCOMPARE(QString::fromUtf8(r.out), QStringLiteral("wrote %1\n").arg(svgFile));
    const test::ParsedSvg svg = test::parseSvg(svgFile);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QCOMPARE(test::regionPaths(svg).size(), std::size_t(kStirredRegions.size()));
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
