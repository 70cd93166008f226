#include "sim/AreaCorrection.h"

#include <algorithm>
#include <cmath>

namespace vf::sim {

namespace {

// Whether the contour turns by more than a right angle at vertex i.
bool turnsSharply(const Polygon& polygon, std::size_t i)
{
    const std::size_t n = polygon.size();
    const Vec2 in = polygon[i] - polygon[(i + n - 1) % n], out = polygon[(i + 1) % n] - polygon[i];
    return in.x * out.x + in.y * out.y < 0.0;
}

} // namespace

void correctArea(Polygon& polygon, double targetArea, double shortEdge, const std::vector<bool>& held, double maxOffset)
{
    const std::size_t n = polygon.size();
    if (n < 3)
        return;
    std::vector<bool> sharp(n);
    for (std::size_t i = 0; i < n; ++i)
        sharp[i] = turnsSharply(polygon, i);
    Polygon direction(n);
    double rate = 0.0;  // Σ g_i·u_i: the area's rate of change under the offset
    for (std::size_t i = 0; i < n; ++i) {
        if (held[i] || sharp[(i + n - 1) % n] || sharp[i] || sharp[(i + 1) % n]) {
            direction[i] = Vec2(0.0);
            continue;
        }
        const Vec2 d = polygon[(i + 1) % n] - polygon[(i + n - 1) % n];
        const Vec2 gradient = 0.5 * Vec2(d.y, -d.x);  // ∂A/∂v_i for the shoelace area
        const double length = std::sqrt(gradient.x * gradient.x + gradient.y * gradient.y);
        direction[i] = gradient / std::max(length, shortEdge);
        rate += length * length / std::max(length, shortEdge);
    }
    if (rate <= 0.0)
        return;
    // a·λ² + b·λ + c = 0; the root nearest zero is the smallest move.
    const double a = signedArea(direction);
    const double b = rate;
    const double c = signedArea(polygon) - targetArea;
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0)
        return;
    // The numerically stable form of the smaller root.
    const double lambda = std::clamp(-2.0 * c / (b + std::sqrt(disc)), -maxOffset, maxOffset);
    for (std::size_t i = 0; i < n; ++i)
        polygon[i] += lambda * direction[i];
}

} // namespace vf::sim
