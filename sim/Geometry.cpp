#include "sim/Geometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
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

namespace {

struct Segment {
    Vec2 a, b;
    std::size_t polygon, index, count;
};

double cross(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool properlyIntersect(const Segment& s, const Segment& t)
{
    const double d1 = cross(s.a, s.b, t.a), d2 = cross(s.a, s.b, t.b);
    const double d3 = cross(t.a, t.b, s.a), d4 = cross(t.a, t.b, s.b);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

bool onSegment(Vec2 p, const Segment& s)
{
    return cross(s.a, s.b, p) == 0.0 && p.x >= std::min(s.a.x, s.b.x) && p.x <= std::max(s.a.x, s.b.x)
           && p.y >= std::min(s.a.y, s.b.y) && p.y <= std::max(s.a.y, s.b.y);
}

bool touch(const Segment& s, const Segment& t)
{
    return onSegment(s.a, t) || onSegment(s.b, t) || onSegment(t.a, s) || onSegment(t.b, s);
}

// Consecutive edges a→b, b→c fold back when c lies on the line through a and b, behind b.
bool foldsBack(const Segment& s, const Segment& t)
{
    return cross(s.a, s.b, t.b) == 0.0 && glm::dot(s.b - s.a, t.b - t.a) < 0.0;
}

bool areNeighbours(const Segment& s, const Segment& t)
{
    if (s.polygon != t.polygon)
        return false;
    const std::size_t d = s.index > t.index ? s.index - t.index : t.index - s.index;
    return d <= 1 || d == s.count - 1;
}

} // namespace

namespace {

// Pairs of edges over all polygons that `meet` (neighbours sharing a vertex are passed to
// `meetNeighbours` instead), found through a uniform segment grid.
template <typename Meet, typename MeetNeighbours>
std::size_t countMeetings(const std::vector<const Polygon*>& polygons, Meet meet, MeetNeighbours meetNeighbours)
{
    std::vector<Segment> segments;
    Vec2 lo(INFINITY), hi(-INFINITY);
    double totalLength = 0.0;
    for (std::size_t p = 0; p < polygons.size(); ++p) {
        const Polygon& poly = *polygons[p];
        for (std::size_t i = 0; i < poly.size(); ++i) {
            Segment s{poly[i], poly[(i + 1) % poly.size()], p, i, poly.size()};
            lo = glm::min(lo, glm::min(s.a, s.b));
            hi = glm::max(hi, glm::max(s.a, s.b));
            totalLength += glm::distance(s.a, s.b);
            segments.push_back(s);
        }
    }
    if (segments.size() < 2)
        return 0;

    // Cells about twice the mean edge length, capped so the grid stays near the segment count.
    const Vec2 extent = glm::max(hi - lo, Vec2(1e-300));
    double cell = std::max(2.0 * totalLength / segments.size(), 1e-300);
    const double minCell = std::sqrt(extent.x * extent.y / double(4 * segments.size()));
    cell = std::max(cell, minCell);
    const int cols = std::max(1, int(std::min(extent.x / cell, 4096.0)) + 1);
    const int rows = std::max(1, int(std::min(extent.y / cell, 4096.0)) + 1);
    const double cellX = extent.x / (cols - 0.5), cellY = extent.y / (rows - 0.5);
    auto column = [&](double x) { return std::clamp(int((x - lo.x) / cellX), 0, cols - 1); };
    auto row = [&](double y) { return std::clamp(int((y - lo.y) / cellY), 0, rows - 1); };

    std::vector<std::vector<std::uint32_t>> cells(std::size_t(cols) * rows);
    for (std::uint32_t k = 0; k < segments.size(); ++k) {
        const Segment& s = segments[k];
        for (int r = row(std::min(s.a.y, s.b.y)); r <= row(std::max(s.a.y, s.b.y)); ++r)
            for (int c = column(std::min(s.a.x, s.b.x)); c <= column(std::max(s.a.x, s.b.x)); ++c)
                cells[std::size_t(r) * cols + c].push_back(k);
    }

    std::size_t crossings = 0;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            const auto& bucket = cells[std::size_t(r) * cols + c];
            for (std::size_t i = 0; i < bucket.size(); ++i) {
                for (std::size_t j = i + 1; j < bucket.size(); ++j) {
                    const Segment& s = segments[bucket[i]];
                    const Segment& t = segments[bucket[j]];
                    // Count each pair once: in the first cell both bounding boxes share.
                    const int firstRow = std::max(row(std::min(s.a.y, s.b.y)), row(std::min(t.a.y, t.b.y)));
                    const int firstCol = std::max(column(std::min(s.a.x, s.b.x)), column(std::min(t.a.x, t.b.x)));
                    if (firstRow != r || firstCol != c)
                        continue;
                    if (areNeighbours(s, t) ? meetNeighbours(s, t) : meet(s, t))
                        ++crossings;
                }
            }
        }
    }
    return crossings;
}

} // namespace

std::size_t countCrossings(const std::vector<const Polygon*>& polygons)
{
    return countMeetings(polygons, properlyIntersect, [](const Segment&, const Segment&) { return false; });
}

bool isSimple(const Polygon& polygon)
{
    const auto meet = [](const Segment& s, const Segment& t) { return properlyIntersect(s, t) || touch(s, t); };
    const auto neighboursMeet = [](const Segment& s, const Segment& t) {
        if (s.count == 3)
            return false;  // a triangle's edges are all neighbours; only a zero area would be wrong
        return s.index + 1 == t.index || (t.index == 0 && s.index + 1 == s.count) ? foldsBack(s, t) : foldsBack(t, s);
    };
    return countMeetings({&polygon}, meet, neighboursMeet) == 0;
}

namespace {

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b)
{
    const Vec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::distance(p, a + t * ab);
}

} // namespace

double directedHausdorffDistance(const Polygon& from, const Polygon& to)
{
    double worst = 0.0;
    for (const Vec2& p : from) {
        double best = INFINITY;
        for (std::size_t i = 0; i < to.size(); ++i)
            best = std::min(best, pointSegmentDistance(p, to[i], to[(i + 1) % to.size()]));
        worst = std::max(worst, best);
    }
    return worst;
}

double hausdorffDistance(const Polygon& a, const Polygon& b)
{
    return std::max(directedHausdorffDistance(a, b), directedHausdorffDistance(b, a));
}

} // namespace vf::sim
