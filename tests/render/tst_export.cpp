// Export formats end to end: what the files contain, read back by our own parser and by the real
// readers (xmllint, rsvg-convert, qpdf, pdftoppm, Ghostscript), and atomic replacement on failure.
// Runs with a QCoreApplication only (QTEST_GUILESS_MAIN): PNG export must not need a GUI.
// One file past 500 lines: every format's checks share the scenes and the reader helpers below.
#include "../TestFiles.h"
#include "ExternalTools.h"
#include "SvgReadBack.h"
#include "TestGeometry.h"

#include "render/Exporter.h"
#include "render/PathEmitter.h"
#include "render/Writers.h"

#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace vf;
using sim::Polygon;
using sim::Vec2;
using test::ParsedLayer;
using test::ParsedPath;
using test::ParsedSvg;
using test::parseSvg;
using test::verticesOf;

Q_DECLARE_METATYPE(model::Drawing)

namespace {

// ---- the drawing every format is checked with ------------------------------------------------

const QColor kBackground(255, 224, 160);
const QColor kDiscColor(230, 57, 70);
const QColor kRingColor(29, 53, 87);

model::Drawing probeDrawing()
{
    model::Drawing drawing;
    drawing.width = 1.0;
    drawing.height = 0.75;
    drawing.background = kBackground;
    drawing.regions = {
        {QStringLiteral("disc"), kDiscColor, true, {test::circlePolygon({0.25, 0.375}, 0.15, 240)}},
        {QStringLiteral("ring"), kRingColor, true,
         {test::circlePolygon({0.7, 0.375}, 0.2, 300), test::circlePolygon({0.7, 0.375}, 0.08, 120)}},
        {QStringLiteral("hidden"), QColor(0, 160, 0), false, {test::squarePolygon({0.42, 0.62}, 0.06, 10)}},
    };
    return drawing;
}

struct Probe {
    const char* what;
    Vec2 at; // canvas units
    QColor expected;
};

// Interior points far from any edge, so antialiasing and Bézier tolerance cannot matter.
std::vector<Probe> probes(const QColor& background)
{
    return {{"disc", {0.25, 0.375}, kDiscColor},
            {"ring body", {0.84, 0.375}, kRingColor},
            {"ring hole (even-odd)", {0.7, 0.375}, background},
            {"outside", {0.05, 0.05}, background},
            {"hidden region", {0.45, 0.65}, background}};
}

QString checkProbes(const QImage& image, const std::vector<Probe>& expected, const model::Drawing& drawing)
{
    if (image.isNull())
        return QStringLiteral("no image");
    for (const Probe& probe : expected) {
        const int x = int(probe.at.x / drawing.width * image.width());
        const int y = int(probe.at.y / drawing.height * image.height());
        const QColor got = image.pixelColor(x, y);
        const bool same = std::abs(got.red() - probe.expected.red()) <= 3
                          && std::abs(got.green() - probe.expected.green()) <= 3
                          && std::abs(got.blue() - probe.expected.blue()) <= 3
                          && std::abs(got.alpha() - probe.expected.alpha()) <= 3;
        if (!same)
            return QStringLiteral("%1: got %2 alpha %3, expected %4 alpha %5")
                .arg(QLatin1String(probe.what), got.name(), QString::number(got.alpha()),
                     probe.expected.name(), QString::number(probe.expected.alpha()));
    }
    return {};
}

// The same number of vertices, each coordinate within step / 2 (and a rounding error) of the original.
bool withinHalfStep(const Polygon& back, const Polygon& original, double step)
{
    if (back.size() != original.size())
        return false;
    for (std::size_t i = 0; i < back.size(); ++i)
        if (std::abs(back[i].x - original[i].x) > 0.5 * step * (1 + 1e-9)
            || std::abs(back[i].y - original[i].y) > 0.5 * step * (1 + 1e-9))
            return false;
    return true;
}

// ---- external readers: ExternalTools.h ---------------------------------------------------

#define EXPORT_OK(drawing, path, options)                                                                \
    do {                                                                                                 \
        const QString error_ = render::exportDrawing(drawing, path, options);                             \
        QVERIFY2(error_.isEmpty(), qPrintable(error_));                                                   \
    } while (false)

using test::readAll;
using test::writeFile;

// Accepts `budget` bytes, then fails every write, like a full disk.
class FailingDevice final : public QIODevice {
public:
    explicit FailingDevice(qint64 budget) : m_budget(budget) { open(QIODevice::WriteOnly); }

protected:
    qint64 readData(char*, qint64) override { return -1; }
    qint64 writeData(const char*, qint64 length) override
    {
        if (length > m_budget) {
            setErrorString(QStringLiteral("No space left on device"));
            return -1;
        }
        m_budget -= length;
        return length;
    }

private:
    qint64 m_budget;
};

} // namespace

