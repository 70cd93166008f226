// Reading SVG geometry with QXmlStreamReader rather than QtSvg: QtSvg hands out no paths and
// truncates long ones (32,767 elements in Qt 6.4), and logos exported from the app are long.
#include "model/SvgImport.h"

#include "model/Scene.h"
#include "model/StartingContour.h"
#include "model/SvgOutline.h"
#include "model/SvgPathData.h"
#include "model/SvgSyntax.h"
#include "sim/Crossings.h"

#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QXmlStreamReader>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>
#include <numbers>
#include <optional>
#include <utility>

namespace vf::model {
namespace {

using namespace Qt::StringLiterals;
using svg::Outline;
using svg::Segment;
using svg::Vec2;

constexpr qint64 kMaxFileBytes = qint64(256) << 20;
// Groups are read by recursion; drawings nest a few dozen deep, a hostile file could nest millions
// and overflow the stack.
constexpr int kMaxGroupDepth = 1000;

// Thrown by any check; importSvg turns it into the error line. `where` is "line:col" or empty.
struct ImportError {
    QString where;
    QString what;
};

// What an element inherits from its ancestors (SVG's inherited properties, and the composited
// product of their opacities).
struct Context {
    QTransform toCanvas;                  // this element's user units to canvas units
    std::optional<QColor> fill = QColor(Qt::black);  // nullopt: fill="none"
    QColor currentColor = QColor(Qt::black);
    double fillOpacity = 1.0;
    double opacity = 1.0;
    bool visible = true;
    bool evenOdd = false;  // fill-rule; SVG's default is nonzero
};

// Elements whose content is never drawn where it stands: referenced resources and metadata.
bool isNeverDrawn(QStringView tag)
{
    static const QStringList kTags = {u"defs"_s,  u"clipPath"_s, u"mask"_s,  u"symbol"_s,   u"marker"_s,
                                      u"pattern"_s, u"linearGradient"_s, u"radialGradient"_s, u"filter"_s,
                                      u"title"_s, u"desc"_s,     u"metadata"_s, u"script"_s};
    return kTags.contains(tag);
}

// Why an element we do not import is skipped, for the warning that counts them.
QString skipReason(QStringView tag)
{
    if (tag == u"polyline" || tag == u"line")
        return u"open shapes enclose no ink"_s;
    if (tag == u"style")
        return u"CSS style sheets are not applied (only style=\"\" attributes)"_s;
    if (tag == u"use")
        return u"references are not followed"_s;
    return u"not supported"_s;
}

Segment lineTo(Vec2 to) { return {Segment::Kind::Line, {}, {}, to, {}}; }

// A quarter of the ellipse with radii r around center, from parameter angle theta0 on, clockwise
// as seen on screen (y down).
Segment quarterArc(Vec2 center, Vec2 r, double theta0)
{
    Segment segment{Segment::Kind::Arc, {}, {}, {}, {}};
    segment.arc = {center, {r.x, 0.0}, {0.0, r.y}, theta0, 0.5 * std::numbers::pi};
    segment.end = center + Vec2(r.x * std::cos(theta0 + 0.5 * std::numbers::pi), r.y * std::sin(theta0 + 0.5 * std::numbers::pi));
    return segment;
}

Outline ellipseOutline(Vec2 center, Vec2 r)
{
    Segment segment{Segment::Kind::Arc, {}, {}, center + Vec2(r.x, 0.0), {}};
    segment.arc = {center, {r.x, 0.0}, {0.0, r.y}, 0.0, 2.0 * std::numbers::pi};
    return {{center + Vec2(r.x, 0.0), {segment}}};
}

// Rounded corners as SVG 1.1 draws them: a missing radius takes the other's value, and each is
// at most half the side.
Outline rectOutline(Vec2 p, Vec2 size, Vec2 r)
{
    r = glm::min(r, 0.5 * size);
    if (r.x <= 0.0 || r.y <= 0.0)
        return {{p, {lineTo(p + Vec2(size.x, 0.0)), lineTo(p + size), lineTo(p + Vec2(0.0, size.y))}}};
    const double pi = std::numbers::pi;
    const Vec2 q = p + size;
    return {{{p.x + r.x, p.y},
             {lineTo({q.x - r.x, p.y}), quarterArc({q.x - r.x, p.y + r.y}, r, -0.5 * pi),
              lineTo({q.x, q.y - r.y}), quarterArc({q.x - r.x, q.y - r.y}, r, 0.0),
              lineTo({p.x + r.x, q.y}), quarterArc({p.x + r.x, q.y - r.y}, r, 0.5 * pi),
              lineTo({p.x, p.y + r.y}), quarterArc({p.x + r.x, p.y + r.y}, r, pi)}}};
}

// Whether SVG's nonzero rule fills these non-crossing contours as the regions' even-odd rule does.
// Just inside contour i, the winding number is the sum of the directions of i and of the contours
// around it, and the even-odd count is one more than the number of contours around it. Past
// kNestingBudget vertices visited (sim::visitEnclosures) the answer is nullopt: unknown (only a
// warning depends on it).
constexpr std::size_t kNestingBudget = 100'000'000;

std::optional<bool> nonzeroFillsEvenOdd(const std::vector<sim::Polygon>& contours, const std::vector<int>& directions)
{
    std::vector<int> winding = directions, depth(contours.size(), 0);
    const bool known = sim::visitEnclosures(contours, kNestingBudget, [&](std::size_t inner, std::size_t outer) {
        winding[inner] += directions[outer];
        ++depth[inner];
    });
    if (!known)
        return std::nullopt;
    for (std::size_t i = 0; i < contours.size(); ++i)
        if ((winding[i] != 0) != (depth[i] % 2 == 0))
            return false;
    return true;
}

class Importer {
public:
    Importer(const QByteArray& svg, double width, double height, double spacing)
        : m_xml(svg), m_canvas(width, height), m_spacing(spacing)
    {
    }

