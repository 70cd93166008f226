// SVG written by hand rather than through QtSvg: we need Inkscape layers and ids, and the file
// must stream. Layout: an optional locked "Background" layer, then one layer per region (bottom to
// top) holding that region's even-odd <path>. Hidden regions are kept, as Inkscape keeps hidden
// layers: the layer gets style="display:none". Polyline coordinates are rounded to a step relative
// to the canvas (render/SvgRounding.h); Bézier coordinates are exact.
//
// Readers built on libxml2 2.9 (xmllint, rsvg, Inkscape) refuse, unless asked for XML_PARSE_HUGE,
// an attribute value over 10,000,000 bytes (XML_MAX_TEXT_LENGTH, "AttValue length too long") and,
// separately, an input buffer that holds more than 10,000,000 bytes behind the read position
// (XML_MAX_LOOKUP_LIMIT, "Huge input lookup", checked whenever the parser reads more). A region
// whose element would pass kMaxBetweenGaps is therefore cut in halves, again and again
// (render/RegionHalves.h), each piece its own <path> in the region's layer, and a run of
// whitespace (kShrinkGap, see there for why) goes before any element that would bring the bytes
// since the last such run over kMaxBetweenGaps. A file of small regions has none.
#include "render/Writers.h"

#include "render/BufferedWriter.h"
#include "render/Page.h"
#include "render/PathEmitter.h"
#include "render/RegionHalves.h"
#include "render/SvgParts.h"
#include "render/SvgRounding.h"
#include "render/XmlNames.h"

#include <QBuffer>
#include <QColor>

#include <array>
#include <cstdint>
#include <string>

namespace vf::render {
namespace {

// The most bytes between two kShrinkGap runs, and so the most one <path .../> element may take:
// libxml2's 10,000,000-byte limits less what may precede the element in the parser's buffer after
// a gap (at most 80 + 4,250 bytes), with a wide margin.
constexpr std::uint64_t kMaxBetweenGaps = 9'000'000;
// Each cut at least about halves the vertices; past this many cuts a region is written as it is.
constexpr int kMaxCuts = 40;

// libxml2 2.9's pull parser discards consumed input (SHRINK) only when fewer than 500 bytes of
// unread input are buffered, and its reads add 4,000 bytes whenever fewer than 250 remain, so
// after a tag a discard happens only by chance and large elements in a row add up towards the
// 10,000,000-byte lookup limit. Inside a run of character data, though, it discards whenever it
// reaches the end of its buffer (xmlParseCharData). At most 4,000 + 250 bytes are buffered ahead
// of the read position, so a run of whitespace longer than that always reaches the end of the
// buffer: after kShrinkGap spaces the parser's buffer starts afresh.
constexpr std::size_t kShrinkGap = 8'000;

// What the region's layers share while they are written.
struct SvgOutput {
    BufferedWriter& xml;
    UniqueXmlIds& ids;
    PathStyle style;
    double step = 0;           // polyline rounding (render/SvgRounding.h)
    std::uint64_t gapEnd = 0;  // xml.size() after the last kShrinkGap
};

// A region's path data, built in memory first so that its size is known before it is written.
QByteArray pathData(const model::DrawnRegion& region, const PathStyle& style)
{
    QByteArray data;
    QBuffer buffer(&data);
    buffer.open(QIODevice::WriteOnly);
    BufferedWriter out(buffer);
    SvgPathData sink(out);
    emitRegion(region, style, sink);
    static_cast<void>(out.finish());  // a QBuffer takes every write
    return data;
}

// A <path> element's text before its path data.
QByteArray pathHead(const QColor& color, const QString& id, const QString& label)
{
    QByteArray head;
    QBuffer buffer(&head);
    buffer.open(QIODevice::WriteOnly);
    BufferedWriter out(buffer);
    out << "<path id=\"" << id << "\" inkscape:label=\"" << label << '"';
    writeSvgFill(out, color);
    out << " fill-rule=\"evenodd\" d=\"";
    static_cast<void>(out.finish());  // a QBuffer takes every write
    return head;
}

std::size_t vertexCount(const model::DrawnRegion& region)
{
    std::size_t count = 0;
    for (const sim::Polygon& contour : region.contours)
        count += contour.size();
    return count;
}

// The region as <path> elements of at most kMaxBetweenGaps bytes each where cutting allows, a
// kShrinkGap before any element that would bring the bytes since the last gap over that. The first
// element takes `pathId`, claimed already, the others pathId-2, pathId-3, ... (a few bytes longer
// than the size checked here: well within the margin of kMaxBetweenGaps).
void writePaths(SvgOutput& out, const model::DrawnRegion& region, const QString& pathId, const QString& label,
                bool& first, int cuts)
{
    const QByteArray data = pathData(region, out.style);
    const std::uint64_t size = std::uint64_t(pathHead(region.color, pathId, label).size() + data.size()) + 4;
    if (size > kMaxBetweenGaps && cuts < kMaxCuts) {
        const std::size_t vertices = vertexCount(region);
        const std::array<model::DrawnRegion, 2> halves = cutInHalves(region);
        if (vertexCount(halves[0]) < vertices && vertexCount(halves[1]) < vertices) {
            for (const model::DrawnRegion& half : halves)
                writePaths(out, half, pathId, label, first, cuts + 1);
            return;
        }
    }
    if (out.xml.size() - out.gapEnd + size > kMaxBetweenGaps) {
        out.xml << std::string(kShrinkGap, ' ') << '\n';
        out.gapEnd = out.xml.size();
    }
    out.xml << pathHead(region.color, first ? pathId : out.ids.claim(pathId), label)
            << data << "\"/>\n";
    first = false;
}

void writeRegion(SvgOutput& out, const model::DrawnRegion& region)
{
    const QString pathId = out.ids.claim(sanitizedXmlId(region.name));
    const QString label = escapedXmlAttribute(region.name);
    out.xml << "<g id=\"" << out.ids.claim(QStringLiteral("layer-") + pathId)
            << "\" inkscape:groupmode=\"layer\" inkscape:label=\"" << label << '"';
    if (!region.visible)
        out.xml << " style=\"display:none\"";
    out.xml << ">\n";
    bool first = true;
    if (out.style.bezier)
        writePaths(out, region, pathId, label, first, 0);
    else  // rounded once, before any cut: the cuts' new vertices on the seams are written exactly
        writePaths(out, roundedRegion(region, out.step).region, pathId, label, first, 0);
    out.xml << "</g>\n";
}

} // namespace

QString writeSvg(const model::Drawing& drawing, const ExportOptions& options, QIODevice& out)
{
    BufferedWriter xml(out);
    UniqueXmlIds ids;
    writeSvgHeader(xml, drawing, pageFor(drawing, options));
    if (options.background)
        writeSvgBackground(xml, drawing, ids);
    SvgOutput output{xml, ids, pathStyle(drawing, options), svgCoordinateStep(drawing)};
    for (const model::DrawnRegion& region : drawing.regions)
        writeRegion(output, region);
    xml << "</svg>\n";
    return xml.finish();
}

} // namespace vf::render
