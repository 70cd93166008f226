#pragma once
// Uniform-grid neighbour search for the proximity term (eq. 7): for each vertex, the distance to
// the nearest vertex of *another part* of any contour. Built by counting sort over cells, the same
// layout the OpenCL port uses ([Grand 2007], cited by the paper §3.4).
#include "sim/Tracking.h"

#include <cstdint>
#include <vector>

namespace vf::sim {

class ProximityGrid {
public:
    // Indexes every vertex of `contours` in cells of `cell` (or larger, for a spread beyond 4096
    // cells); `radius` is the search radius.
    void build(const std::vector<Contour>& contours, double radius, double cell);

    // Distance from vertex `index` of contour `contour` to the nearest vertex of another part of
    // any contour, or +infinity when none lies within the radius. A vertex of the same contour is
    // another part when the way along the contour is more than twice the straight distance: the
    // far side of a thin filament counts, the vertex's own neighbourhood does not.
    double nearestOtherPart(std::size_t contour, std::size_t index) const;

private:
    struct Entry {
        Vec2 position;
        float arc;  // arc length from the contour's first vertex (as the device keeps it: only "more
                    // than twice the straight distance" is asked of it)
        std::uint32_t contour;
    };
    int cellOf(Vec2 p, int& column, int& row) const;

    double m_radius = 0.0;  // the search radius
    double m_cell = 0.0;    // the cell size
    Vec2 m_origin{0.0};
    int m_columns = 0, m_rows = 0;
    std::vector<std::uint32_t> m_cellStart;         // m_columns * m_rows + 1 offsets into m_entries
    std::vector<Entry> m_entries;                   // sorted by cell
    std::vector<std::vector<std::uint32_t>> m_slot; // [contour][vertex] -> index into m_entries
    std::vector<double> m_contourLength;
    std::vector<std::uint32_t> m_fill;  // build scratch, kept to avoid reallocation
};

} // namespace vf::sim