    SvgImport run()
    {
        readRoot();
        while (!m_xml.atEnd())  // the rest of the document must be well-formed too
            m_xml.readNext();
        throwIfXmlError();
        if (m_shapes.empty())
            throw ImportError{{}, u"nothing to import (no filled closed shape)"_s};
        SvgImport result;
        result.shapes = std::move(m_shapes);
        for (const auto& [what, count] : m_skipped)
            result.warnings << u"skipped %1 × %2"_s.arg(count).arg(what);
        result.warnings << m_notes;
        return result;
    }

private:
    void throwIfXmlError()
    {
        if (m_xml.hasError())
            throw ImportError{u"%1:%2"_s.arg(m_xml.lineNumber()).arg(m_xml.columnNumber()),
                              u"not well-formed XML: "_s + m_xml.errorString()};
    }
    [[noreturn]] void fail(const QString& what) const { throw ImportError{m_where, what}; }

    bool has(const QString& name) const { return m_attributes.hasAttribute(name); }
    QString attribute(const QString& name) const { return m_attributes.value(name).toString(); }
    // A presentation property: style="" wins over the attribute of the same name.
    QString property(const QString& name) const { return m_style.value(name, attribute(name)).trimmed(); }

    // Makes the current start element the one attribute() and property() read.
    void enterElement()
    {
        m_where = u"%1:%2"_s.arg(m_xml.lineNumber()).arg(m_xml.columnNumber());
        m_attributes = m_xml.attributes();
        m_style.clear();
        for (const QString& declaration : attribute(u"style"_s).split(u';', Qt::SkipEmptyParts)) {
            const qsizetype colon = declaration.indexOf(u':');
            if (colon > 0)
                m_style.insert(declaration.first(colon).trimmed(), declaration.sliced(colon + 1));
        }
    }

    void readRoot()
    {
        if (!m_xml.readNextStartElement()) {
            throwIfXmlError();
            throw ImportError{{}, u"not an SVG file: no root element"_s};
        }
        if (m_xml.name() != u"svg" || (!m_xml.namespaceUri().isEmpty() && m_xml.namespaceUri() != u"http://www.w3.org/2000/svg"))
            throw ImportError{{}, u"not an SVG file: the root element is <%1>, not <svg>"_s.arg(m_xml.qualifiedName())};
        m_svgNamespace = m_xml.namespaceUri().toString();
        enterElement();
        Context root;
        root.toCanvas = fitToCanvas();
        if (const std::optional<Context> context = childContext(root))
            readChildren(*context);
        else
            m_xml.skipCurrentElement();
    }

