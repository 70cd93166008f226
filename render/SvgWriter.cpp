// SVG written by hand rather than through QtSvg: we need Inkscape layers, ids and full precision,
// and the file must stream. Layout: an optional locked "Background" layer, then one layer per
// region (bottom to top) holding that region's single even-odd <path>. Hidden regions are kept,
// as Inkscape keeps hidden layers: the layer gets style="display:none".
//
// Coordinates are exact (shortest round-trip), about 38 bytes per polyline vertex. libxml2-based
// readers (xmllint, Inkscape, rsvg) refuse an attribute value over 10,000,000 bytes unless told
// otherwise, so a region whose path data would pass kMaxPathData is cut in halves, again and
// again, each half its own <path> in the region's layer (render/RegionHalves.h).
#include "render/Writers.h"

#include "render/BufferedWriter.h"
#include "render/RegionHalves.h"
#include "render/Page.h"
#include "render/PathEmitter.h"
#include "render/XmlNames.h"

#include <QBuffer>
#include <QColor>

#include <array>
#include <string_view>

namespace vf::render {
namespace {

// libxml2's XML_MAX_TEXT_LENGTH, less a margin.
constexpr qsizetype kMaxPathData = 9'000'000;
// Each cut at least about halves the vertices; past this many cuts a region is written as it is.
constexpr int kMaxCuts = 40;

// Absolute coordinates (relative ones would accumulate rounding), a command letter only where it
// changes, shortest round-trip numbers: exact, and as compact as exactness allows.
class SvgPathData final : public PathSink {
public:
    explicit SvgPathData(BufferedWriter& out) : m_out(out) {}

    void moveTo(sim::Vec2 point) override
    {
        command('M');
        write(point);
    }
    void lineTo(sim::Vec2 point) override
    {
        command('L');
        write(point);
    }
    void cubicTo(sim::Vec2 control1, sim::Vec2 control2, sim::Vec2 end) override
    {
        command('C');
        write(control1);
        m_out << ' ';
        write(control2);
        m_out << ' ';
        write(end);
    }
    void closePath() override { command('Z'); }

private:
    void command(char letter)
    {
        if (letter == m_last && (letter == 'L' || letter == 'C'))
            m_out << ' ';
        else
            m_out << letter;
        m_last = letter;
    }
    void write(sim::Vec2 point) { m_out << point.x << ' ' << point.y; }

    BufferedWriter& m_out;
    char m_last = 0;
};

void writeFill(BufferedWriter& xml, const QColor& color)
{
    xml << " fill=\"" << color.name(QColor::HexRgb) << '"';
    if (color.alpha() < 255)
        xml << " fill-opacity=\"" << color.alpha() / 255.0 << '"';
}

void writeHeader(BufferedWriter& xml, const model::Drawing& drawing, const Page& page)
{
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\"\n"
           "     xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"\n"
           "     xmlns:sodipodi=\"http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd\"\n"
           "     version=\"1.1\" width=\""
        << page.width << "pt\" height=\"" << page.height << "pt\" viewBox=\"0 0 " << drawing.width << ' '
        << drawing.height << "\">\n";
}

// Its own locked layer, so a designer editing the regions cannot grab the background by accident.
void writeBackground(BufferedWriter& xml, const model::Drawing& drawing, UniqueXmlIds& ids)
{
    xml << "<g id=\"" << ids.claim(QStringLiteral("background"))
        << "\" inkscape:groupmode=\"layer\" inkscape:label=\"Background\" sodipodi:insensitive=\"true\">\n"
        << "<rect id=\"" << ids.claim(QStringLiteral("background-rect")) << "\" x=\"0\" y=\"0\" width=\""
        << drawing.width << "\" height=\"" << drawing.height << '"';
    writeFill(xml, drawing.background);
    xml << "/>\n</g>\n";
}

// The region's path data, built in memory first so that its size is known before it is written.
QByteArray pathData(const model::DrawnRegion& region, const PathStyle& style)
{
    QByteArray data;
    QBuffer buffer(&data);
    buffer.open(QIODevice::WriteOnly);
    BufferedWriter out(buffer);
    SvgPathData sink(out);
    emitRegion(region, style, sink);
    out.finish();  // a QBuffer takes every write
    return data;
}

std::size_t vertexCount(const model::DrawnRegion& region)
{
    std::size_t count = 0;
    for (const sim::Polygon& contour : region.contours)
        count += contour.size();
    return count;
}

// One <path> per piece of the region whose data fits in one attribute; the first takes `pathId`,
// claimed already, the others pathId-2, pathId-3, ...
void writePaths(BufferedWriter& xml, const model::DrawnRegion& region, const PathStyle& style, const QString& pathId,
                const QString& label, UniqueXmlIds& ids, bool& first, int cuts)
{
    const QByteArray data = pathData(region, style);
    if (data.size() > kMaxPathData && cuts < kMaxCuts) {
        const std::size_t vertices = vertexCount(region);
        const std::array<model::DrawnRegion, 2> halves = cutInHalves(region);
        if (vertexCount(halves[0]) < vertices && vertexCount(halves[1]) < vertices) {
            for (const model::DrawnRegion& half : halves)
                writePaths(xml, half, style, pathId, label, ids, first, cuts + 1);
            return;
        }
    }
    xml << "<path id=\"" << (first ? pathId : ids.claim(pathId)) << "\" inkscape:label=\"" << label << '"';
    writeFill(xml, region.color);
    xml << " fill-rule=\"evenodd\" d=\"" << std::string_view(data.constData(), std::size_t(data.size())) << "\"/>\n";
    first = false;
}

void writeRegion(BufferedWriter& xml, const model::DrawnRegion& region, const PathStyle& style,
                 UniqueXmlIds& ids)
{
    const QString pathId = ids.claim(sanitizedXmlId(region.name));
    const QString label = escapedXmlAttribute(region.name);
    xml << "<g id=\"" << ids.claim(QStringLiteral("layer-") + pathId)
        << "\" inkscape:groupmode=\"layer\" inkscape:label=\"" << label << '"';
    if (!region.visible)
        xml << " style=\"display:none\"";
    xml << ">\n";
    bool first = true;
    writePaths(xml, region, style, pathId, label, ids, first, 0);
    xml << "</g>\n";
}

} // namespace

QString writeSvg(const model::Drawing& drawing, const ExportOptions& options, QIODevice& out)
{
    BufferedWriter xml(out);
    UniqueXmlIds ids;
    writeHeader(xml, drawing, pageFor(drawing, options));
    if (options.background)
        writeBackground(xml, drawing, ids);
    const PathStyle style = pathStyle(drawing, options);
    for (const model::DrawnRegion& region : drawing.regions)
        writeRegion(xml, region, style, ids);
    xml << "</svg>\n";
    return xml.finish();
}

} // namespace vf::render
