#include "model/StartingContour.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace vf::model {
namespace {

// Distances below this fraction of the spacing are rounding, not shape.
constexpr double kNegligibleFraction = 1e-9;

double cross(sim::Vec2 a, sim::Vec2 b) { return a.x * b.y - a.y * b.x; }

// All vertices within tolerance of the line through the first vertex and the one farthest from it.
bool onOneLine(const sim::Polygon& polygon, double tolerance)
{
    const sim::Vec2 origin = polygon.front();
    const auto farthest = std::max_element(polygon.begin(), polygon.end(), [&](sim::Vec2 a, sim::Vec2 b) {
        return glm::distance(origin, a) < glm::distance(origin, b);
    });
    const sim::Vec2 direction = glm::normalize(*farthest - origin);
    return std::all_of(polygon.begin(), polygon.end(), [&](sim::Vec2 p) { return std::abs(cross(direction, p - origin)) <= tolerance; });
}

} // namespace

std::optional<sim::Polygon> startingContour(const sim::Polygon& closedPolyline, double spacing)
{
    const double tolerance = kNegligibleFraction * spacing;
    sim::Polygon polygon;
    polygon.reserve(closedPolyline.size());
    for (const sim::Vec2& p : closedPolyline) {
        if (polygon.empty() || glm::distance(polygon.back(), p) > tolerance)
            polygon.push_back(p);
    }
    while (polygon.size() > 1 && glm::distance(polygon.back(), polygon.front()) <= tolerance)
        polygon.pop_back();
    if (polygon.size() < 3 || onOneLine(polygon, tolerance))
        return std::nullopt;
    if (sim::signedArea(polygon) < 0.0)
        std::reverse(polygon.begin(), polygon.end());
    return sim::resample(polygon, spacing);
}

} // namespace vf::model
