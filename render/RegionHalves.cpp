#include "render/RegionHalves.h"

#include <algorithm>
#include <vector>

namespace vf::render {

namespace {

// A point's coordinate along the cut's normal: x (axis 0) or y (axis 1).
double along(sim::Vec2 point, int axis) { return axis == 0 ? point.x : point.y; }

// The part of `contour` where along(p) <= cut (sign +1) or >= cut (sign -1); points on the cut
// belong to both sides. Returns fewer than 3 points when nothing with area is left.
sim::Polygon clip(const sim::Polygon& contour, int axis, double cut, double sign)
{
    const auto inside = [&](sim::Vec2 p) { return sign * (along(p, axis) - cut) <= 0; };
    const auto crossing = [&](sim::Vec2 a, sim::Vec2 b) {
        const double t = (cut - along(a, axis)) / (along(b, axis) - along(a, axis));
        sim::Vec2 p = a + (b - a) * t;
        (axis == 0 ? p.x : p.y) = cut;  // exactly on the cut, whatever the rounding of t
        return p;
    };
    sim::Polygon out;
    const auto add = [&](sim::Vec2 p) {
        if (out.empty() || out.back() != p)
            out.push_back(p);
    };
    sim::Vec2 previous = contour.back();
    for (const sim::Vec2& current : contour) {
        if (inside(current) != inside(previous))
            add(crossing(previous, current));
        if (inside(current))
            add(current);
        previous = current;
    }
    if (out.size() > 1 && out.front() == out.back())
        out.pop_back();
    return out;
}

} // namespace

std::array<model::DrawnRegion, 2> cutInHalves(const model::DrawnRegion& region)
{
    std::array<std::vector<double>, 2> coordinates;
    for (const sim::Polygon& contour : region.contours)
        for (const sim::Vec2& p : contour)
            for (int axis = 0; axis < 2; ++axis)
                coordinates[axis].push_back(along(p, axis));
    const auto spread = [](const std::vector<double>& values) {
        const auto [low, high] = std::minmax_element(values.begin(), values.end());
        return values.empty() ? 0.0 : *high - *low;
    };
    const int axis = spread(coordinates[0]) >= spread(coordinates[1]) ? 0 : 1;
    std::vector<double>& values = coordinates[axis];
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    const double cut = values.empty() ? 0.0 : *middle;

    std::array<model::DrawnRegion, 2> halves;
    for (std::size_t side = 0; side < 2; ++side) {
        halves[side] = {region.name, region.color, region.visible, {}};
        for (const sim::Polygon& contour : region.contours) {
            sim::Polygon part = clip(contour, axis, cut, side == 0 ? 1.0 : -1.0);
            if (part.size() >= 3)
                halves[side].contours.push_back(std::move(part));
        }
    }
    return halves;
}

} // namespace vf::render
