#include "sim/Crossings.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>

namespace vf::sim {

namespace {

// Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates"
// (1997): a sum of doubles kept exactly as a nonoverlapping expansion, smallest component first.
template <std::size_t Capacity>
class ExactSum {
public:
    void add(double x)
    {
        // Grow-Expansion: two-sum x through every component.
        std::size_t kept = 0;
        for (std::size_t i = 0; i < m_size; ++i) {
            const double sum = x + m_part[i];
            const double virtualX = sum - m_part[i];
            const double error = (x - virtualX) + (m_part[i] - (sum - virtualX));
            x = sum;
            if (error != 0.0)
                m_part[kept++] = error;
        }
        m_part[kept++] = x;
        m_size = kept;
    }
    // x·y exactly: the rounded product and its error (fma computes the error exactly).
    void addProduct(double x, double y)
    {
        const double p = x * y;
        add(std::fma(x, y, -p));
        add(p);
    }
    // The sign of the exact sum: that of its largest nonzero component.
    int sign() const
    {
        for (std::size_t i = m_size; i-- > 0;)
            if (m_part[i] != 0.0)
                return m_part[i] > 0.0 ? 1 : -1;
        return 0;
    }

private:
    std::array<double, Capacity> m_part{};
    std::size_t m_size = 0;
};

} // namespace

int orientation(Vec2 a, Vec2 b, Vec2 c)
{
    const double left = (a.x - c.x) * (b.y - c.y), right = (a.y - c.y) * (b.x - c.x);
    const double det = left - right;
    // Shewchuk's ccwerrboundA: past it, rounding cannot have changed the sign.
    const double bound = 3.3306690738754716e-16 * (std::abs(left) + std::abs(right));
    if (det > bound || -det > bound)
        return det > 0.0 ? 1 : -1;
    // On one vertical or horizontal line (the sides of rectangles, H and V in SVG paths): collinear
    // exactly, and common enough that the expansion arithmetic below would dominate.
    if ((a.x == c.x && b.x == c.x) || (a.y == c.y && b.y == c.y))
        return 0;
    // det = ax·by − ay·bx + bx·cy − by·cx + cx·ay − cy·ax, each product exact as two doubles.
    ExactSum<12> sum;
    sum.addProduct(a.x, b.y);
    sum.addProduct(-a.y, b.x);
    sum.addProduct(b.x, c.y);
    sum.addProduct(-b.y, c.x);
    sum.addProduct(c.x, a.y);
    sum.addProduct(-c.y, a.x);
    return sum.sign();
}

bool properlyCross(Vec2 a, Vec2 b, Vec2 c, Vec2 d)
{
    const int d1 = orientation(a, b, c), d2 = orientation(a, b, d);
    if (d1 == 0 || d2 == 0 || d1 == d2)
        return false;
    const int d3 = orientation(c, d, a), d4 = orientation(c, d, b);
    return d3 != 0 && d4 != 0 && d3 != d4;
}

namespace {

struct Segment {
    Vec2 a, b;
    std::uint32_t polygon, index, count;
};

bool boxesOverlap(const Segment& s, const Segment& t)
{
    return std::max(s.a.x, s.b.x) >= std::min(t.a.x, t.b.x) && std::max(t.a.x, t.b.x) >= std::min(s.a.x, s.b.x) &&
           std::max(s.a.y, s.b.y) >= std::min(t.a.y, t.b.y) && std::max(t.a.y, t.b.y) >= std::min(s.a.y, s.b.y);
}

bool areNeighbours(const Segment& s, const Segment& t)
{
    if (s.polygon != t.polygon)
        return false;
    const std::uint32_t d = s.index > t.index ? s.index - t.index : t.index - s.index;
    return d <= 1 || d == s.count - 1;
}

Vec2 crossingPoint(const Segment& s, const Segment& t)
{
    const Vec2 r = s.b - s.a, q = t.b - t.a;
    const double denominator = r.x * q.y - r.y * q.x;
    const Vec2 w = t.a - s.a;
    const double u = denominator != 0.0 ? std::clamp((w.x * q.y - w.y * q.x) / denominator, 0.0, 1.0) : 0.5;
    return s.a + u * r;
}

// Every edge of the polygons, binned in a uniform grid by bounding box (counting sort: cell
// starts, then entries), so that only edges sharing a cell are compared.
class SegmentGrid {
public:
    explicit SegmentGrid(const std::vector<Outline>& polygons)
    {
        Vec2 lo(INFINITY), hi(-INFINITY);
        double totalLength = 0.0;
        for (std::uint32_t p = 0; p < polygons.size(); ++p) {
            const Outline poly = polygons[p];
            const auto n = std::uint32_t(poly.size());
            for (std::uint32_t i = 0; i < n; ++i) {
                const Segment s{poly[i], poly[(i + 1) % n], p, i, n};
                lo = glm::min(lo, glm::min(s.a, s.b));
                hi = glm::max(hi, glm::max(s.a, s.b));
                totalLength += glm::distance(s.a, s.b);
                m_segments.push_back(s);
            }
        }
        if (m_segments.size() < 2)
            return;
        // Square cells about twice the mean edge length, no more of them than about four per edge,
        // and no more than two per edge along either side (polygons far apart make a wide extent
        // of little area). Square: cells capped on one axis only grow long and thin along a long
        // shape, and then each holds thousands of edges of its two sides (found by fuzzing).
        const double n = double(m_segments.size());
        const Vec2 extent = glm::max(hi - lo, Vec2(1e-300));
        double cell = std::max(2.0 * totalLength / n, 1e-300);
        cell = std::max({cell, std::sqrt(extent.x * extent.y / (4.0 * n)), std::max(extent.x, extent.y) / (2.0 * n)});
        m_columns = int(extent.x / cell) + 1;
        m_rows = int(extent.y / cell) + 1;
        m_lo = lo;
        m_cell = Vec2(extent.x / (m_columns - 0.5), extent.y / (m_rows - 0.5));

        m_start.assign(std::size_t(m_columns) * m_rows + 1, 0);
        forEachCell([this](std::uint32_t, std::size_t cell) { ++m_start[cell + 1]; });
        for (std::size_t c = 1; c < m_start.size(); ++c)
            m_start[c] += m_start[c - 1];
        m_entries.resize(m_start.back());
        std::vector<std::uint32_t> fill(m_start.begin(), m_start.end() - 1);
        forEachCell([&](std::uint32_t k, std::size_t cell) { m_entries[fill[cell]++] = k; });
    }

