#include "sim/AreaCorrection.h"

#include <cmath>

namespace vf::sim {

void correctArea(Polygon& polygon, double targetArea)
{
    const std::size_t n = polygon.size();
    if (n < 3)
        return;
    Polygon gradient(n);
    double gradientNorm2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 d = polygon[(i + 1) % n] - polygon[(i + n - 1) % n];
        gradient[i] = 0.5 * Vec2(d.y, -d.x);  // ∂A/∂v_i for the shoelace area
        gradientNorm2 += gradient[i].x * gradient[i].x + gradient[i].y * gradient[i].y;
    }
    if (gradientNorm2 <= 0.0)
        return;
    // a·λ² + b·λ + c = 0; the root nearest zero is the smallest move.
    const double a = signedArea(gradient);
    const double b = gradientNorm2;
    const double c = signedArea(polygon) - targetArea;
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0)
        return;
    // The numerically stable form of the smaller root.
    const double lambda = -2.0 * c / (b + std::sqrt(disc));
    for (std::size_t i = 0; i < n; ++i)
        polygon[i] += lambda * gradient[i];
}

} // namespace vf::sim
