#include "sim/Comb.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

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

Vec2 Comb::waved(Vec2 p, double sign) const
{
    if (amplitude == 0.0)
        return p;
    const Vec2 along = glm::normalize(to - from);
    const double t = glm::dot(p - 0.5 * (from + to), along);
    return p + sign * amplitude * std::sin(2.0 * std::numbers::pi * t / wavelength + phase) * quarterTurn(along);
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
    const double wa = glm::dot(waved(a, -1.0) - tineStart(0), across) / unit;
    const double wb = glm::dot(waved(b, -1.0) - tineStart(0), across) / unit;
    return wholeCrossing(wa, wb, last);
}

Vec2 Comb::operator()(Vec2 p) const
{
    const Vec2 stroke = to - from;
    const double length = glm::length(stroke);
    if (!(length > 0.0))
        return p;
    const Vec2 along = stroke / length, across = quarterTurn(along);
    const Vec2 straight = waved(p, -1.0);
    double shift = 0.0;
    for (int k = 0; k < tines; ++k) {
        const double d = std::abs(glm::dot(straight - tineStart(k), across));
        shift += length * sharpness / (d + sharpness);
    }
    return waved(straight + shift * along, 1.0);
}

double Comb::mostPull() const
{
    if (!(sharpness > 0.0))
        return 1.0;  // a map that moves nothing but the tines' own lines
    double most = 0.0;
    for (int k = 0; k < tines; ++k) {
        double pull = 0.0;
        for (int j = 0; j < tines; ++j)
            pull += sharpness / (std::abs(j - k) * spacing + sharpness);
        most = std::max(most, pull);
    }
    return most;
}

} // namespace vf::sim
