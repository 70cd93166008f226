// SVG written by hand rather than through QtSvg: we need Inkscape layers, ids and full precision,
// and the file must stream. Layout: an optional locked "Background" layer, then one layer per
// region (bottom to top) holding that region's single even-odd <path>. Hidden regions are kept,
// as Inkscape keeps hidden layers: the layer gets style="display:none".
//
// Limit: coordinates are exact (shortest round-trip), about 38 bytes per polyline vertex, so a
// region of more than ~250k vertices in polyline mode has a `d` attribute over the 10 MB that
// libxml2-based readers (xmllint, Inkscape, rsvg) accept by default. Bézier mode is far smaller.
#include "render/Writers.h"

#include "render/BufferedWriter.h"
#include "render/Page.h"
#include "render/PathEmitter.h"
#include "render/XmlNames.h"

#include <QColor>

namespace vf::render {
namespace {

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

void writeRegion(BufferedWriter& xml, const model::DrawnRegion& region, const PathStyle& style,
                 UniqueXmlIds& ids)
{
    const QString pathId = ids.claim(sanitizedXmlId(region.name));
    const QString label = escapedXmlAttribute(region.name);
    xml << "<g id=\"" << ids.claim(QStringLiteral("layer-") + pathId)
        << "\" inkscape:groupmode=\"layer\" inkscape:label=\"" << label << '"';
    if (!region.visible)
        xml << " style=\"display:none\"";
    xml << ">\n<path id=\"" << pathId << "\" inkscape:label=\"" << label << '"';
    writeFill(xml, region.color);
    xml << " fill-rule=\"evenodd\" d=\"";
    SvgPathData pathData(xml);
    emitRegion(region, style, pathData);
    xml << "\"/>\n</g>\n";
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
