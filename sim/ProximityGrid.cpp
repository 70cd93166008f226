#include "sim/ProximityGrid.h"

#include "sim/TightGrowth.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vf::sim {

namespace {
constexpr int maxCellsPerAxis = 4096;  // a wider spread only makes cells larger, never wrong
}


int ProximityGrid::cellOf(Vec2 p, int& column, int& row) const
{
    column = std::clamp(int((p.x - m_origin.x) / m_cell), 0, m_columns - 1);
    row = std::clamp(int((p.y - m_origin.y) / m_cell), 0, m_rows - 1);
    return row * m_columns + column;
}

void ProximityGrid::build(const std::vector<Contour>& contours, double radius, double cell)
{
    Vec2 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    std::size_t total = 0;
    for (const Contour& c : contours) {
        for (const Vec2& p : c.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        total += c.positions.size();
    }
    if (total == 0)
        lo = hi = Vec2(0.0);
    const Vec2 extent = hi - lo;
    m_radius = radius;
    // No more cells than about twice the vertices: fine cells over a wide spread of few vertices
    // would cost memory for nothing.
    const double sparse = std::sqrt(std::max(extent.x, cell) * std::max(extent.y, cell) / (2.0 * double(std::max<std::size_t>(total, 1))));
    m_cell = std::max({cell, sparse, extent.x / maxCellsPerAxis, extent.y / maxCellsPerAxis, 1e-300});
    m_origin = lo;
    m_columns = int(extent.x / m_cell) + 1;
    m_rows = int(extent.y / m_cell) + 1;

    // Counting sort: count per cell, exclusive prefix sum, scatter.
    m_cellStart.assign(std::size_t(m_columns) * m_rows + 1, 0);
    int column = 0, row = 0;
    for (const Contour& c : contours)
        for (const Vec2& p : c.positions)
            ++m_cellStart[cellOf(p, column, row) + 1];
    for (std::size_t cell = 1; cell < m_cellStart.size(); ++cell)
        m_cellStart[cell] += m_cellStart[cell - 1];

    m_fill.assign(m_cellStart.begin(), m_cellStart.end() - 1);
    resizeDiscarding(m_entries, total);
    m_slot.resize(contours.size());
    m_contourLength.resize(contours.size());
    for (std::uint32_t ci = 0; ci < contours.size(); ++ci) {
        const auto& positions = contours[ci].positions;
        resizeDiscarding(m_slot[ci], positions.size());
        double arc = 0.0;
        for (std::size_t i = 0; i < positions.size(); ++i) {
            // The cell again rather than kept from the count: 4 bytes a vertex less.
            const std::uint32_t slot = m_fill[cellOf(positions[i], column, row)]++;
            m_entries[slot] = {positions[i], float(arc), ci};
            m_slot[ci][i] = slot;
            arc += glm::distance(positions[i], positions[(i + 1) % positions.size()]);
        }
        m_contourLength[ci] = arc;
    }
}

double ProximityGrid::nearestOtherPart(std::size_t contour, std::size_t index) const
{
    const Entry& self = m_entries[m_slot[contour][index]];
    const double length = m_contourLength[contour];
    double best2 = m_radius * m_radius;
    bool found = false;
    // The entries of cells [firstColumn, lastColumn] of row r, one span of the sorted entries.
    const auto searchSpan = [&](int r, int firstColumn, int lastColumn) {
        if (r < 0 || r >= m_rows)
            return;
        firstColumn = std::max(0, firstColumn);
        lastColumn = std::min(m_columns - 1, lastColumn);
        if (firstColumn > lastColumn)
            return;
        const std::size_t rowStart = std::size_t(r) * m_columns;
        for (std::uint32_t e = m_cellStart[rowStart + firstColumn]; e < m_cellStart[rowStart + lastColumn + 1]; ++e) {
            const Entry& other = m_entries[e];
            const Vec2 d = other.position - self.position;
            const double dist2 = glm::dot(d, d);
            if (dist2 >= best2)
                continue;
            if (other.contour == self.contour) {
                const double along = std::abs(other.arc - self.arc);
                const double arc = std::min(along, length - along);
                if (arc * arc <= 4.0 * dist2)
                    continue;  // its own neighbourhood along the contour
            }
            best2 = dist2;
            found = true;
        }
    };
    int column = 0, row = 0;
    cellOf(self.position, column, row);
    // Ring k: the cells k away (Chebyshev). Once rings 0…k are searched, every vertex nearer than
    // k cells plus the vertex's distance to the edge of its own cell has been seen, so the search
    // stops as soon as the nearest found is that near. Dense ink finds it in its own cell, where
    // cells as wide as the radius would hold hundreds of candidates.
    const Vec2 inCell = self.position - m_origin - Vec2(column, row) * m_cell;
    const double edge = std::max(0.0, std::min({inCell.x, inCell.y, m_cell - inCell.x, m_cell - inCell.y}));
    const int rings = int(std::ceil(m_radius / m_cell));
    searchSpan(row, column, column);
    for (int k = 1; k <= rings && best2 > (edge + (k - 1) * m_cell) * (edge + (k - 1) * m_cell); ++k) {
        searchSpan(row - k, column - k, column + k);
        searchSpan(row + k, column - k, column + k);
        for (int r = row - k + 1; r <= row + k - 1; ++r) {
            searchSpan(r, column - k, column - k);
            searchSpan(r, column + k, column + k);
        }
    }
    return found ? std::sqrt(best2) : std::numeric_limits<double>::infinity();
}

} // namespace vf::sim
