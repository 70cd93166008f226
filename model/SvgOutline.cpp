#include "model/SvgOutline.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vf::model::svg {
namespace {

// Even a curve far smaller than the spacing keeps a recognisable outline: a full ellipse gets at
// least 8 vertices (as sim::circle), a cubic at least 4 pieces.
constexpr double kMinArcPiecesPerRadian = 4.0 / std::numbers::pi;
constexpr double kMinCubicPieces = 4.0;
// Parameter steps per output vertex when measuring a curve's length; see appendCurve.
constexpr double kFineStepsPerVertex = 8.0;

Vec2 mapPoint(const QTransform& m, Vec2 p) { return {m.m11() * p.x + m.m21() * p.y + m.dx(), m.m12() * p.x + m.m22() * p.y + m.dy()}; }
Vec2 mapVector(const QTransform& m, Vec2 v) { return {m.m11() * v.x + m.m21() * v.y, m.m12() * v.x + m.m22() * v.y}; }

Vec2 cubicAt(Vec2 p0, const Segment& s, double t)
{
    const double r = 1.0 - t;
    return r * r * r * p0 + 3.0 * r * r * t * s.control1 + 3.0 * r * t * t * s.control2 + t * t * t * s.end;
}

Vec2 arcAt(const Arc& a, double t)
{
    const double theta = a.theta0 + t * a.sweep;
    return a.center + a.u * std::cos(theta) + a.v * std::sin(theta);
}

Vec2 segmentEnd(const Segment& s) { return s.kind == Segment::Kind::Arc ? arcAt(s.arc, 1.0) : s.end; }

// Bounds on a segment's length (the control polygon for a cubic; |θ'|·sqrt(|u|²+|v|²) bounds an
// arc's speed) and the fewest pieces its shape deserves.
double lengthBound(Vec2 p0, const Segment& s)
{
    switch (s.kind) {
    case Segment::Kind::Line: return glm::distance(p0, s.end);
    case Segment::Kind::Cubic: return glm::distance(p0, s.control1) + glm::distance(s.control1, s.control2) + glm::distance(s.control2, s.end);
    case Segment::Kind::Arc: return std::abs(s.arc.sweep) * std::sqrt(glm::dot(s.arc.u, s.arc.u) + glm::dot(s.arc.v, s.arc.v));
    }
    return 0.0;
}

double minPieces(const Segment& s)
{
    switch (s.kind) {
    case Segment::Kind::Line: return 1.0;
    case Segment::Kind::Cubic: return kMinCubicPieces;
    case Segment::Kind::Arc: return std::max(1.0, std::ceil(std::abs(s.arc.sweep) * kMinArcPiecesPerRadian));
    }
    return 1.0;
}

// Appends the curve's points after its start at equal arc length, each evaluated on the curve.
// Arc length is measured by chords over parameter steps several times finer than the output, as
// model/Scene.cpp does for ellipses: uniform parameter steps would crowd where the curve is slow.
template <typename Curve>
void appendCurve(const Curve& at, double bound, double pieces, double spacing, sim::Polygon& out)
{
    const auto fine = static_cast<std::size_t>(kFineStepsPerVertex * (std::ceil(bound / spacing) + pieces));
    std::vector<double> walked(fine + 1, 0.0);
    Vec2 previous = at(0.0);
    for (std::size_t j = 1; j <= fine; ++j) {
        const Vec2 p = at(static_cast<double>(j) / static_cast<double>(fine));
        walked[j] = walked[j - 1] + glm::distance(previous, p);
        previous = p;
    }
    const double total = walked[fine];
    const auto count = static_cast<std::size_t>(std::max(pieces, std::ceil(total / spacing)));
    std::size_t j = 1;
    for (std::size_t k = 1; k < count; ++k) {
        const double target = total * static_cast<double>(k) / static_cast<double>(count);
        while (j < fine && walked[j] < target)
            ++j;
        const double chord = walked[j] - walked[j - 1];
        const double f = chord > 0.0 ? (target - walked[j - 1]) / chord : 0.0;
        out.push_back(at((static_cast<double>(j - 1) + f) / static_cast<double>(fine)));
    }
    out.push_back(at(1.0));
}

} // namespace

void transform(Outline& outline, const QTransform& matrix)
{
    for (Subpath& subpath : outline) {
        subpath.start = mapPoint(matrix, subpath.start);
        for (Segment& s : subpath.segments) {
            s.control1 = mapPoint(matrix, s.control1);
            s.control2 = mapPoint(matrix, s.control2);
            s.end = mapPoint(matrix, s.end);
            s.arc.center = mapPoint(matrix, s.arc.center);
            s.arc.u = mapVector(matrix, s.arc.u);
            s.arc.v = mapVector(matrix, s.arc.v);
        }
    }
}

double vertexBound(const Outline& outline, double spacing)
{
    double bound = 0.0;
    for (const Subpath& subpath : outline) {
        Vec2 p = subpath.start;
        for (const Segment& s : subpath.segments) {
            bound += lengthBound(p, s) / spacing + minPieces(s) + 1.0;
            p = segmentEnd(s);
        }
        bound += glm::distance(p, subpath.start) / spacing + 1.0;  // the closing edge
    }
    return bound;
}

std::vector<sim::Polygon> flatten(const Outline& outline, double spacing)
{
    std::vector<sim::Polygon> polygons;
    for (const Subpath& subpath : outline) {
        sim::Polygon polygon{subpath.start};
        for (const Segment& s : subpath.segments) {
            const Vec2 p0 = polygon.back();
            switch (s.kind) {
            case Segment::Kind::Line:
                polygon.push_back(s.end);
                break;
            case Segment::Kind::Cubic:
                appendCurve([&](double t) { return cubicAt(p0, s, t); }, lengthBound(p0, s), minPieces(s), spacing, polygon);
                break;
            case Segment::Kind::Arc:
                appendCurve([&](double t) { return arcAt(s.arc, t); }, lengthBound(p0, s), minPieces(s), spacing, polygon);
                break;
            }
        }
        polygons.push_back(std::move(polygon));
    }
    return polygons;
}

} // namespace vf::model::svg
