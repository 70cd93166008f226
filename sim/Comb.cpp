#include "sim/Comb.h"

#include <glm/geometric.hpp>

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
