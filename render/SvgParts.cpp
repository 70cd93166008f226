#include "render/SvgParts.h"

#include "render/SvgRounding.h"

namespace vf::render {

void SvgPathData::moveTo(sim::Vec2 point)
{
    command('M');
    write(point);
}

void SvgPathData::lineTo(sim::Vec2 point)
{
    command('L');
    write(point);
}

void SvgPathData::cubicTo(sim::Vec2 control1, sim::Vec2 control2, sim::Vec2 end)
{
    command('C');
    write(control1);
    m_out << ' ';
    write(control2);
    m_out << ' ';
    write(end);
}

void SvgPathData::closePath()
{
    command('Z');
}

void SvgPathData::command(char letter)
{
    if (letter == m_last && (letter == 'L' || letter == 'C'))
        m_out << ' ';
    else
        m_out << letter;
    m_last = letter;
}

void SvgPathData::write(sim::Vec2 point)
{
    if (m_step > 0)  // + 0.0 turns -0 into 0, one character shorter
        point = {roundedToStep(point.x, m_step) + 0.0, roundedToStep(point.y, m_step) + 0.0};
    m_out << point.x << ' ' << point.y;
}

void writeSvgFill(BufferedWriter& xml, const QColor& color)
{
    xml << " fill=\"" << color.name(QColor::HexRgb) << '"';
    if (color.alpha() < 255)
        xml << " fill-opacity=\"" << color.alpha() / 255.0 << '"';
}

void writeSvgHeader(BufferedWriter& xml, const model::Drawing& drawing, const Page& page)
{
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\"\n"
           "     xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"\n"
           "     xmlns:sodipodi=\"http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd\"\n"
           "     version=\"1.1\" width=\""
        << page.width << "pt\" height=\"" << page.height << "pt\" viewBox=\"0 0 " << drawing.width << ' '
        << drawing.height << "\">\n";
}

void writeSvgBackground(BufferedWriter& xml, const model::Drawing& drawing, UniqueXmlIds& ids)
{
    xml << "<g id=\"" << ids.claim(QStringLiteral("background"))
        << "\" inkscape:groupmode=\"layer\" inkscape:label=\"Background\" sodipodi:insensitive=\"true\">\n"
        << "<rect id=\"" << ids.claim(QStringLiteral("background-rect")) << "\" x=\"0\" y=\"0\" width=\""
        << drawing.width << "\" height=\"" << drawing.height << '"';
    writeSvgFill(xml, drawing.background);
    xml << "/>\n</g>\n";
}

} // namespace vf::render