class TestExport : public QObject {
    Q_OBJECT

private slots:
    void init();

    void svgPolylineReadsBackRounded();
    void svgIdsAreUniqueXmlNames();
    void svgAcceptedByXmllint();
    void svgRenderedByRsvg();
    void svgBezierWithinTolerance();
    void svgBezierKeepsSquareCorners();
    void svgLargeRegionStreams();
    void svgHugeRegionReadableWithoutHugeOption();

    void pdfPassesQpdfAndPdftoppm();
    void pageOfAnotherAspectCentresTheCanvas();
    void epsHasPageBoundingBoxAndRendersInGhostscript_data();
    void epsHasPageBoundingBoxAndRendersInGhostscript();

    void pngSizeFollowsDpi_data();
    void pngSizeFollowsDpi();
    void pngColoursAndEvenOddHole();
    void pngTransparentWithoutBackground();

    void suffixSelectsFormat();
    void missingDirectoryIsAnError();
    void failedExportLeavesOldFileUntouched_data();
    void failedExportLeavesOldFileUntouched();
    void writersReportDeviceFailure_data();
    void writersReportDeviceFailure();

private:
    QString path(const QString& name) const { return m_dir->filePath(name); }

    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestExport::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
}

// Within half the rounding step (1e-6 on this canvas) of the drawing, vertex for vertex.
void TestExport::svgPolylineReadsBackRounded()
{
    const model::Drawing drawing = probeDrawing();
    const QString file = path(QStringLiteral("a.svg"));
    render::ExportOptions options;
    options.bezier = false;
    EXPORT_OK(drawing, file, options);

    const ParsedSvg svg = parseSvg(file);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QCOMPARE(svg.viewBox, QStringLiteral("0 0 1 0.75"));
    QCOMPARE(svg.width, QStringLiteral("576pt"));
    QCOMPARE(svg.height, QStringLiteral("432pt"));
    QCOMPARE(svg.backgroundFill, kBackground.name());
    QCOMPARE(svg.layers.size(), drawing.regions.size() + 1); // + the background layer

    for (std::size_t r = 0; r < drawing.regions.size(); ++r) {
        const model::DrawnRegion& region = drawing.regions[r];
        const ParsedLayer& layer = svg.layers[r + 1];
        QCOMPARE(layer.groupMode, QStringLiteral("layer"));
        QCOMPARE(layer.label, region.name);
        QCOMPARE(layer.style, region.visible ? QString() : QStringLiteral("display:none"));
        QCOMPARE(layer.paths.size(), std::size_t(1));
        const ParsedPath& path = layer.paths.front();
        QCOMPARE(path.id, region.name);
        QCOMPARE(path.label, region.name);
        QCOMPARE(path.fill, region.color.name());
        QCOMPARE(path.fillRule, QStringLiteral("evenodd"));
        QCOMPARE(path.contours.size(), region.contours.size());
        for (std::size_t c = 0; c < region.contours.size(); ++c) {
            const Polygon back = verticesOf(path.contours[c]);
            QVERIFY(withinHalfStep(back, region.contours[c], 1e-6));
            for (std::size_t i = 0; i < back.size(); ++i)
                QVERIFY(back[i] != back[(i + 1) % back.size()]);
        }
    }
    QVERIFY(!QRegularExpression(QStringLiteral("\\.[0-9]{7}")).match(QString::fromLatin1(readAll(file))).hasMatch());
}