    // The viewBox (or 0 0 width height) scaled uniformly into the canvas and centred.
    QTransform fitToCanvas()
    {
        QString reason;
        std::vector<double> box;
        if (has(u"viewBox"_s)) {
            const auto numbers = svg::parseNumberList(attribute(u"viewBox"_s), reason);
            if (!numbers || numbers->size() != 4 || (*numbers)[2] <= 0.0 || (*numbers)[3] <= 0.0)
                fail(u"viewBox %1 is not four numbers with positive width and height"_s.arg(svg::quoted(attribute(u"viewBox"_s))));
            box = *numbers;
        } else if (has(u"width"_s) && has(u"height"_s)) {
            const auto w = svg::parseLength(attribute(u"width"_s), reason);
            const auto h = w ? svg::parseLength(attribute(u"height"_s), reason) : std::nullopt;
            if (!h)
                fail(u"without a viewBox, width and height must be in px: "_s + reason);
            if (*w <= 0.0 || *h <= 0.0)
                fail(u"width and height must be positive"_s);
            box = {0.0, 0.0, *w, *h};
        } else {
            fail(u"<svg> has neither a viewBox nor a width and height, so its size is unknown"_s);
        }
        const double scale = std::min(m_canvas.x / box[2], m_canvas.y / box[3]);
        return QTransform(scale, 0.0, 0.0, scale, 0.5 * (m_canvas.x - scale * box[2]) - scale * box[0],
                          0.5 * (m_canvas.y - scale * box[3]) - scale * box[1]);
    }

    // This element's context from its parent's and its own attributes; nullopt with display="none".
    std::optional<Context> childContext(const Context& parent)
    {
        if (property(u"display"_s) == u"none")
            return std::nullopt;
        Context context = parent;
        if (has(u"transform"_s)) {
            QString reason;
            const std::optional<QTransform> own = svg::parseTransform(attribute(u"transform"_s), reason);
            if (!own)
                fail(reason);
            context.toCanvas = *own * parent.toCanvas;  // own first, then the ancestors'
        }
        if (const QString color = property(u"color"_s); !color.isEmpty() && color != u"inherit")
            context.currentColor = colorValue(u"color"_s, color, parent.currentColor);
        if (const QString fill = property(u"fill"_s); !fill.isEmpty() && fill != u"inherit")
            context.fill = paintValue(fill, context.currentColor, parent.fill);
        context.fillOpacity = opacityValue(u"fill-opacity"_s, parent.fillOpacity);
        context.opacity = parent.opacity * opacityValue(u"opacity"_s, 1.0);
        if (const QString rule = property(u"fill-rule"_s); rule == u"evenodd" || rule == u"nonzero")
            context.evenOdd = rule == u"evenodd";
        if (const QString visibility = property(u"visibility"_s); !visibility.isEmpty() && visibility != u"inherit")
            context.visible = visibility == u"visible";
        return context;
    }

    QColor colorValue(const QString& name, const QString& text, const QColor& fallback)
    {
        const QColor color = svg::parseColor(text);
        if (color.isValid())
            return color;
        m_notes << u"%1: %2 %3 is not a colour we read; inherited instead"_s.arg(m_where, name, svg::quoted(text));
        return fallback;
    }

    std::optional<QColor> paintValue(const QString& text, const QColor& currentColor, const std::optional<QColor>& inherited)
    {
        if (text == u"none")
            return std::nullopt;
        if (text == u"currentColor")
            return currentColor;
        if (text.startsWith(u"url(")) {
            // A gradient or pattern: its fallback colour if one follows, else black. Without the
            // closing parenthesis nothing follows (not the whole text again: endless recursion).
            const qsizetype close = text.indexOf(u')');
            const QString fallback = close < 0 ? QString() : text.sliced(close + 1).trimmed();
            if (!fallback.isEmpty())
                return paintValue(fallback, currentColor, inherited);
            m_notes << u"%1: fill %2 imported as black (gradients and patterns are not read)"_s.arg(m_where, svg::quoted(text));
            return QColor(Qt::black);
        }
        return colorValue(u"fill"_s, text, inherited.value_or(QColor(Qt::black)));
    }

    double opacityValue(const QString& name, double inherited) const
    {
        const QString text = property(name);
        if (text.isEmpty() || text == u"inherit")
            return inherited;
        const std::optional<double> value = svg::parseNumber(text);
        return value ? std::clamp(*value, 0.0, 1.0) : inherited;
    }

    // Counted, so that a file of a thousand strokes gives one warning, not a thousand.
    void countSkipped(const QString& what)
    {
        auto it = std::find_if(m_skipped.begin(), m_skipped.end(), [&](const auto& entry) { return entry.first == what; });
        if (it == m_skipped.end())
            m_skipped.emplace_back(what, 1);
        else
            ++it->second;
    }

