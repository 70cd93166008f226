#include "sim/Comb.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace vf::sim {

namespace {

Vec2 quarterTurn(Vec2 v)
{
    return {-v.y, v.x};
}

} // namespace

Vec2 Comb::tineStart(int k) const
{
    const Vec2 stroke = to - from;
    const double length = glm::length(stroke);
    const Vec2 across = length > 0.0 ? quarterTurn(stroke / length) : Vec2(0.0);
    return from + (double(k) - 0.5 * double(tines - 1)) * spacing * across;
}

std::optional<double> Comb::tineCrossing(Vec2 a, Vec2 b) const
{
    const Vec2 stroke = to - from;
    const double length = glm::length(stroke);
    if (!(length > 0.0))
        return std::nullopt;
    // Across the stroke in tine spacings from tine 0, so that tine k lies at k.
    const Vec2 across = quarterTurn(stroke / length);
    const double unit = spacing > 0.0 ? spacing : 1.0, last = spacing > 0.0 ? double(tines - 1) : 0.0;
    const double wa = glm::dot(a - tineStart(0), across) / unit, wb = glm::dot(b - tineStart(0), across) / unit;
    // The tines strictly between a and b: from the first whole number above the lower end to the
    // last below the upper one.
    const double first = std::max(std::floor(std::min(wa, wb)) + 1.0, 0.0);
    const double final = std::min(std::ceil(std::max(wa, wb)) - 1.0, last);
    if (!(first <= final))
        return std::nullopt;
    const double tine = std::clamp(std::round(0.5 * (wa + wb)), first, final);
    return (tine - wa) / (wb - wa);
}

Vec2 Comb::operator()(Vec2 p) const
{
    const Vec2 stroke = to - from;
    const double length = glm::length(stroke);
    if (!(length > 0.0))
        return p;
    const Vec2 along = stroke / length, across = quarterTurn(along);
    double shift = 0.0;
    for (int k = 0; k < tines; ++k) {
        const double d = std::abs(glm::dot(p - tineStart(k), across));
        shift += length * sharpness / (d + sharpness);
    }
    return p + shift * along;
}

} // namespace vf::sim
