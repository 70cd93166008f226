#include "render/SvgRounding.h"

#include "sim/Crossings.h"

#include <algorithm>
#include <cmath>

namespace vf::render {
namespace {

// The decimals the step stands for, as the exact power of ten 10^decimals (exact in a double up to
// 10^22); 0 when the canvas is so small (under 1e-16) that no such power exists.
double scaleFor(double step)
{
    const int decimals = int(std::lround(-std::log10(step)));
    return decimals <= 22 ? std::pow(10.0, decimals) : 0.0;
}

// round(value * 10^d) / 10^d: the division is correctly rounded, so the result is the double
// nearest the decimal and prints in at most d decimals. Values too large for an integral double
// (2^53) are already coarser than the step and stay.
double rounded(double value, double scale)
{
    const double scaled = value * scale;
    return std::abs(scaled) < 0x1p53 ? std::nearbyint(scaled) / scale : value;
}

sim::Polygon roundedContour(const sim::Polygon& contour, double scale)
{
    sim::Polygon out;
    out.reserve(contour.size());
    for (const sim::Vec2& p : contour) {
        const sim::Vec2 q(rounded(p.x, scale), rounded(p.y, scale));
        if (out.empty() || out.back() != q)
            out.push_back(q);
    }
    while (out.size() > 1 && out.back() == out.front())
        out.pop_back();
    return out;
}

} // namespace

double svgCoordinateStep(const model::Drawing& drawing)
{
    return decimalStepBelow(1e-6 * std::max(drawing.width, drawing.height));
}

double decimalStepBelow(double length)
{
    // The slack keeps a length of exactly 10^n from landing one power lower through rounding in log10.
    return std::pow(10.0, std::floor(std::log10(length) + 1e-9));
}

double roundedToStep(double value, double step)
{
    const double scale = scaleFor(step);
    return scale == 0 ? value : rounded(value, scale);
}

RoundedRegion roundedRegion(const model::DrawnRegion& region, double step)
{
    const double scale = scaleFor(step);
    if (scale == 0)
        return {region, false};
    RoundedRegion out{{region.name, region.color, region.visible, {}}, false};
    for (const sim::Polygon& contour : region.contours) {
        sim::Polygon rounded = roundedContour(contour, scale);
        if (rounded.size() >= 3)
            out.region.contours.push_back(std::move(rounded));
    }
    std::vector<const sim::Polygon*> contours;
    for (const sim::Polygon& contour : out.region.contours)
        contours.push_back(&contour);
    // The sweep line (n log n whatever the layout) and stricter than needed: contours that touch
    // after rounding keep their full precision too.
    if (!sim::isSimple(contours))
        return {region, true};
    return out;
}

} // namespace vf::render
