// Scene files: every broken file gives one clear line, every demo scene reads, writing and reading
// back loses nothing, a failed save keeps the old file, and shapes become well-formed contours.
#include "model/SceneFile.h"
#include "sim/AnalyticFlow.h"
#include "sim/Crossings.h"

#include "../TestFiles.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRandomGenerator>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

using namespace vf;
using namespace vf::model;
using namespace Qt::StringLiterals;

namespace {

const QString kBadDir = QStringLiteral(VF_TEST_DATA "/bad");
const QString kScenesDir = QStringLiteral(VF_SOURCE_DIR "/resources/scenes");

QByteArray readBytes(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// EXPECTED.tsv: "file<TAB>substring" per line.
QList<QStringList> expectedErrors()
{
    QList<QStringList> rows;
    for (const QByteArray& line : readBytes(kBadDir + u"/EXPECTED.tsv"_s).split('\n')) {
        if (!line.trimmed().isEmpty())
            rows << QString::fromUtf8(line).split(u'\t');
    }
    return rows;
}

void verifyOneLineError(const QString& error, const QString& file, const QString& expected)
{
    QVERIFY2(!error.isEmpty(), qPrintable(file + u" was accepted"_s));
    QVERIFY2(error.startsWith(file + u": "_s), qPrintable(error));
    QVERIFY2(error.contains(expected), qPrintable(u"expected \"%1\" in: %2"_s.arg(expected, error)));
    QVERIFY2(!error.contains(u'\n') && !error.contains(u'\r'), qPrintable(error));
}

// A scene that sets every field away from its default, with numbers that need all 17 digits.
Scene richScene()
{
    Scene s;
    s.canvas = {1.0 + 1.0 / 3.0, 0.7071067811865476, QColor(18, 52, 86)};
    s.flow.gridX = 96;
    s.flow.gridY = 48;
    s.flow.viscosity = 1e-7 * std::numbers::sqrt2;
    s.flow.maccormack = false;
    s.flow.stylusResponse = 0.0;  // the pen sets the velocity at once: allowed
    s.flow.stylusRadius = 0.045;
    s.time = {1.0 / 700.0, 123'456};
    s.tracking = {std::numbers::pi / 1000.0, false, false, true, 123'457};
    s.regions.push_back({u"ink"_s, QColor(29, 53, 87), true, CircleShape{{0.1 + 0.2, 0.75}, 0.15}});
    s.regions.push_back({u"veil"_s, QColor(230, 57, 70, 128), false, EllipseShape{{0.5, 1.0 / 3.0}, {0.25, 0.0625}}});
    s.regions.push_back({u"slab ü/\"quoted\""_s, QColor(1, 2, 3), true, RectShape{{-0.5, 1e-9}, {0.3, 1.0 / 9.0}}});
    s.regions.push_back({u"tri"_s, QColor(4, 5, 6, 0), true,
                         PolygonShape{{{0.1, 0.1}, {0.4, 0.1 + 1e-12}, {0.25, 1.0 / 7.0 + 0.2}}}});
    s.strokes.push_back(StylusStroke{0.0125, {{0.2, 0.5}, {0.8, 0.5}, {0.9, 0.6}}, {0.0, 0.4, 0.4}});
    s.strokes.push_back(DropStroke{0.5, {0.5, 0.5}, 0.1, QColor(241, 196, 15), u"sun"_s});
    s.strokes.push_back(DropStroke{1e6, {2.0, -3.0}, 1e-3, QColor(0, 0, 0, 254), QString()});
    s.strokes.push_back(CombStroke{CombStroke::Mode::Water, 0.7, {0.1, 0.2}, {0.9, 0.2 + 1e-12}, 7, 1.0 / 30.0,
                                   0.02, 0.75, 0.011});
    s.strokes.push_back(CombStroke{CombStroke::Mode::Exact, 0.0, {0.5, 0.1}, {0.5, 0.9}, 1, 0.0, 1.0 / 3.0, 0.5, 0.03});
    s.strokes.push_back(CombStroke{CombStroke::Mode::Water, 0.2, {0.1, 0.9}, {0.7, 0.3}, 5, 0.05, 0.02, 0.3, 0.01,
                                   1.0 / 7.0, 0.3, -45.5});
    s.strokes.push_back(CircularCombStroke{CombStroke::Mode::Water, 0.3, {0.5, 0.4}, 0.05, 4, 1.0 / 60.0, -270.0, 0.02,
                                           0.9, 0.015});
    s.strokes.push_back(CircularCombStroke{CombStroke::Mode::Exact, 0.4, {0.45, 0.5}, 0.2, 1, 0.0, 3600.0, 1e-3, 0.5, 0.03});
    s.strokes.push_back(SwirlStroke{0.45, {0.5, 0.5}, 0.15, -90.0});
    s.strokes.push_back(SwirlStroke{0.5, {0.4, 0.6}, 0.1, 270.0, CombStroke::Mode::Water, 0.3, 6});
    s.strokes.push_back(SwirlStroke{0.6, {0.1, 1.0 / 3.0}, 0.25, -3600.0});
    s.strokes.push_back(SpatterStroke{0.7, {0.4, 0.6}, 1.0 / 3.0, 10'000, 1e-3, 1e-3, {QColor(1, 2, 3), QColor(250, 0, 5, 17)},
                                      (std::uint64_t(1) << 53) - 7, 0.0});
    s.strokes.push_back(PatternStroke{PatternStroke::Kind::Bouquet, 0.8, CombStroke::Mode::Water,
                                      {QColor(1, 2, 3), QColor(9, 8, 7, 6)}, 99, 0.1, 0.2, 0.05, 0.3, 0.01, 0.7});
    s.strokes.push_back(PatternStroke{PatternStroke::Kind::GelGit, 0.9, CombStroke::Mode::Exact, {QColor(4, 5, 6)},
                                      std::uint64_t(1) << 53, 1.0 / 7.0, 1.0 / 3.0, 1e-3, 0.125, 1e-9, 1e-9});
    s.strokes.push_back(GatherStroke{1.0, 2.5, Shape(RectShape{{0.2, 0.3}, {0.6, 1.0 / 3.0}}), {0.0, 1.1, 0.02}, {}});
    s.strokes.push_back(GatherStroke{0.0, 1e-3, TextTarget{u"Ink ✓"_s, u"DejaVu Serif"_s, false, {0.1, 0.7}, 0.3}, {8.0, 0.0, 1e-3}, {}});
    return s;
}

Scene analyticScene()
{
    Scene s;
    s.flow.type = FlowSpec::Type::Analytic;
    s.flow.u = u"-sin(pi*x)^2*sin(2*pi*y)"_s;
    s.flow.v = u"sin(pi*y)^2*sin(2*pi*x)*cos(pi*t/8)"_s;
    s.regions.push_back({u"ink"_s, QColor(29, 53, 87), true, CircleShape{{0.5, 0.75}, 0.15}});
    s.strokes.push_back(DropStroke{0.25, {0.5, 0.5}, 0.05, QColor(241, 196, 15), QString()});
    s.strokes.push_back(CombStroke{CombStroke::Mode::Exact, 0.5, {0.2, 0.5}, {0.6, 0.5}, 4, 0.1, 0.025, 0.5, 0.03});
    return s;
}

// Random positions and lengths of every magnitude the format allows: the written text must carry
// every bit of every double.
Scene randomScene()
{
    QRandomGenerator random(20240611);
    auto magnitude = [&random] { return std::ldexp(random.generateDouble(), random.bounded(-40, 19)); };
    Scene s;
    for (int i = 0; i < 200; ++i) {
        const sim::Vec2 center{magnitude() - magnitude(), magnitude() - magnitude()};
        s.regions.push_back({u"r%1"_s.arg(i), QColor::fromRgb(random.generate()), true, CircleShape{center, magnitude() + 1e-3}});
    }
    s.tracking.maxSpacing = 1e6;  // keeps the vertex budget out of the way of big radii
    return s;
}

QStringList jsonKeys(const QJsonValue& value)
{
    QStringList keys;
    if (value.isObject()) {
        const QJsonObject object = value.toObject();
        for (auto it = object.begin(); it != object.end(); ++it)
            keys << it.key() << jsonKeys(it.value());
    } else if (value.isArray()) {
        for (const QJsonValue& element : value.toArray())
            keys << jsonKeys(element);
    }
    return keys;
}

std::vector<double> edgeLengths(const sim::Polygon& polygon)
{
    std::vector<double> lengths;
    for (std::size_t i = 0; i < polygon.size(); ++i)
        lengths.push_back(glm::distance(polygon[i], polygon[(i + 1) % polygon.size()]));
    return lengths;
}

} // namespace

Q_DECLARE_METATYPE(vf::model::Shape)

class TestSceneFile : public QObject {
    Q_OBJECT

private slots:
    void badFileGivesOneLineError_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("expected");
        for (const QStringList& row : expectedErrors())
            QTest::newRow(qPrintable(row.value(0))) << kBadDir + u'/' + row.value(0) << row.value(1);
    }
    void badFileGivesOneLineError()
    {
        QFETCH(QString, file);
        QFETCH(QString, expected);
        const SceneReadResult result = readSceneFile(file);
        verifyOneLineError(result.error, file, expected);
        QVERIFY(!result.ok());
    }

    void everyBadFileIsListed()
    {
        QSet<QString> listed;
        for (const QStringList& row : expectedErrors()) {
            QCOMPARE(row.size(), 2);
            QVERIFY2(QFile::exists(kBadDir + u'/' + row[0]), qPrintable(row[0]));
            listed << row[0];
        }
        const QStringList present = QDir(kBadDir).entryList(QDir::Files).filter(u".vfscene"_s);
        QVERIFY(present.size() >= 14);
        for (const QString& file : present)
            QVERIFY2(listed.contains(file), qPrintable(file + u" is not in EXPECTED.tsv"_s));
    }

    void missingOrUnreadableFile()
    {
        const QTemporaryDir dir;
        const QString missing = dir.filePath(u"nope.vfscene"_s);
        verifyOneLineError(readSceneFile(missing).error, missing, u"cannot open"_s);
        verifyOneLineError(readSceneFile(dir.path()).error, dir.path(), u"cannot open"_s);
    }

    void parseNamesTheSource()
    {
        verifyOneLineError(parseScene("{\"vectorfluid\": 1, \"canvas\": 3}", u"clipboard"_s).error, u"clipboard"_s,
                           u"clipboard: canvas: must be an object, not the number 3"_s);
    }

    // What fuzzing finds slowly (docs/fuzzing.md): deep nesting and numbers at the edges of double
    // are refused with one line, never a crash or a stack overflow.
    void hostileInputGivesOneLineError_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("expected");
        const auto circle = [](const char* radius) {
            return QByteArray("{\"vectorfluid\": 1, \"regions\": [{\"name\": \"a\", \"color\": \"#000000\", \"shape\": {\"circle\": {\"center\": [0.5, 0.5], \"radius\": ") +
                   radius + "}}}]}";
        };
        QTest::newRow("deep arrays") << QByteArray("{\"vectorfluid\": 1, \"regions\": ") + QByteArray("[").repeated(100'000) +
                                            QByteArray("]").repeated(100'000) + "}"
                                     << u"hostile: 1:1054: broken JSON: too deeply nested document"_s;
        QTest::newRow("deep objects") << QByteArray("{\"a\": ").repeated(100'000) + "1" + QByteArray("}").repeated(100'000)
                                      << u"broken JSON: too deeply nested document"_s;
        QTest::newRow("radius 1e308") << circle("1e308") << u"regions[0].shape.circle.radius: must be at most 1e+06, is 1e+308"_s;
        QTest::newRow("radius 1e-308") << circle("1e-308") << u"regions[0].shape.circle.radius: must be at least 1e-09, is 1e-308"_s;
        QTest::newRow("radius denormal") << circle("4.9e-324") << u"regions[0].shape.circle.radius: must be at least 1e-09"_s;
        QTest::newRow("radius 1e309") << circle("1e309") << u"broken JSON: illegal number"_s;
        QTest::newRow("canvas 1e308") << QByteArray("{\"vectorfluid\": 1, \"canvas\": {\"width\": 1e308, \"height\": 1e308}}") << u"canvas.width: must be at most 1e+06, is 1e+308"_s;
        QTest::newRow("canvas denormal") << QByteArray("{\"vectorfluid\": 1, \"canvas\": {\"width\": 4.9e-324, \"height\": 1}}") << u"canvas.width: must be at least 1e-09"_s;
    }
    void hostileInputGivesOneLineError()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, expected);
        verifyOneLineError(parseScene(json, u"hostile"_s).error, u"hostile"_s, expected);
    }

    void omittedKeysTakeTheDefaults()
    {
        const SceneReadResult result = parseScene("{\"vectorfluid\": 1}", u"minimal"_s);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QVERIFY(result.scene == Scene());
    }

    void demoScenesRead_data()
    {
        QTest::addColumn<QString>("file");
        const QStringList files = QDir(kScenesDir).entryList({u"*.vfscene"_s}, QDir::Files);
        for (const QString& required : {u"sumi-nagashi.vfscene"_s, u"logo-design.vfscene"_s,
                                        u"vortex-reversal.vfscene"_s, u"example.vfscene"_s})
            QVERIFY2(files.contains(required), qPrintable(required));
        for (const QString& file : files)
            QTest::newRow(qPrintable(file)) << kScenesDir + u'/' + file;
    }
    void demoScenesRead()
    {
        QFETCH(QString, file);
        const SceneReadResult result = readSceneFile(file);
        QVERIFY2(result.ok(), qPrintable(result.error));
        QVERIFY(!result.scene.regions.empty() || !result.scene.strokes.empty());
        // Demo runs stay affordable on a laptop.
        QVERIFY(result.scene.time.steps <= 1000);
        const SceneReadResult again = parseScene(sceneToJson(result.scene), file, kScenesDir);
        QVERIFY2(again.ok(), qPrintable(again.error));
        QVERIFY(again.scene == result.scene);
    }

    // muparser's precedence of unary minus against ^ is a classic trap: the demo must mean the
    // reversed single vortex as written in the literature.
    void vortexDemoIsTheReversedVortex()
    {
        const SceneReadResult result = readSceneFile(kScenesDir + u"/vortex-reversal.vfscene"_s);
        QVERIFY2(result.ok(), qPrintable(result.error));
        const sim::AnalyticFlow flow(result.scene.flow.u.toStdString(), result.scene.flow.v.toStdString());
        const double pi = std::numbers::pi;
        for (const sim::Vec2 p : {sim::Vec2(0.25, 0.125), sim::Vec2(0.6, 0.3), sim::Vec2(0.9, 0.7)}) {
            for (const double t : {0.0, 1.5, 6.0}) {
                const double u = -std::pow(std::sin(pi * p.x), 2) * std::sin(2 * pi * p.y) * std::cos(pi * t / 8);
                const double v = std::pow(std::sin(pi * p.y), 2) * std::sin(2 * pi * p.x) * std::cos(pi * t / 8);
                const sim::Vec2 velocity = flow.velocity(p, t);
                QVERIFY(std::abs(velocity.x - u) < 1e-12);
                QVERIFY(std::abs(velocity.y - v) < 1e-12);
            }
        }
        QCOMPARE(result.scene.time.dt * double(result.scene.time.steps), 8.0);
        QCOMPARE(result.scene.tracking.maxSpacing, 1.0 / 256.0);
        QVERIFY(!result.scene.tracking.adaptive);
    }

    void roundTripIsExact_data()
    {
        QTest::addColumn<int>("which");
        QTest::newRow("every field") << 0;
        QTest::newRow("analytic flow") << 1;
        QTest::newRow("random doubles") << 2;
        QTest::newRow("defaults") << 3;
    }
    void roundTripIsExact()
    {
        QFETCH(int, which);
        const Scene scenes[] = {richScene(), analyticScene(), randomScene(), Scene()};
        const Scene& scene = scenes[which];
        const QTemporaryDir dir;
        const QString path = dir.filePath(u"scene.vfscene"_s);
        QCOMPARE(writeSceneFile(scene, path), QString());
        const SceneReadResult result = readSceneFile(path);
        QVERIFY2(result.ok(), qPrintable(result.error));
        // Compare part by part so that a failure points at the part.
        QVERIFY(result.scene.canvas == scene.canvas);
        QVERIFY(result.scene.flow == scene.flow);
        QVERIFY(result.scene.time == scene.time);
        QVERIFY(result.scene.tracking == scene.tracking);
        QCOMPARE(result.scene.regions.size(), scene.regions.size());
        for (std::size_t i = 0; i < scene.regions.size(); ++i)
            QVERIFY2(result.scene.regions[i] == scene.regions[i], qPrintable(scene.regions[i].name));
        QVERIFY(result.scene.strokes == scene.strokes);
        QCOMPARE(sceneToJson(result.scene), sceneToJson(scene));
    }

    // Every key the writer knows is documented, and defaults are written out too.
    void writerWritesEveryKeyAndDocsNameThem()
    {
        const QJsonObject written = QJsonDocument::fromJson(sceneToJson(richScene())).object();
        const QStringList keys = jsonKeys(written) + jsonKeys(QJsonDocument::fromJson(sceneToJson(analyticScene())).object());
        for (const QString& key : {u"area_correction"_s, u"max_vertices"_s, u"advection"_s, u"visible"_s, u"name"_s})
            QVERIFY2(keys.contains(key), qPrintable(key));
        const QString docs = QString::fromUtf8(readBytes(QStringLiteral(VF_SOURCE_DIR "/docs/scene-format.md")));
        QVERIFY(!docs.isEmpty());
        for (const QString& key : keys)
            QVERIFY2(docs.contains(u'`' + key + u'`'), qPrintable(key + u" is not in docs/scene-format.md"_s));
    }

    void writeIntoMissingDirectoryFails()
    {
        const QTemporaryDir dir;
        const QString path = dir.filePath(u"missing/scene.vfscene"_s);
        verifyOneLineError(writeSceneFile(richScene(), path), path, u"cannot write"_s);
        QVERIFY(!QFile::exists(path));
    }

    void failedWriteKeepsThePreviousFile()
    {
#ifdef Q_OS_UNIX
        const QTemporaryDir dir;
        const QString path = dir.filePath(u"scene.vfscene"_s);
        QCOMPARE(writeSceneFile(Scene(), path), QString());
        const QByteArray previous = readBytes(path);
        QString error;
        {
            const test::FileSizeLimit limit(64);
            QVERIFY(limit.active());
            error = writeSceneFile(richScene(), path);
        }
        verifyOneLineError(error, path, u"write failed: File too large"_s);
        QCOMPARE(readBytes(path), previous);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{u"scene.vfscene"_s});
#else
        QSKIP("needs RLIMIT_FSIZE");
#endif
    }