void TestExport::svgIdsAreUniqueXmlNames()
{
    model::Drawing drawing;
    const QStringList names{QStringLiteral("ink"),       QStringLiteral("ink"),
                            QStringLiteral("1st coat"),  QString(),
                            QStringLiteral("layer-ink"), QStringLiteral("a<&>\"b\nc\u00e9"),
                            QStringLiteral("background")};
    for (const QString& name : names)
        drawing.regions.push_back({name, QColor(10, 20, 30, 128), true, {test::squarePolygon({0.1, 0.1}, 0.2, 1)}});
    const QString file = path(QStringLiteral("ids.svg"));
    EXPORT_OK(drawing, file, render::ExportOptions{});

    const ParsedSvg svg = parseSvg(file);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QCOMPARE(QSet<QString>(svg.ids.begin(), svg.ids.end()).size(), svg.ids.size());
    static const QRegularExpression ncName(QStringLiteral("^[A-Za-z_][A-Za-z0-9._-]*$"));
    for (const QString& id : svg.ids)
        QVERIFY2(ncName.match(id).hasMatch(), qPrintable(id));
    QCOMPARE(svg.layers.size(), std::size_t(names.size() + 1));
    for (qsizetype i = 0; i < names.size(); ++i) {
        const ParsedPath& path = svg.layers[std::size_t(i) + 1].paths.front();
        QCOMPARE(path.label, names[i]);
        QCOMPARE(path.fillOpacity.toDouble(), 128 / 255.0);
    }
    QCOMPARE(svg.layers[1].paths.front().id, QStringLiteral("ink"));
    QCOMPARE(svg.layers[2].paths.front().id, QStringLiteral("ink-2"));
    QCOMPARE(svg.layers[3].paths.front().id, QStringLiteral("region-1st_coat"));
}

void TestExport::svgAcceptedByXmllint()
{
    REQUIRE_TOOL(xmllint, "xmllint");
    const QString file = path(QStringLiteral("a.svg"));
    EXPORT_OK(probeDrawing(), file, render::ExportOptions{});
    const Run result = run(xmllint, {QStringLiteral("--noout"), file});
    QVERIFY2(result.exitCode == 0, result.output.constData());
    QVERIFY2(result.output.isEmpty(), result.output.constData());
}

void TestExport::svgRenderedByRsvg()
{
    REQUIRE_TOOL(rsvg, "rsvg-convert");
    const model::Drawing drawing = probeDrawing();
    for (const bool bezier : {false, true}) {
        const QString svgFile = path(QStringLiteral("a.svg"));
        const QString pngFile = path(QStringLiteral("rsvg.png"));
        render::ExportOptions options;
        options.bezier = bezier;
        EXPORT_OK(drawing, svgFile, options);
        const Run result = run(rsvg, {QStringLiteral("-w"), QStringLiteral("200"), QStringLiteral("-h"),
                                      QStringLiteral("150"), QStringLiteral("-o"), pngFile, svgFile});
        QVERIFY2(result.exitCode == 0, result.output.constData());
        const QString mismatch = checkProbes(QImage(pngFile), probes(kBackground), drawing);
        QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    }
}

void TestExport::svgBezierWithinTolerance()
{
    model::Drawing drawing;
    const Polygon circle = test::circlePolygon({0.5, 0.5}, 0.3, 800);
    const Polygon wobbly = test::wobblyPolygon({0.5, 0.5}, 0.2, 500, 11);
    drawing.regions = {{QStringLiteral("circle"), Qt::black, true, {circle}},
                       {QStringLiteral("wobbly"), Qt::black, true, {wobbly}}};
    for (const double tolerance : {0.0, 1e-3}) {
        const QString file = path(QStringLiteral("bezier.svg"));
        render::ExportOptions options;
        options.bezierTolerance = tolerance;
        EXPORT_OK(drawing, file, options);
        const ParsedSvg svg = parseSvg(file);
        QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
        const double bound = tolerance > 0 ? tolerance : render::defaultBezierTolerance(drawing);
        const render::FittedContour& fittedCircle = svg.layers[1].paths.front().contours.front();
        const render::FittedContour& fittedWobbly = svg.layers[2].paths.front().contours.front();
        QVERIFY(test::endsFollowVertices(fittedCircle, circle));
        QVERIFY(test::endsFollowVertices(fittedWobbly, wobbly));
        QVERIFY(test::deviation(fittedCircle, circle) <= bound * 1.001);
        QVERIFY(test::deviation(fittedWobbly, wobbly) <= bound * 1.001);
        QVERIFY2(fittedCircle.segments.size() * 20 < circle.size(),
                 qPrintable(QString::number(fittedCircle.segments.size())));
    }
}

