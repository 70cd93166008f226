#pragma once
// Every vertex of every contour while refinement changes them, kept current as vertices are split
// in, removed and moved, so that a removal or a recentring can make sure that no ink lies where its
// new edges sweep (ContourTracker::refine; docs/method.md, "Topology").
#include "sim/Tracking.h"

#include <cstdint>
#include <vector>

namespace vf::sim {

class VertexGrid {
public:
    // Indexes every vertex of `contours` in square cells of about `cell`, coarser where the
    // contours spread over more cells than they have vertices.
    void build(const std::vector<Contour>& contours, double cell);

    void insert(Vec2 p);
    // Removes a vertex at p (vertices at one place are alike to the searches).
    void erase(Vec2 p);

    // What a sweep check is about: joining pa–pc in place of pa–pb–pc (pb removed), or pa–pb–pc in
    // place of pa–pc (pb inserted).
    enum class Change { RemovePb, InsertPb };
    // Whether a vertex other than the triangle's own three lies in the closed triangle pa, pb, pc
    // (exact predicates); each corner must be in the grid, and stands for one vertex there. Another
    // vertex at pb's place counts, as one at pa's or pc's does for an insertion: a contour touching
    // itself or another there, whose edges may leave that corner into the triangle and out across
    // a new edge (a removal's pa–pc shares an end with those at pa and pc, so cannot cross their
    // edges). Where none does, and no edge crosses pa–pb or pb–pc, no edge can cross pa–pc either:
    // it would have to enter the triangle and leave it through a side that no edge crosses, or end
    // inside it; and the same the other way round.
    bool anyInside(Vec2 pa, Vec2 pb, Vec2 pc, Change change) const;

private:
    static constexpr std::uint32_t none = ~std::uint32_t(0);
    // Each cell's entries as a list through `next`, so that insertion and removal move nothing. A
    // removed entry stays in m_entries, unlinked, until the next build.
    struct Entry {
        Vec2 position;
        std::uint32_t next;
    };
    std::size_t cellOf(Vec2 p) const;
    int column(double x) const;
    int row(double y) const;

    double m_cell = 1.0;
    Vec2 m_origin{0.0};
    int m_columns = 0, m_rows = 0;
    std::vector<std::uint32_t> m_head;  // per cell: its first entry, or none
    std::vector<Entry> m_entries;
};

} // namespace vf::sim
