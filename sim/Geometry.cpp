#include "sim/Geometry.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vf::sim {

double signedArea(const Polygon& polygon)
{
    double twiceArea = 0.0;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % n];
        twiceArea += a.x * b.y - b.x * a.y;
    }
    return 0.5 * twiceArea;
}

double perimeter(const Polygon& polygon)
{
    double length = 0.0;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i)
        length += glm::distance(polygon[i], polygon[(i + 1) % n]);
    return length;
}

int windingNumber(const Polygon& polygon, Vec2 p)
{
    // Sunday's crossing rule: count upward crossings left of p, minus downward ones.
    int winding = 0;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 a = polygon[i], b = polygon[(i + 1) % n];
        const double side = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
        if (a.y <= p.y && b.y > p.y && side > 0)
            ++winding;
        else if (a.y > p.y && b.y <= p.y && side < 0)
            --winding;
    }
    return winding;
}

bool visitEnclosures(const std::vector<Polygon>& contours, std::size_t budget,
                     const std::function<void(std::size_t inner, std::size_t outer)>& enclosedBy)
{
    struct Box {
        Vec2 low{INFINITY}, high{-INFINITY};
        bool holds(Vec2 p) const { return p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y; }
    };
    std::vector<Box> boxes(contours.size());
    for (std::size_t c = 0; c < contours.size(); ++c)
        for (const Vec2& p : contours[c]) {
            boxes[c].low = glm::min(boxes[c].low, p);
            boxes[c].high = glm::max(boxes[c].high, p);
        }
    std::size_t visited = 0;
    for (std::size_t inner = 0; inner < contours.size(); ++inner) {
        if (contours[inner].empty())
            continue;
        const Vec2 probe = contours[inner].front();
        for (std::size_t outer = 0; outer < contours.size(); ++outer) {
            if (outer == inner || !boxes[outer].holds(probe))
                continue;
            if ((visited += contours[outer].size()) > budget)
                return false;
            if (windingNumber(contours[outer], probe) != 0)
                enclosedBy(inner, outer);
        }
    }
    return true;
}

double filledArea(const std::vector<Polygon>& contours)
{
    std::vector<int> enclosing(contours.size(), 0);
    visitEnclosures(contours, std::numeric_limits<std::size_t>::max(),
                    [&enclosing](std::size_t inner, std::size_t) { ++enclosing[inner]; });
    double area = 0.0;
    for (std::size_t c = 0; c < contours.size(); ++c) {
        const double own = std::abs(signedArea(contours[c]));
        area += enclosing[c] % 2 == 0 ? own : -own;
    }
    return area;
}

Polygon resample(const Polygon& polygon, double maxSpacing)
{
    Polygon out;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 a = polygon[i];
        const Vec2 b = polygon[(i + 1) % n];
        const int pieces = std::max(1, int(std::ceil(glm::distance(a, b) / maxSpacing)));
        for (int k = 0; k < pieces; ++k)
            out.push_back(a + (b - a) * (double(k) / pieces));
    }
    return out;
}

Polygon circle(Vec2 center, double radius, double maxSpacing)
{
    // Chord length 2r·sin(π/n) ≤ maxSpacing.
    const double chordAngle = 2.0 * std::asin(std::min(1.0, maxSpacing / (2.0 * radius)));
    const int n = std::max(8, int(std::ceil(2.0 * std::numbers::pi / chordAngle)));
    Polygon out(n);
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n;
        out[i] = center + radius * Vec2(std::cos(a), std::sin(a));
    }
    return out;
}

double squaredDistanceToSegment(Vec2 p, Vec2 a, Vec2 b)
{
    const Vec2 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    const Vec2 d = p - (a + t * ab);
    return glm::dot(d, d);
}

std::optional<double> wholeCrossing(double wa, double wb, double last)
{
    // From the first whole number above the lower end to the last below the upper one.
    const double first = std::max(std::floor(std::min(wa, wb)) + 1.0, 0.0);
    const double final = std::min(std::ceil(std::max(wa, wb)) - 1.0, last);
    if (!(first <= final))
        return std::nullopt;
    return (std::clamp(std::round(0.5 * (wa + wb)), first, final) - wa) / (wb - wa);
}

Vec2 storedPosition(Vec2 p, bool singlePrecision)
{
    if (!singlePrecision)
        return p;
    // Through volatile floats: GCC 12.2 at -O2 (Debian 12's) vectorizes the two conversions of a
    // pair and then drops them, as if double(float(x)) were x.
    const volatile float x = float(p.x), y = float(p.y);
    return {x, y};
}

double directedHausdorffDistance(const Polygon& from, const Polygon& to)
{
    double worst = 0.0;
    for (const Vec2& p : from) {
        double best = INFINITY;
        for (std::size_t i = 0; i < to.size(); ++i)
            best = std::min(best, std::sqrt(squaredDistanceToSegment(p, to[i], to[(i + 1) % to.size()])));
        worst = std::max(worst, best);
    }
    return worst;
}

double hausdorffDistance(const Polygon& a, const Polygon& b)
{
    return std::max(directedHausdorffDistance(a, b), directedHausdorffDistance(b, a));
}

} // namespace vf::sim