    void contoursAreOrientedFineAndOnTheShape_data()
    {
        QTest::addColumn<Shape>("shape");
        QTest::addColumn<double>("spacing");
        QTest::addColumn<double>("area");
        QTest::newRow("circle") << Shape(CircleShape{{0.5, 0.75}, 0.15}) << 1.0 / 256 << std::numbers::pi * 0.0225;
        // Below the spacing a circle is the minimal octagon: area 8/2 · r² · sin(2π/8).
        QTest::newRow("tiny circle") << Shape(CircleShape{{0.5, 0.5}, 1e-4}) << 0.004 << 4e-8 * std::numbers::sqrt2 / 2;
        QTest::newRow("ellipse") << Shape(EllipseShape{{0.5, 0.5}, {0.3, 0.1}}) << 0.004 << std::numbers::pi * 0.03;
        QTest::newRow("slim ellipse") << Shape(EllipseShape{{0.5, 0.5}, {0.01, 0.4}}) << 0.004 << std::numbers::pi * 0.004;
        QTest::newRow("rect") << Shape(RectShape{{0.1, 0.2}, {0.5, 0.013}}) << 0.004 << 0.5 * 0.013;
        const sim::Polygon lShape{{0.1, 0.1}, {0.5, 0.1}, {0.5, 0.2}, {0.2, 0.2}, {0.2, 0.6}, {0.1, 0.6}};
        const double lArea = 0.4 * 0.1 + 0.1 * 0.4;
        QTest::newRow("polygon, positive") << Shape(PolygonShape{lShape}) << 0.004 << lArea;
        QTest::newRow("polygon, negative") << Shape(PolygonShape{{lShape.rbegin(), lShape.rend()}}) << 0.004 << lArea;
    }
    void contoursAreOrientedFineAndOnTheShape()
    {
        QFETCH(Shape, shape);
        QFETCH(double, spacing);
        QFETCH(double, area);
        const std::vector<sim::Polygon> contours = shapeContours(shape, spacing);
        QCOMPARE(contours.size(), std::size_t(1));
        const sim::Polygon& contour = contours[0];
        QVERIFY(contour.size() >= 8 || std::holds_alternative<RectShape>(shape) || std::holds_alternative<PolygonShape>(shape));
        QVERIFY(double(contour.size()) <= shapeVertexBound(shape, spacing));

        // The engine's orientation: positive shoelace area, same as sim::circle.
        QVERIFY(sim::signedArea(contour) > 0.0);
        QVERIFY(sim::signedArea(sim::circle({0.0, 0.0}, 1.0, 0.1)) > 0.0);
        QVERIFY(sim::isSimple(contour));
        const double relativeAreaError = std::abs(sim::signedArea(contour) - area) / area;
        const bool curved = std::holds_alternative<CircleShape>(shape) || std::holds_alternative<EllipseShape>(shape);
        QVERIFY2(relativeAreaError < (curved ? 1e-3 : 1e-12), qPrintable(QString::number(relativeAreaError)));

        const std::vector<double> lengths = edgeLengths(contour);
        QVERIFY(*std::max_element(lengths.begin(), lengths.end()) <= spacing * (1 + 1e-12));
        if (const auto* ellipse = std::get_if<EllipseShape>(&shape)) {
            for (const sim::Vec2& p : contour) {
                const sim::Vec2 q = (p - ellipse->center) / ellipse->radii;
                QVERIFY(std::abs(glm::dot(q, q) - 1.0) < 1e-9);
            }
            // Equal arc length: no crowding at the narrow ends.
            QVERIFY(*std::min_element(lengths.begin(), lengths.end()) >= 0.25 * spacing);
        }
        if (const auto* polygon = std::get_if<PolygonShape>(&shape)) {
            for (const sim::Vec2& corner : polygon->points)
                QVERIFY(std::find(contour.begin(), contour.end(), corner) != contour.end());
        }
        if (const auto* rect = std::get_if<RectShape>(&shape)) {
            QVERIFY(contour[0] == rect->topLeft);
            QVERIFY(contour[1].x > contour[0].x);  // along the top edge first: clockwise on screen
        }
    }
};

QTEST_MAIN(TestSceneFile)  // text targets are set with the font database
#include "tst_scenefile.moc"