    // Calls meet(s, t) once for every pair of edges whose bounding boxes share a cell, but for
    // neighbours sharing a vertex, until it has returned true `limit` times.
    template <typename Meet>
    void forEachMeeting(Meet meet, std::size_t limit) const
    {
        std::size_t found = 0;
        for (std::size_t cell = 0; cell + 1 < m_start.size() && found < limit; ++cell) {
            const int r = int(cell / std::size_t(m_columns)), c = int(cell % std::size_t(m_columns));
            for (std::uint32_t i = m_start[cell]; i < m_start[cell + 1] && found < limit; ++i) {
                for (std::uint32_t j = i + 1; j < m_start[cell + 1] && found < limit; ++j) {
                    const Segment& s = m_segments[m_entries[i]];
                    const Segment& t = m_segments[m_entries[j]];
                    // Edges whose bounding boxes are apart neither cross nor touch: most pairs of a
                    // cell end here, before any orientation test.
                    if (!boxesOverlap(s, t))
                        continue;
                    // Each pair once: in the first cell both bounding boxes share.
                    if (std::max(row(std::min(s.a.y, s.b.y)), row(std::min(t.a.y, t.b.y))) != r ||
                        std::max(column(std::min(s.a.x, s.b.x)), column(std::min(t.a.x, t.b.x))) != c)
                        continue;
                    if (!areNeighbours(s, t) && meet(s, t))
                        ++found;
                }
            }
        }
    }

private:
    int column(double x) const { return std::clamp(int((x - m_lo.x) / m_cell.x), 0, m_columns - 1); }
    int row(double y) const { return std::clamp(int((y - m_lo.y) / m_cell.y), 0, m_rows - 1); }

    template <typename F>
    void forEachCell(F f) const
    {
        for (std::uint32_t k = 0; k < m_segments.size(); ++k) {
            const Segment& s = m_segments[k];
            const int c0 = column(std::min(s.a.x, s.b.x)), c1 = column(std::max(s.a.x, s.b.x));
            for (int r = row(std::min(s.a.y, s.b.y)); r <= row(std::max(s.a.y, s.b.y)); ++r)
                for (int c = c0; c <= c1; ++c)
                    f(k, std::size_t(r) * m_columns + c);
        }
    }

    std::vector<Segment> m_segments;
    Vec2 m_lo{0.0}, m_cell{1.0};
    int m_columns = 1, m_rows = 1;
    std::vector<std::uint32_t> m_start, m_entries;
};

} // namespace

std::vector<EdgeCrossing> findCrossings(const std::vector<const Polygon*>& polygons, std::size_t limit)
{
    std::vector<Outline> outlines;
    outlines.reserve(polygons.size());
    for (const Polygon* p : polygons)
        outlines.emplace_back(*p);
    return findOutlineCrossings(outlines, limit);
}

std::vector<EdgeCrossing> findOutlineCrossings(const std::vector<Outline>& outlines, std::size_t limit)
{
    std::vector<EdgeCrossing> crossings;
    const auto meet = [&crossings](const Segment& s, const Segment& t) {
        if (!properlyCross(s.a, s.b, t.a, t.b))
            return false;
        const bool sFirst = s.polygon < t.polygon || (s.polygon == t.polygon && s.index < t.index);
        const Segment& a = sFirst ? s : t;
        const Segment& b = sFirst ? t : s;
        crossings.push_back({a.polygon, a.index, b.polygon, b.index, crossingPoint(a, b)});
        return true;
    };
    SegmentGrid(outlines).forEachMeeting(meet, limit);
    std::sort(crossings.begin(), crossings.end(), [](const EdgeCrossing& x, const EdgeCrossing& y) {
        return std::tie(x.polygonA, x.edgeA, x.polygonB, x.edgeB) < std::tie(y.polygonA, y.edgeA, y.polygonB, y.edgeB);
    });
    return crossings;
}

std::size_t countCrossings(const std::vector<const Polygon*>& polygons)
{
    return findCrossings(polygons).size();
}

} // namespace vf::sim
