#pragma once
// Every edge of a set of contours in a uniform grid, for the searches of sim/Pinches and
// sim/Separation: which edges lie near a point or a segment. Counting sort, as ProximityGrid.
#include "sim/Geometry.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace vf::sim {

// The vertex after i on a ring of n (no division: this runs for every vertex and edge).
inline std::size_t after(std::size_t i, std::size_t n)
{
    return i + 1 == n ? 0 : i + 1;
}

// Every edge of every contour (or, given a window, every one whose widened box meets it) in the
// cells its box, widened by its contour's pinch width, overlaps: the edges of a contour within that
// width of a point are among those of the point's cell. Counting sort, as ProximityGrid.
class EdgeGrid {
public:
    struct Edge {
        std::uint32_t contour, from;  // from vertex `from` to the next
    };
    // The grid's per-cell arrays, kept by a caller that builds grids again and again (the pinch
    // check): a million cells allocated afresh take their pages from the system each time, and
    // faulting them in cost five times the search (48k vertices: 19 ms a check against 3 ms). At
    // most 8 MB; the entries, which grow with the ink, are the grid's own.
    struct Storage {
        std::vector<std::uint32_t> start, fill;
    };

    EdgeGrid(const std::vector<Outline>& contours, const std::vector<double>& widths, Storage& storage,
             std::optional<Window> window = std::nullopt)
        : m_widths(widths), m_window(window), m_start(storage.start)
    {
        m_start.clear();
        Vec2 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
        double edgeLength = 0.0;
        std::size_t edges = 0;
        forEveryEdge(contours, [&](Edge, Vec2 a, Vec2 b) {
            low = glm::min(low, glm::min(a, b));
            high = glm::max(high, glm::max(a, b));
            edgeLength += glm::distance(a, b);
            ++edges;
        });
        if (edges == 0)
            return;
        // Cells about twice the mean edge long, at most 1024 across the extent.
        const Vec2 extent = high - low;
        const double widest = *std::max_element(widths.begin(), widths.end());
        m_cell = std::max({2.0 * edgeLength / double(edges), std::max(extent.x, extent.y) / 1024.0,
                           std::numeric_limits<double>::min()});
        m_origin = low - Vec2(widest);
        m_columns = int(extent.x / m_cell) + 2;
        m_rows = int(extent.y / m_cell) + 2;
        m_start.assign(std::size_t(m_columns) * std::size_t(m_rows) + 1, 0);
        forEveryEdgeCell(contours, [this](std::size_t cell, Edge) { ++m_start[cell + 1]; });
        for (std::size_t k = 1; k < m_start.size(); ++k)
            m_start[k] += m_start[k - 1];
        m_entries.resize(m_start.back());
        std::vector<std::uint32_t>& fill = storage.fill;
        fill.assign(m_start.begin(), m_start.end() - 1);
        forEveryEdgeCell(contours, [&](std::size_t cell, Edge e) { m_entries[fill[cell]++] = e; });
    }

    // f(edge) for every edge whose widened box overlaps the box of a and b.
    template <class F>
    void forEdgesNear(Vec2 a, Vec2 b, F f) const
    {
        if (m_entries.empty())
            return;
        const auto [c0, r0] = cellOf(glm::min(a, b));
        const auto [c1, r1] = cellOf(glm::max(a, b));
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) {
                const std::size_t cell = std::size_t(r) * std::size_t(m_columns) + std::size_t(c);
                for (std::uint32_t k = m_start[cell]; k < m_start[cell + 1]; ++k)
                    f(m_entries[k]);
            }
    }

private:
    std::pair<int, int> cellOf(Vec2 p) const
    {
        const Vec2 q = (p - m_origin) / m_cell;
        return {std::clamp(int(q.x), 0, m_columns - 1), std::clamp(int(q.y), 0, m_rows - 1)};
    }

    // f(edge, a, b) for every edge a–b the grid holds.
    template <class F>
    void forEveryEdge(const std::vector<Outline>& contours, F f) const
    {
        for (std::size_t k = 0; k < contours.size(); ++k) {
            const Outline& p = contours[k];
            for (std::size_t i = 0; i < p.size(); ++i) {
                const Vec2 a = p[i], b = p[after(i, p.size())];
                if (!m_window || m_window->meets(a, b, m_widths[k]))
                    f(Edge{std::uint32_t(k), std::uint32_t(i)}, a, b);
            }
        }
    }

    template <class F>
    void forEveryEdgeCell(const std::vector<Outline>& contours, F f) const
    {
        forEveryEdge(contours, [&](Edge e, Vec2 a, Vec2 b) {
            const double width = m_widths[e.contour];
            const auto [c0, r0] = cellOf(glm::min(a, b) - Vec2(width));
            const auto [c1, r1] = cellOf(glm::max(a, b) + Vec2(width));
            for (int r = r0; r <= r1; ++r)
                for (int c = c0; c <= c1; ++c)
                    f(std::size_t(r) * std::size_t(m_columns) + std::size_t(c), e);
        });
    }

    const std::vector<double>& m_widths;
    std::optional<Window> m_window;
    double m_cell = 1.0;
    Vec2 m_origin{0.0};
    int m_columns = 0, m_rows = 0;
    std::vector<std::uint32_t>& m_start;
    std::vector<Edge> m_entries;
};

} // namespace vf::sim
