#include "sim/Whirl.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace vf::sim {

namespace {

Vec2 turned(Vec2 p, Vec2 centre, double angle)
{
    const double c = std::cos(angle), s = std::sin(angle);
    const Vec2 d = p - centre;
    return centre + Vec2(c * d.x - s * d.y, s * d.x + c * d.y);
}

} // namespace

Vec2 CircularComb::operator()(Vec2 p) const
{
    const double rho = glm::distance(p, centre);
    double theta = 0.0;
    for (int k = 0; k < tines; ++k)
        theta += angle * sharpness / (std::abs(rho - (radius + k * spacing)) + sharpness);
    return turned(p, centre, theta);
}

std::optional<double> CircularComb::tineCrossing(Vec2 a, Vec2 b) const
{
    // ρ in tine spacings from tine 0, so that tine k lies at k.
    const double unit = spacing > 0.0 ? spacing : 1.0, last = spacing > 0.0 ? double(tines - 1) : 0.0;
    const double wa = (glm::distance(a, centre) - radius) / unit, wb = (glm::distance(b, centre) - radius) / unit;
    return wholeCrossing(wa, wb, last);
}

double Swirl::angleAt(double rho) const
{
    const double r = rho / radius;
    return angle * std::exp(-r * r);
}

Vec2 Swirl::operator()(Vec2 p) const
{
    return turned(p, centre, angleAt(glm::distance(p, centre)));
}

} // namespace vf::sim
