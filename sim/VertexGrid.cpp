#include "sim/VertexGrid.h"

#include "sim/Crossings.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vf::sim {

void VertexGrid::build(const std::vector<Contour>& contours, double cell)
{
    Vec2 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
    std::size_t vertices = 0;
    for (const Contour& c : contours)
        for (const Vec2& p : c.positions) {
            low = glm::min(low, p);
            high = glm::max(high, p);
            ++vertices;
        }
    m_entries.clear();
    if (vertices == 0) {
        m_columns = m_rows = 0;
        return;
    }
    const Vec2 extent = high - low;
    m_cell = std::max({cell, std::sqrt(extent.x * extent.y / double(vertices)), std::max(extent.x, extent.y) / 4096.0,
                       std::numeric_limits<double>::min()});
    m_origin = low;
    m_columns = int(extent.x / m_cell) + 1;
    m_rows = int(extent.y / m_cell) + 1;
    m_head.assign(std::size_t(m_columns) * std::size_t(m_rows), none);
    m_entries.reserve(vertices + vertices / 4);  // room for a step's splits, most of the time
    for (const Contour& c : contours)
        for (const Vec2& p : c.positions)
            insert(p);
}

// Points outside the extent built on (split and recentred vertices may lie there) go to the border
// cells, where a search clamped the same way finds them.
int VertexGrid::column(double x) const
{
    return std::clamp(int(std::floor((x - m_origin.x) / m_cell)), 0, m_columns - 1);
}

int VertexGrid::row(double y) const
{
    return std::clamp(int(std::floor((y - m_origin.y) / m_cell)), 0, m_rows - 1);
}

std::size_t VertexGrid::cellOf(Vec2 p) const
{
    return std::size_t(row(p.y)) * std::size_t(m_columns) + std::size_t(column(p.x));
}

void VertexGrid::insert(Vec2 p)
{
    std::uint32_t& head = m_head[cellOf(p)];
    m_entries.push_back({p, head});
    head = std::uint32_t(m_entries.size() - 1);
}

void VertexGrid::erase(Vec2 p)
{
    for (std::uint32_t* link = &m_head[cellOf(p)]; *link != none; link = &m_entries[*link].next)
        if (const Entry& e = m_entries[*link]; e.position == p) {
            *link = e.next;
            return;
        }
}

bool VertexGrid::anyInside(Vec2 pa, Vec2 pb, Vec2 pc, Change change) const
{
    const int turn = orientation(pa, pb, pc);
    const Vec2 low = glm::min(pa, glm::min(pb, pc)), high = glm::max(pa, glm::max(pb, pc));
    // How many vertices lie at each corner's place: the corners themselves, and any others.
    const std::array<Vec2, 3> corners{pa, pb, pc};
    std::array<int, 3> atCorner{};
    for (int y = row(low.y); y <= row(high.y); ++y)
        for (int x = column(low.x); x <= column(high.x); ++x)
            for (std::uint32_t k = m_head[std::size_t(y) * std::size_t(m_columns) + std::size_t(x)]; k != none;
                 k = m_entries[k].next) {
                const Vec2 p = m_entries[k].position;
                if (p.x < low.x || p.x > high.x || p.y < low.y || p.y > high.y)
                    continue;
                if (p == pa || p == pb || p == pc) {
                    for (std::size_t c = 0; c < 3; ++c)
                        atCorner[c] += p == corners[c];
                    continue;
                }
                const int ab = orientation(pa, pb, p), bc = orientation(pb, pc, p), ca = orientation(pc, pa, p);
                // A degenerate triangle (turn 0) is a segment: p lies in it when on that line.
                const bool inside = turn != 0 ? ab * turn >= 0 && bc * turn >= 0 && ca * turn >= 0
                                              : ab == 0 && bc == 0 && ca == 0;
                if (inside)
                    return true;
            }
    auto another = [&](std::size_t c) {
        return atCorner[c] > std::count(corners.begin(), corners.end(), corners[c]);
    };
    return another(1) || (change == Change::InsertPb && (another(0) || another(2)));
}

} // namespace vf::sim
