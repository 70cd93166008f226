// The starting contours of the scene's shapes.
//
// Orientation: every contour has POSITIVE sim::signedArea (the shoelace sum on the raw canvas
// coordinates), the engine's convention (sim/Geometry.h, sim::circle, the area correction's target
// areas). With y pointing down that is clockwise as seen on screen: right, then down, then left.
#include "model/Scene.h"

#include "model/SplitMix64.h"
#include "model/TextOutlines.h"

#include <QFont>
#include <QGuiApplication>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

namespace vf::model {
namespace {

// Small shapes still get a recognisable outline, matching sim::circle's minimum.
constexpr double kMinVertices = 8.0;

// theta increases from +x towards +y, as in sim::circle: positive area.
sim::Vec2 ellipsePoint(sim::Vec2 radii, double theta) { return radii * sim::Vec2(std::cos(theta), std::sin(theta)); }

// Walks the ellipse in parameter steps far shorter than maxSpacing, calling
// visit(thetaBefore, dTheta, chordLength) per step. Shared by both passes of contour(EllipseShape).
template <typename Visit>
void marchEllipse(sim::Vec2 radii, double maxSpacing, Visit visit)
{
    const double steps = 8.0 * std::ceil(2.0 * std::numbers::pi * std::max(radii.x, radii.y) / maxSpacing) + 256.0;
    const double dTheta = 2.0 * std::numbers::pi / steps;
    sim::Vec2 previous = ellipsePoint(radii, 0.0);
    for (double j = 1.0; j <= steps; j += 1.0) {
        const sim::Vec2 p = ellipsePoint(radii, j * dTheta);
        visit((j - 1.0) * dTheta, dTheta, glm::length(p - previous));
        previous = p;
    }
}

sim::Polygon contour(const CircleShape& circle, double maxSpacing)
{
    return sim::circle(circle.center, circle.radius, maxSpacing);
}

// Vertices at equal arc length: uniform parameter steps would crowd the ends of a slim ellipse
// with edges far below maxSpacing/2, which the tracker would only collapse again.
sim::Polygon contour(const EllipseShape& ellipse, double maxSpacing)
{
    double length = 0.0;
    marchEllipse(ellipse.radii, maxSpacing, [&length](double, double, double chord) { length += chord; });
    const auto count = static_cast<std::size_t>(std::max(kMinVertices, std::ceil(length / maxSpacing)));
    const double spacing = length / static_cast<double>(count);

    sim::Polygon polygon;
    polygon.reserve(count);
    double walked = 0.0;
    marchEllipse(ellipse.radii, maxSpacing, [&](double theta, double dTheta, double chord) {
        while (polygon.size() < count && walked + chord >= static_cast<double>(polygon.size()) * spacing) {
            const double f = chord > 0.0 ? (static_cast<double>(polygon.size()) * spacing - walked) / chord : 0.0;
            polygon.push_back(ellipse.center + ellipsePoint(ellipse.radii, theta + f * dTheta));
        }
        walked += chord;
    });
    // The chord sum slightly underestimates the arc; resampling guarantees the bound regardless.
    return sim::resample(polygon, maxSpacing);
}

sim::Polygon contour(const RectShape& rect, double maxSpacing)
{
    // Along the top edge first: positive area.
    const sim::Vec2 p = rect.topLeft;
    return sim::resample({p, p + sim::Vec2(rect.size.x, 0.0), p + rect.size, p + sim::Vec2(0.0, rect.size.y)}, maxSpacing);
}

sim::Polygon contour(const PolygonShape& shape, double maxSpacing)
{
    sim::Polygon polygon = sim::resample(shape.points, maxSpacing);
    if (sim::signedArea(polygon) < 0.0)
        std::reverse(polygon.begin(), polygon.end());
    return polygon;
}

// The contours as Import SVG gave them; a finer spacing than the import's (the app's tracking
// settings changed since) splits their edges further.
std::vector<sim::Polygon> partContours(const SvgShape& svg, const ImportedShape& part, double maxSpacing)
{
    if (maxSpacing >= svg.spacing)
        return part.contours;
    std::vector<sim::Polygon> contours;
    for (const sim::Polygon& c : part.contours)
        contours.push_back(sim::resample(c, maxSpacing));
    return contours;
}

template <typename S>
std::vector<sim::Polygon> contours(const S& shape, double maxSpacing)
{
    return {contour(shape, maxSpacing)};
}

std::vector<sim::Polygon> contours(const SvgShape& svg, double maxSpacing)
{
    std::vector<sim::Polygon> all;
    for (const ImportedShape& part : svg.shapes)
        std::ranges::move(partContours(svg, part, maxSpacing), std::back_inserter(all));
    return all;
}

// Upper bounds on the perimeter and on the vertices kept from the input.
double perimeterBound(const CircleShape& c) { return 2.0 * std::numbers::pi * c.radius; }
double perimeterBound(const EllipseShape& e) { return 2.0 * std::numbers::pi * std::max(e.radii.x, e.radii.y); }
double perimeterBound(const RectShape& r) { return 2.0 * (r.size.x + r.size.y); }
double perimeterBound(const PolygonShape& p) { return sim::perimeter(p.points); }
double cornerCount(const CircleShape&) { return 0.0; }
double cornerCount(const EllipseShape&) { return 0.0; }
double cornerCount(const RectShape&) { return 4.0; }
double cornerCount(const PolygonShape& p) { return static_cast<double>(p.points.size()); }

template <typename F>
double sumOverContours(const SvgShape& svg, F f)
{
    double sum = 0.0;
    for (const ImportedShape& part : svg.shapes)
        for (const sim::Polygon& c : part.contours)
            sum += f(c);
    return sum;
}
double perimeterBound(const SvgShape& s) { return sumOverContours(s, sim::perimeter); }
double cornerCount(const SvgShape& s) { return sumOverContours(s, [](const sim::Polygon& c) { return double(c.size()); }); }

} // namespace

std::vector<sim::Polygon> shapeContours(const Shape& shape, double maxSpacing)
{
    return std::visit([maxSpacing](const auto& s) { return contours(s, maxSpacing); }, shape);
}

double shapeVertexBound(const Shape& shape, double maxSpacing)
{
    // Each edge of length L becomes ceil(L / maxSpacing) <= L / maxSpacing + 1 edges; curves get at
    // least kMinVertices and at most one extra vertex from rounding up.
    return std::visit([maxSpacing](const auto& s) { return perimeterBound(s) / maxSpacing + cornerCount(s); }, shape)
           + kMinVertices + 1.0;
}

std::vector<StartingRegion> startingLooks(const RegionSpec& region)
{
    const auto* svg = std::get_if<SvgShape>(&region.shape);
    if (!svg)
        return {{region.name, region.color, region.visible, {}}};
    std::vector<StartingRegion> looks;
    for (const ImportedShape& part : svg->shapes)
        looks.push_back({region.name + u'/' + part.name, region.color.isValid() ? region.color : part.color, region.visible, {}});
    return looks;
}

std::vector<StartingRegion> startingRegions(const RegionSpec& region, double maxSpacing)
{
    std::vector<StartingRegion> regions = startingLooks(region);
    if (const auto* svg = std::get_if<SvgShape>(&region.shape)) {
        for (std::size_t i = 0; i < regions.size(); ++i)
            regions[i].contours = partContours(*svg, svg->shapes[i], maxSpacing);
    } else {
        regions.front().contours = shapeContours(region.shape, maxSpacing);
    }
    return regions;
}

sim::Comb CombStroke::map() const
{
    return {from, to, tines, spacing, sharpness, amplitude, wavelength, phase * std::numbers::pi / 180.0};
}

StylusStroke CombStroke::tineStroke(int k) const
{
    const sim::Comb comb = map();
    const sim::Vec2 start = comb.tineStart(k), stroke = to - from;
    const double length = glm::length(stroke);
    const int pieces = amplitude > 0.0 && length > 0.0
                           ? std::clamp(int(std::ceil(16.0 * length / wavelength)), 1, pathPoints - 1)
                           : 1;
    const sim::Vec2 across = length > 0.0 ? sim::Vec2(-stroke.y, stroke.x) / length : sim::Vec2(0.0);
    StylusStroke path{radius, {}, {}};
    for (int i = 0; i <= pieces; ++i) {
        const double s = double(i) / pieces, t = (s - 0.5) * length;
        path.points.push_back(start + s * stroke +
                              amplitude * std::sin(2.0 * std::numbers::pi * t / wavelength + comb.phase) * across);
        path.times.push_back(time + s * duration);
    }
    return path;
}

sim::CircularComb CircularCombStroke::map() const
{
    return {center, innerRadius, tines, spacing, sharpness, angle * std::numbers::pi / 180.0};
}

namespace {

// A stylus of radius `width` along the circle of radius `ring` about `center`, from angle `from`
// through `turn` radians more (counter-clockwise) between `time` and `time + duration`.
StylusStroke arcStroke(sim::Vec2 center, double ring, double from, double turn, double width, double time,
                       double duration)
{
    const int pieces = std::clamp(int(std::ceil(64.0 * std::abs(turn) / (2.0 * std::numbers::pi))), 1, pathPoints - 1);
    StylusStroke path{width, {}, {}};
    for (int i = 0; i <= pieces; ++i) {
        const double s = double(i) / pieces;
        path.points.push_back(center + ring * sim::Vec2(std::cos(from + s * turn), std::sin(from + s * turn)));
        path.times.push_back(time + s * duration);
    }
    return path;
}

} // namespace

StylusStroke CircularCombStroke::tineStroke(int k) const
{
    return arcStroke(center, innerRadius + k * spacing, 0.0, angle * std::numbers::pi / 180.0, radius, time, duration);
}

sim::Swirl SwirlStroke::map() const
{
    return {center, radius, angle * std::numbers::pi / 180.0};
}

std::vector<StylusStroke> SwirlStroke::ringStrokes(int k) const
{
    const double width = radius / rings, ring = (k + 0.5) * width;
    const double turn = map().angleAt(ring);
    const int count = int(std::ceil(2.0 * std::numbers::pi * (k + 0.5)));  // one a width around the ring
    std::vector<StylusStroke> strokes;
    for (int j = 0; j < count; ++j)
        strokes.push_back(arcStroke(center, ring, 2.0 * std::numbers::pi * j / count, turn, width, time, duration));
    return strokes;
}

std::vector<DropStroke> SpatterStroke::drops() const
{
    SplitMix64 random(seed);
    std::vector<DropStroke> out;
    for (int i = 0; i < count; ++i) {
        const double distance = spread * std::sqrt(random.unit()), turn = 2.0 * std::numbers::pi * random.unit();
        const double radius = smallest + (largest - smallest) * random.unit();
        const auto pick = std::min(std::size_t(random.unit() * double(colors.size())), colors.size() - 1);
        out.push_back({time + i * interval, center + distance * sim::Vec2(std::cos(turn), std::sin(turn)), radius,
                       colors[pick], QString()});
    }
    return out;
}

std::vector<sim::Polygon> targetContours(const std::variant<Shape, TextTarget>& target, double spacing)
{
    if (const auto* shape = std::get_if<Shape>(&target))
        return shapeContours(*shape, spacing);
    if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        return {};
    const TextTarget& text = std::get<TextTarget>(target);
    QFont font(text.font);
    font.setBold(text.bold);
    return textContours(text.text, font, text.baseline, text.size, spacing);
}

} // namespace vf::model