void TestExport::svgBezierKeepsSquareCorners()
{
    model::Drawing drawing;
    drawing.regions = {{QStringLiteral("square"), Qt::black, true, {test::squarePolygon({0.25, 0.25}, 0.5, 40)}}};
    const QString file = path(QStringLiteral("square.svg"));
    EXPORT_OK(drawing, file, render::ExportOptions{});
    const ParsedSvg svg = parseSvg(file);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    const Polygon vertices = verticesOf(svg.layers[1].paths.front().contours.front());
    QCOMPARE(vertices.size(), std::size_t(5)); // four corners, the last one repeating the start
    for (const Vec2& v : vertices)
        QVERIFY((v.x == 0.25 || v.x == 0.75) && (v.y == 0.25 || v.y == 0.75));
    for (const render::PathSegment& s : svg.layers[1].paths.front().contours.front().segments)
        QVERIFY(s.isLine);
}

// Moderate size (100k vertices, ~3.7 MB of path data: under libxml2's 10 MB attribute limit),
// read back exactly by our parser and by xmllint.
void TestExport::svgLargeRegionStreams()
{
    model::Drawing drawing;
    const Polygon polygon = test::wobblyPolygon({0.5, 0.5}, 0.35, 100000, 5, 0.0);
    drawing.regions = {{QStringLiteral("big"), Qt::black, true, {polygon}}};
    const QString file = path(QStringLiteral("big.svg"));
    render::ExportOptions options;
    options.bezier = false;
    EXPORT_OK(drawing, file, options);
    const ParsedSvg svg = parseSvg(file);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QVERIFY(withinHalfStep(verticesOf(svg.layers[1].paths.front().contours.front()), polygon, 1e-6));
    if (const QString xmllint = QStandardPaths::findExecutable(QStringLiteral("xmllint")); !xmllint.isEmpty()) {
        const Run result = run(xmllint, {QStringLiteral("--noout"), file});
        QVERIFY2(result.exitCode == 0, result.output.constData());
    }
}

namespace {

// The ring's body as six concentric circles of 2.2M vertices in all: its outline and hole, and
// two pairs of close circles between them, hairline stripes that leave every probe's even-odd
// parity as it was. Edges of about 2.5e-6, longer than the SVG's rounding step (1e-6 here), so no
// vertex merges with its neighbour (a single circle of 2M vertices this size would have edges
// shorter than the step).
std::vector<Polygon> stripedRing(Vec2 center)
{
    const double radii[] = {0.2, 0.19, 0.185, 0.11, 0.105, 0.08};
    std::vector<Polygon> contours;
    for (const double radius : radii)
        contours.push_back(test::circlePolygon(center, radius, int(radius / 0.87 * 2'200'000)));
    return contours;
}

} // namespace

