#pragma once
// Reading our own SVG back without QtSvg, shared by the export tests and the command-line tests:
// an XML parse (QXmlStreamReader) of the layers, the region paths and their absolute M/L/C/Z data.
#include "render/BezierFit.h"

#include <QFile>
#include <QString>
#include <QStringList>
#include <QXmlStreamReader>

#include <cctype>
#include <charconv>
#include <string>
#include <vector>

namespace vf::test {

inline QString svgNamespace() { return QStringLiteral("http://www.w3.org/2000/svg"); }
inline QString inkscapeNamespace() { return QStringLiteral("http://www.inkscape.org/namespaces/inkscape"); }

struct ParsedPath {
    QString id, label, fill, fillOpacity, fillRule;
    std::vector<render::FittedContour> contours;
};

struct ParsedLayer {
    QString id, label, groupMode, style;
    std::vector<ParsedPath> paths;
};

struct ParsedSvg {
    QString width, height, viewBox, backgroundFill;
    QStringList ids;
    std::vector<ParsedLayer> layers;
    QString error;
};

// Absolute M/L/C/Z only, as our writer produces; anything else is an error.
inline bool parsePathData(const std::string& d, std::vector<render::FittedContour>& contours)
{
    std::size_t i = 0;
    char command = 0;
    const auto skipSeparators = [&] {
        while (i < d.size() && (d[i] == ' ' || d[i] == ',' || d[i] == '\n' || d[i] == '\t'))
            ++i;
    };
    const auto number = [&](double& value) {
        skipSeparators();
        const auto [end, ec] = std::from_chars(d.data() + i, d.data() + d.size(), value);
        i = std::size_t(end - d.data());
        return ec == std::errc();
    };
    const auto point = [&](sim::Vec2& p) { return number(p.x) && number(p.y); };
    for (skipSeparators(); i < d.size(); skipSeparators()) {
        if (std::isalpha(static_cast<unsigned char>(d[i])))
            command = d[i++];
        else if (command == 0 || command == 'Z')
            return false;
        render::PathSegment segment;
        switch (command) {
        case 'M':
            contours.push_back({});
            if (!point(contours.back().start))
                return false;
            command = 'L'; // further pairs are implicit line-tos
            break;
        case 'L':
            segment.isLine = true;
            if (contours.empty() || !point(segment.end))
                return false;
            contours.back().segments.push_back(segment);
            break;
        case 'C':
            if (contours.empty() || !point(segment.control1) || !point(segment.control2) || !point(segment.end))
                return false;
            contours.back().segments.push_back(segment);
            break;
        case 'Z':
            break;
        default:
            return false;
        }
    }
    return true;
}

inline ParsedSvg parseSvg(const QString& fileName)
{
    ParsedSvg svg;
    QFile file(fileName);
    if (!file.open(QIODevice::ReadOnly)) {
        svg.error = file.errorString();
        return svg;
    }
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement || xml.namespaceUri() != svgNamespace())
            continue;
        const QXmlStreamAttributes a = xml.attributes();
        if (a.hasAttribute(QStringLiteral("id")))
            svg.ids << a.value(QStringLiteral("id")).toString();
        const auto inkscape = [&](const char* name) {
            return a.value(inkscapeNamespace(), QLatin1String(name)).toString();
        };
        const auto plain = [&](const char* name) { return a.value(QLatin1String(name)).toString(); };
        if (xml.name() == u"svg") {
            svg.width = plain("width");
            svg.height = plain("height");
            svg.viewBox = plain("viewBox");
        } else if (xml.name() == u"g") {
            svg.layers.push_back({plain("id"), inkscape("label"), inkscape("groupmode"), plain("style"), {}});
        } else if (xml.name() == u"rect") {
            svg.backgroundFill = plain("fill");
        } else if (xml.name() == u"path") {
            ParsedPath path{plain("id"), inkscape("label"), plain("fill"), plain("fill-opacity"),
                            plain("fill-rule"), {}};
            if (svg.layers.empty() || !parsePathData(plain("d").toStdString(), path.contours)) {
                svg.error = QStringLiteral("bad path %1").arg(path.id);
                return svg;
            }
            svg.layers.back().paths.push_back(std::move(path));
        }
    }
    if (xml.hasError())
        svg.error = xml.errorString();
    return svg;
}

inline sim::Polygon verticesOf(const render::FittedContour& contour)
{
    sim::Polygon vertices{contour.start};
    for (const render::PathSegment& s : contour.segments)
        vertices.push_back(s.end);
    return vertices;
}

// Every region path of the file, bottom to top (the background is a <rect>, never a path).
inline std::vector<const ParsedPath*> regionPaths(const ParsedSvg& svg)
{
    std::vector<const ParsedPath*> paths;
    for (const ParsedLayer& layer : svg.layers) {
        for (const ParsedPath& path : layer.paths)
            paths.push_back(&path);
    }
    return paths;
}

// The path's subpaths as the polygons of their segment end points (exact in polyline mode).
inline std::vector<sim::Polygon> polygonsOf(const ParsedPath& path)
{
    std::vector<sim::Polygon> polygons;
    for (const render::FittedContour& contour : path.contours)
        polygons.push_back(verticesOf(contour));
    return polygons;
}

} // namespace vf::test