    // Children of the current element up to its end tag, and theirs. The open groups are a stack
    // here, not the call stack: a frame of this function (inlined callees, sanitizer redzones)
    // can take kilobytes, and hostile files nest groups as deep as the limit.
    void readChildren(const Context& root)
    {
        std::vector<Context> open{root};  // the element's context, then each open group's
        while (!open.empty()) {
            if (!m_xml.readNextStartElement()) {  // the innermost one's end tag
                open.pop_back();
                continue;
            }
            const QString tag = m_xml.name().toString();
            if (m_xml.namespaceUri() != m_svgNamespace || isNeverDrawn(tag)) {
                m_xml.skipCurrentElement();  // another vocabulary (Inkscape's editor state), or resources
                continue;
            }
            enterElement();
            std::optional<Context> context = childContext(open.back());
            if (!context) {
                m_xml.skipCurrentElement();
            } else if (tag == u"g" || tag == u"a") {
                if (int(open.size()) > kMaxGroupDepth)
                    fail(u"groups nested deeper than %1 levels"_s.arg(kMaxGroupDepth));
                open.push_back(std::move(*context));
            } else if (tag == u"path" || tag == u"polygon" || tag == u"rect" || tag == u"circle" || tag == u"ellipse") {
                importShape(tag, *context);
                m_xml.skipCurrentElement();  // children such as <title> or <animate>
            } else {
                countSkipped(u"<%1>: %2"_s.arg(tag, skipReason(tag)));
                m_xml.skipCurrentElement();
            }
        }
    }

    double length(const QString& name)
    {
        if (!has(name))
            return 0.0;
        QString reason;
        const std::optional<double> value = svg::parseLength(attribute(name), reason);
        if (!value)
            fail(u"%1: %2"_s.arg(name, reason));
        return *value;
    }

    Outline outline(const QString& tag, const QString& name)
    {
        QString reason;
        if (tag == u"path") {
            std::optional<Outline> outline = svg::parsePathData(attribute(u"d"_s), reason);
            if (!outline)
                fail(u"path \"%1\": bad path data: %2"_s.arg(name, reason));
            return std::move(*outline);
        }
        if (tag == u"polygon") {
            const auto numbers = svg::parseNumberList(attribute(u"points"_s), reason);
            if (!numbers || numbers->size() % 2 != 0)
                fail(u"polygon \"%1\": points must be pairs of numbers: %2"_s.arg(name, numbers ? u"odd count"_s : reason));
            if (numbers->empty())
                return {};
            svg::Subpath subpath{{(*numbers)[0], (*numbers)[1]}, {}};
            for (std::size_t i = 2; i < numbers->size(); i += 2)
                subpath.segments.push_back(lineTo({(*numbers)[i], (*numbers)[i + 1]}));
            return {subpath};
        }
        if (tag == u"rect") {
            const Vec2 size(length(u"width"_s), length(u"height"_s));
            if (size.x <= 0.0 || size.y <= 0.0)
                return {};
            const bool hasRx = has(u"rx"_s), hasRy = has(u"ry"_s);
            const double rx = length(u"rx"_s), ry = length(u"ry"_s);
            return rectOutline({length(u"x"_s), length(u"y"_s)}, size, {hasRx ? rx : ry, hasRy ? ry : rx});
        }
        const Vec2 center(length(u"cx"_s), length(u"cy"_s));
        const Vec2 radii = tag == u"circle" ? Vec2(length(u"r"_s)) : Vec2(length(u"rx"_s), length(u"ry"_s));
        if (radii.x <= 0.0 || radii.y <= 0.0)
            return {};
        return ellipseOutline(center, radii);
    }