// A ring of 2.2M vertices as a polyline: about 40 MB of path data, cut into <path> elements
// with whitespace between them so that libxml2 never holds 10 MB at once (render/SvgWriter.cpp).
// xmllint takes it without --huge and rsvg paints it as the one ring: its hole stays empty.
void TestExport::svgHugeRegionReadableWithoutHugeOption()
{
    REQUIRE_TOOL(xmllint, "xmllint");
    REQUIRE_TOOL(rsvg, "rsvg-convert");
    REQUIRE_TOOL(inkscape, "inkscape");
    model::Drawing drawing = probeDrawing();
    drawing.regions[1].contours = stripedRing({0.7, 0.375});
    const QString svgFile = path(QStringLiteral("huge.svg"));
    render::ExportOptions options;
    options.bezier = false;
    EXPORT_OK(drawing, svgFile, options);
    QVERIFY(QFileInfo(svgFile).size() > 30'000'000);

    const ParsedSvg svg = parseSvg(svgFile);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QCOMPARE(svg.layers[2].label, QStringLiteral("ring"));
    QVERIFY2(svg.layers[2].paths.size() >= 4, qPrintable(QString::number(svg.layers[2].paths.size())));
    QCOMPARE(svg.layers[1].paths.size(), std::size_t(1));  // a region that fits stays one path

    const Run lint = run(xmllint, {QStringLiteral("--noout"), svgFile});
    QVERIFY2(lint.exitCode == 0 && lint.output.isEmpty(), lint.output.constData());
    const QString pngFile = path(QStringLiteral("huge.png"));
    const Run painted = run(rsvg, {QStringLiteral("-w"), QStringLiteral("200"), QStringLiteral("-h"), QStringLiteral("150"),
                                   QStringLiteral("-o"), pngFile, svgFile});
    QVERIFY2(painted.exitCode == 0, painted.output.constData());
    const QString mismatch = checkProbes(QImage(pngFile), probes(kBackground), drawing);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));

    // Inkscape (libxml2 too) reads and paints it from its command line, as a user would.
    const QString inkscapePng = path(QStringLiteral("inkscape.png"));
    const Run inkscaped = run(inkscape, {QStringLiteral("--export-type=png"), QStringLiteral("--export-width=200"),
                                         QStringLiteral("--export-height=150"),
                                         QStringLiteral("--export-filename=") + inkscapePng, svgFile});
    QVERIFY2(inkscaped.exitCode == 0, inkscaped.output.constData());
    const QString inkscapeMismatch = checkProbes(QImage(inkscapePng), probes(kBackground), drawing);
    QVERIFY2(inkscapeMismatch.isEmpty(), qPrintable(inkscapeMismatch));
}

void TestExport::pdfPassesQpdfAndPdftoppm()
{
    REQUIRE_TOOL(qpdf, "qpdf");
    REQUIRE_TOOL(pdftoppm, "pdftoppm");
    const model::Drawing drawing = probeDrawing();
    const QString file = path(QStringLiteral("a.pdf"));
    EXPORT_OK(drawing, file, render::ExportOptions{});
    const Run check = run(qpdf, {QStringLiteral("--check"), file});
    QVERIFY2(check.exitCode == 0, check.output.constData());

    const Run raster = run(pdftoppm, {QStringLiteral("-png"), QStringLiteral("-r"), QStringLiteral("36"),
                                      QStringLiteral("-singlefile"), file, path(QStringLiteral("pdf"))});
    QVERIFY2(raster.exitCode == 0, raster.output.constData());
    const QImage image(path(QStringLiteral("pdf.png")));
    QCOMPARE(image.size(), QSize(288, 216)); // 576 x 432 pt at half a pixel per point
    const QString mismatch = checkProbes(image, probes(kBackground), drawing);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

// A square page for the 4:3 canvas: the canvas fills the width, centred between white bands.
void TestExport::pageOfAnotherAspectCentresTheCanvas()
{
    REQUIRE_TOOL(pdftoppm, "pdftoppm");
    const QString file = path(QStringLiteral("square.pdf"));
    render::ExportOptions options;
    options.pageHeight = options.pageWidth;
    EXPORT_OK(probeDrawing(), file, options);
    const Run raster = run(pdftoppm, {QStringLiteral("-png"), QStringLiteral("-r"), QStringLiteral("36"),
                                      QStringLiteral("-singlefile"), file, path(QStringLiteral("square"))});
    QVERIFY2(raster.exitCode == 0, raster.output.constData());
    const QImage image(path(QStringLiteral("square.png")));
    QCOMPARE(image.size(), QSize(288, 288));  // 576 pt square at half a pixel per point
    // The canvas is 432 pt tall: 72 pt (36 px) bands above and below.
    QCOMPARE(image.pixelColor(2, 30), QColor(Qt::white));
    QCOMPARE(image.pixelColor(2, 258), QColor(Qt::white));
    QCOMPARE(image.pixelColor(2, 40), kBackground);
    QCOMPARE(image.pixelColor(2, 248), kBackground);
}

void TestExport::epsHasPageBoundingBoxAndRendersInGhostscript_data()
{
    QTest::addColumn<bool>("background");
    QTest::newRow("background") << true;
    QTest::newRow("no background") << false; // cairo alone would crop to the ink
}

void TestExport::epsHasPageBoundingBoxAndRendersInGhostscript()
{
    QFETCH(bool, background);
    REQUIRE_TOOL(gs, "gs");
    const model::Drawing drawing = probeDrawing();
    const QString file = path(QStringLiteral("a.eps"));
    render::ExportOptions options;
    options.background = background;
    EXPORT_OK(drawing, file, options);

    const QByteArray eps = readAll(file);
    QVERIFY(eps.startsWith("%!PS-Adobe-3.0 EPSF-3.0"));
    QVERIFY(eps.contains("\n%%BoundingBox: 0 0 576 432\n"));
    QCOMPARE(eps.count("BoundingBox:"), eps.count("BoundingBox: 0 0 576 432"));

    const QString png = path(QStringLiteral("eps.png"));
    const Run result = run(gs, {QStringLiteral("-q"), QStringLiteral("-dSAFER"), QStringLiteral("-dBATCH"),
                                QStringLiteral("-dNOPAUSE"), QStringLiteral("-sDEVICE=png16m"),
                                QStringLiteral("-dEPSCrop"), QStringLiteral("-r36"),
                                QStringLiteral("-sOutputFile=") + png, file});
    QVERIFY2(result.exitCode == 0, result.output.constData());
    const QImage image(png);
    QCOMPARE(image.size(), QSize(288, 216));
    // Ghostscript paints on white where there is no background.
    const QString mismatch = checkProbes(image, probes(background ? kBackground : QColor(Qt::white)), drawing);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

void TestExport::pngSizeFollowsDpi_data()
{
    QTest::addColumn<double>("dpi");
    QTest::addColumn<QSize>("size");
    QTest::newRow("72 dpi") << 72.0 << QSize(576, 432);
    QTest::newRow("36 dpi") << 36.0 << QSize(288, 216);
    QTest::newRow("300 dpi") << 300.0 << QSize(2400, 1800);
}

void TestExport::pngSizeFollowsDpi()
{
    QFETCH(double, dpi);
    QFETCH(QSize, size);
    const QString file = path(QStringLiteral("a.png"));
    render::ExportOptions options;
    options.dpi = dpi;
    EXPORT_OK(probeDrawing(), file, options);
    const QImage image(file);
    QCOMPARE(image.size(), size);
    QCOMPARE(image.dotsPerMeterX(), qRound(dpi / 0.0254));
}

void TestExport::pngColoursAndEvenOddHole()
{
    const model::Drawing drawing = probeDrawing();
    const QString file = path(QStringLiteral("a.png"));
    render::ExportOptions options;
    options.dpi = 36;
    EXPORT_OK(drawing, file, options);
    const QString mismatch = checkProbes(QImage(file), probes(kBackground), drawing);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

void TestExport::pngTransparentWithoutBackground()
{
    const model::Drawing drawing = probeDrawing();
    const QString file = path(QStringLiteral("a.png"));
    render::ExportOptions options;
    options.dpi = 36;
    options.background = false;
    EXPORT_OK(drawing, file, options);
    const QImage image = QImage(file).convertToFormat(QImage::Format_ARGB32);
    QVERIFY(image.hasAlphaChannel());
    const QString mismatch = checkProbes(image, probes(QColor(0, 0, 0, 0)), drawing);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

void TestExport::suffixSelectsFormat()
{
    for (const char* name : {"a.svg", "a.SVG", "b.Pdf", "c.eps", "d.png"})
        QVERIFY2(render::isExportSuffix(QLatin1String(name)), name);
    for (const char* name : {"a.txt", "svg", "a.svg.bak", "a"})
        QVERIFY2(!render::isExportSuffix(QLatin1String(name)), name);

    const QString file = path(QStringLiteral("a.txt"));
    const QString error = render::exportDrawing(probeDrawing(), file, render::ExportOptions{});
    QVERIFY(error.startsWith(file + QStringLiteral(": ")));
    QVERIFY(!QFile::exists(file));

    // Upper-case suffix still writes the right format.
    const QString upper = path(QStringLiteral("A.PDF"));
    EXPORT_OK(probeDrawing(), upper, render::ExportOptions{});
    QVERIFY(readAll(upper).startsWith("%PDF-"));
}

void TestExport::missingDirectoryIsAnError()
{
    const QString file = path(QStringLiteral("no/such/dir/a.svg"));
    const QString error = render::exportDrawing(probeDrawing(), file, render::ExportOptions{});
    QVERIFY(error.startsWith(file + QStringLiteral(": ")));
    QVERIFY(!error.contains(u'\n'));
    QVERIFY(!QFile::exists(file));
}

void TestExport::failedExportLeavesOldFileUntouched_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<model::Drawing>("drawing");
    QTest::addColumn<double>("dpi");
    model::Drawing bad = probeDrawing();
    bad.regions[1].contours[1][7].x = std::numeric_limits<double>::quiet_NaN();
    // The PNG case fails inside the writer, after the temporary file was opened.
    QTest::newRow("image too large") << QStringLiteral("old.png") << probeDrawing() << 1e7;
    QTest::newRow("non-finite vertex") << QStringLiteral("old.svg") << bad << 150.0;
    // A canvas 1e4 times taller than wide makes a page of 5.76e6 pt: beyond PDF and EPS readers.
    model::Drawing tall = probeDrawing();
    tall.height = tall.width * 1e4;
    QTest::newRow("page too tall for PDF") << QStringLiteral("old.pdf") << tall << 150.0;
    QTest::newRow("page too tall for EPS") << QStringLiteral("old.eps") << tall << 150.0;
}

void TestExport::failedExportLeavesOldFileUntouched()
{
    QFETCH(QString, name);
    QFETCH(model::Drawing, drawing);
    QFETCH(double, dpi);
    const QString file = path(name);
    const QByteArray old = "the previous export\n";
    QVERIFY(writeFile(file, old));
    render::ExportOptions options;
    options.dpi = dpi;
    const QString error = render::exportDrawing(drawing, file, options);
    QVERIFY(error.startsWith(file + QStringLiteral(": ")));
    QVERIFY(!error.contains(u'\n'));
    QCOMPARE(readAll(file), old);
    QCOMPARE(QDir(m_dir->path()).entryList(QDir::Files), QStringList{name}); // no temporary left

    options.dpi = 36; // and a good export does replace it
    EXPORT_OK(probeDrawing(), file, options);
    QVERIFY(readAll(file) != old);
}

void TestExport::writersReportDeviceFailure_data()
{
    QTest::addColumn<int>("format");
    QTest::addColumn<qint64>("budget");
    QTest::newRow("svg") << 0 << qint64(100);
    QTest::newRow("pdf") << 1 << qint64(100);
    QTest::newRow("eps") << 2 << qint64(100);
    QTest::newRow("png") << 3 << qint64(100);
    QTest::newRow("svg, no space at all") << 0 << qint64(0);
    QTest::newRow("eps, no space at all") << 2 << qint64(0);
}

void TestExport::writersReportDeviceFailure()
{
    using Writer = QString (*)(const model::Drawing&, const render::ExportOptions&, QIODevice&);
    const Writer writers[] = {render::writeSvg, render::writePdf, render::writeEps, render::writePng};
    QFETCH(int, format);
    QFETCH(qint64, budget);
    FailingDevice device(budget);
    render::ExportOptions options;
    options.dpi = 36;
    const QString error = writers[format](probeDrawing(), options, device);
    QVERIFY(!error.isEmpty());
}

QTEST_GUILESS_MAIN(TestExport)
#include "tst_export.moc"