    void importShape(const QString& tag, const Context& context)
    {
        const int index = ++m_tagCount[tag];
        const QString id = attribute(u"id"_s).trimmed();
        const QString name = id.isEmpty() ? u"%1 %2"_s.arg(tag).arg(index) : id;
        Outline shape = outline(tag, name);
        if (!context.fill || !context.visible) {
            countSkipped(u"<%1> with %2"_s.arg(tag, context.visible ? u"fill=\"none\""_s : u"visibility=\"hidden\""_s));
            return;
        }
        svg::transform(shape, context.toCanvas);
        if (!(svg::vertexBound(shape, m_spacing) <= static_cast<double>(limits::maxPolygonPoints)))  // NaN too
            fail(u"shape \"%1\" would need more than %2 vertices at spacing %3"_s.arg(name).arg(limits::maxPolygonPoints).arg(m_spacing));

        ImportedShape imported{name, *context.fill, {}};
        std::vector<int> directions;  // of each contour as drawn, for the fill rule
        imported.color.setAlphaF(static_cast<float>(imported.color.alphaF() * context.fillOpacity * context.opacity));
        for (const sim::Polygon& polyline : svg::flatten(shape, m_spacing)) {
            std::optional<sim::Polygon> contour = startingContour(polyline, m_spacing);
            if (!contour)
                continue;
            imported.contours.push_back(std::move(*contour));
            directions.push_back(sim::signedArea(polyline) > 0.0 ? 1 : -1);
        }
        if (imported.contours.empty()) {
            m_notes << u"%1: %2 \"%3\" skipped: it has no area"_s.arg(m_where, tag, name);
            return;
        }
        std::vector<const sim::Polygon*> contours;
        for (const sim::Polygon& polygon : imported.contours)
            contours.push_back(&polygon);
        if (!sim::isSimple(contours))
            fail(u"shape \"%1\" crosses itself"_s.arg(name));
        if (const std::optional<bool> agree = context.evenOdd ? true : nonzeroFillsEvenOdd(imported.contours, directions); !agree)
            m_notes << u"%1: %2 \"%3\": too many nested contours to tell whether fill-rule=\"nonzero\" fills them as regions do (even-odd)"_s.arg(m_where, tag, name);
        else if (!*agree)
            m_notes << u"%1: %2 \"%3\": a hole drawn the same way round as its outline, filled under fill-rule=\"nonzero\", is a hole here (regions fill even-odd)"_s.arg(m_where, tag, name);
        m_shapes.push_back(std::move(imported));
    }

    QXmlStreamReader m_xml;
    Vec2 m_canvas;
    double m_spacing;
    QString m_svgNamespace;
    // The element being read: where it is, its attributes and its style="" declarations.
    QString m_where;
    QXmlStreamAttributes m_attributes;
    QHash<QString, QString> m_style;

    std::vector<ImportedShape> m_shapes;
    QHash<QString, int> m_tagCount;
    std::vector<std::pair<QString, int>> m_skipped;  // what and how many, in order of first appearance
    QStringList m_notes;                              // warnings about single elements
};

} // namespace

SvgImport importSvg(const QByteArray& svg, const QString& sourceName, double canvasWidth, double canvasHeight, double spacing)
{
    SvgImport result;
    try {
        if (!(canvasWidth > 0.0 && canvasHeight > 0.0 && spacing > 0.0) || !std::isfinite(canvasWidth * canvasHeight * spacing))
            throw ImportError{{}, u"canvas size and spacing must be positive"_s};
        if (svg.trimmed().isEmpty())
            throw ImportError{{}, u"empty file, not an SVG document"_s};
        result = Importer(svg, canvasWidth, canvasHeight, spacing).run();
        for (QString& warning : result.warnings)
            warning.prepend(sourceName + u": "_s);
    } catch (const ImportError& e) {
        result = {};
        result.error = sourceName + u": "_s + (e.where.isEmpty() ? QString() : e.where + u": "_s) + e.what;
    } catch (const std::bad_alloc&) {
        result = {};
        result.error = sourceName + u": not enough memory to import it"_s;
    } catch (const std::exception& e) {  // a defect of ours; still one line, and the caller goes on
        result = {};
        result.error = sourceName + u": cannot import: "_s + QString::fromLocal8Bit(e.what());
    }
    return result;
}

SvgImport importSvgFile(const QString& path, double canvasWidth, double canvasHeight, double spacing)
{
    const QString name = QFileInfo(path).fileName();
    QFile file(path);
    SvgImport result;
    if (!file.open(QIODevice::ReadOnly))
        result.error = name + u": "_s + file.errorString();
    else if (file.size() > kMaxFileBytes)
        result.error = u"%1: %2 bytes is more than the %3 an SVG file may have"_s.arg(name).arg(file.size()).arg(kMaxFileBytes);
    else
        result = importSvg(file.readAll(), name, canvasWidth, canvasHeight, spacing);
    return result;
}

} // namespace vf::model
