// The adaptive spacing d_i of paper §3.3 (eqs. 3–7), as sim/SpacingField and sim/ProximityGrid:
//   d_i = d_max · exp(−|κ_i|·Lκ − |ω(v_i)|/ω_ref) · (1 − exp(−dist_i/Lp)), smoothed along the
//   contour with a Gaussian window (eq. 6), + ε, clamped to d_max.
//
// dist_i (eq. 7) is the distance to the nearest vertex of another part of any contour, found in a
// uniform grid built by counting sort ([Grand 2007], paper §3.4). Cells are half the search
// radius (wider where few vertices spread thin), and the search goes ring by ring
// (nearestOtherPart, then nearestBeyond): dense ink finds its nearest other part in its own cell,
// where cells as wide as the radius held hundreds of candidates. Both go two entries at a time,
// 8 lanes wide. The buckets, a power of two that follows the vertex count, form a torus that the
// plane wraps onto, so the grid needs no bounding box (no read-back) and stays small however far
// contours spread, and neighbouring cells stay neighbours in memory (a CPU device lives on its
// caches). At a million vertices and the default d_max the torus spans 8 canvas units; cells a
// whole torus apart share buckets, which only adds candidates that the distance test rejects.
//
// "Another part" needs the arc length along the contour: a vertex of the same contour counts when
// the shorter way along the contour is more than twice the straight distance. Arc lengths are a
// prefix sum of edge lengths, split into a float sum within each work-group tile and the tiles'
// prefix in acc_t (double on fp64 devices), so arcs stay precise however long the store.

#define GRID_ARGS float cellSize, uint columnBits, uint rowBits
#define GRID_PASS cellSize, columnBits, rowBits

// The bucket of each lane's p = (x, y), into `buckets`: the cell floor(p / cellSize), clamped into
// int's range (convert_int_sat_rtn does the same, several times slower), wrapped onto the torus.
VF_INLINE void bucketLanes(GRID_ARGS, floatv x, floatv y, int *buckets)
{
    const intv cellX = VF_CONVERT_INTV(clamp(floor(x / cellSize), -1e9f, 1e9f));
    const intv cellY = VF_CONVERT_INTV(clamp(floor(y / cellSize), -1e9f, 1e9f));
    VF_VSTORE(((cellY & (intv)((1 << rowBits) - 1)) << (intv)(columnBits)) + (cellX & (intv)((1 << columnBits) - 1)),
              0, buckets);
}

// The positions of work-item g's lanes (its VF_LANES vertices from VF_LANES·g) and their buckets.
VF_INLINE void lanePositionsAndBuckets(__global const float4 *motion, uint g, uint n, GRID_ARGS, float *xs, float *ys,
                                       int *bucket)
{
    floatv x, y;
    lanesOf((__global const float *)motion, 4, g, n, &x, &y);
    bucketLanes(GRID_PASS, x, y, bucket);
    VF_VSTORE(x, 0, xs);
    VF_VSTORE(y, 0, ys);
}

// Each of the lanes' vertices (from `first`, `lanes` of them) counted into its bucket, and its rank
// there left in `rank`: one atomic per run of lanes in one bucket (neighbours along a contour
// mostly share a cell). The counts do not depend on the order in which work-items arrive, the
// ranks do (see gridScatter).
VF_INLINE void countIntoBuckets(const int *bucket, uint first, int lanes, __global uint *bucketCounts,
                                __global uint *rank)
{
    for (int k = 0; k < lanes;) {
        int end = k + 1;
        while (end < lanes && bucket[end] == bucket[k])
            ++end;
        const uint base = atomic_add(&bucketCounts[bucket[k]], (uint)(end - k));
        for (int m = k; m < end; ++m)
            rank[first + m] = base + (uint)(m - k);
        k = end;
    }
}

// Arc lengths are summed in tiles of VF_ARC_TILE vertices: a work-group of lane work-items.
#define VF_ARC_TILE (VF_LOCAL * VF_LANES)

// Edge lengths to the next vertex, summed within each arc tile (exclusive), and each tile's total
// for the scan; also the grid's per-bucket counts and each vertex's rank in its bucket
// (countIntoBuckets). Launched over one work-item per VF_LANES of the n + 1 vertices, so that the
// prefix at n exists; lengths and cells are computed in lanes.
VF_KERNEL void arcTilesAndCount(__global const float4 *motion, CONTOUR_ARGS, uint n, GRID_ARGS,
                                __global float *tileArc, __global acc_t *tileTotals, uint tiles,
                                __global uint *bucketCounts, __global uint *rank)
{
    __local float scratch[VF_SCAN_SCRATCH];
    const uint g = get_global_id(0), first = VF_LANES * g;
    float lengths[VF_LANES] = {0.0f};
    if (first < n) {
        if (oneContour(contourOf, first, first + VF_LANES, n)) {
            VF_VSTORE(edgesOnward(motion, first), 0, lengths);
        } else {
            for (int k = 0; k < VF_LANES; ++k) {
                const uint i = laneVertex(g, k, n), c = contourOf[i];
                lengths[k] = distance(motion[i].xy, motion[nextIn(i, contourOffset[c], contourCount[c])].xy);
            }
        }
        floatv x, y;
        lanesOf((__global const float *)motion, 4, g, n, &x, &y);
        int bucket[VF_LANES];
        bucketLanes(GRID_PASS, x, y, bucket);
        countIntoBuckets(bucket, first, (int)min((uint)VF_LANES, n - first), bucketCounts, rank);
        for (int k = 0; k < VF_LANES; ++k)
            lengths[k] = first + k < n ? lengths[k] : 0.0f;
    }
    float before[VF_LANES], sum = 0.0f;
    for (int k = 0; k < VF_LANES; ++k) {
        before[k] = sum;
        sum += lengths[k];
    }
    float total;
    const float tileBefore = VF_LOCAL_SCAN(float)(scratch, sum, &total);
    for (int k = 0; k < VF_LANES && first + k <= n; ++k)
        tileArc[first + k] = tileBefore + before[k];
    if (get_local_id(0) == 0)
        tileTotals[get_group_id(0)] = total;
    if (g == 0)
        tileTotals[tiles] = 0;  // the scan leaves the grand total here
}

// Sum of the edge lengths before vertex i in the whole store.
VF_INLINE acc_t arcBefore(__global const float *tileArc, __global const acc_t *tilePrefix, uint i)
{
    return tilePrefix[i / VF_ARC_TILE] + (acc_t)tileArc[i];
}

// Counting sort, second half: bucketStart is the exclusive scan of the counts, and every vertex
// goes to its bucket's start plus its rank; the rank is replaced by that slot. The order within a
// bucket follows the atomics and may differ from run to run, but nearestOtherPart is a minimum
// over the bucket's entries, which no order changes, so no result depends on it. An entry is
// (x, y, arc, contour) as bits, the arc counted from the contour's first vertex; the first vertex
// also leaves its contour's length.
VF_KERNEL void gridScatter(__global const float4 *motion, CONTOUR_ARGS, uint n, __global const float *tileArc,
                           __global const acc_t *tilePrefix, GRID_ARGS, __global const uint *bucketStart,
                           __global uint *rankThenSlot, __global uint4 *entries, __global float *contourLength)
{
    const uint g = get_global_id(0);
    if (VF_LANES * g >= n)
        return;
    float xs[VF_LANES], ys[VF_LANES];
    int bucket[VF_LANES];
    lanePositionsAndBuckets(motion, g, n, GRID_PASS, xs, ys, bucket);
    for (int k = 0; k < VF_LANES && VF_LANES * g + k < n; ++k) {
        const uint i = VF_LANES * g + k, c = contourOf[i], first = contourOffset[c];
        const acc_t start = arcBefore(tileArc, tilePrefix, first);
        const float arc = (float)(arcBefore(tileArc, tilePrefix, i) - start);
        if (i == first)
            contourLength[c] = (float)(arcBefore(tileArc, tilePrefix, first + contourCount[c]) - start);
        const uint slot = bucketStart[bucket[k]] + rankThenSlot[i];
        entries[slot] = (uint4)(as_uint(xs[k]), as_uint(ys[k]), as_uint(arc), c);
        rankThenSlot[i] = slot;
    }
}

// Two entries of one bucket, searched together: entry A in lanes 0–3, entry B in lanes 4–7, each
// lane with its entry's position, arc, contour and contour length.
typedef struct {
    float8 x, y, arc, length;
    uint8 contour;
} EntryPair;

// The candidates of one run of entries [from, end) for both entries of `pair`, each lane taking
// those from index `low` on: for each entry, the smallest squared distance among those of another
// part, and, when `symmetric`, each of them gets this distance as a candidate for its own minimum
// (atomic_min on the bits of a non-negative float orders as the floats do, and gives the same
// result in any order). Four candidates at a time, compared with both entries in one 8-wide step
// (one load and shuffle of the candidates serves two entries), branch-free: most candidates are
// the vertex's own neighbours along its contour, and a branch per candidate would mispredict.
// Lanes past the run read the next entries (the array has slack at the end) and are masked out.
// best2 keeps a minimum per lane, which the caller reduces once. Minima are plain comparisons: a NaN distance
// fails `<` and leaves the minimum as it was, as fmin would (a step that moved a vertex to a
// non-finite position is thrown away when its next refinement pass reads the status).
VF_INLINE float8 nearestInRun(__global const uint4 *entries, uint from, uint end, uint8 low, const EntryPair *pair,
                              float radius2, float8 best2, bool symmetric, __global uint *gap2)
{
    for (uint e = from; e < end; e += 4) {
        const uint16 q = vload16(0, (__global const uint *)(entries + e));
        const uint8 index = (uint8)(e) + (uint8)(0, 1, 2, 3, 0, 1, 2, 3);
        const float8 dx = as_float8(q.s048c048c) - pair->x, dy = as_float8(q.s159d159d) - pair->y;
        const float8 dist2 = dx * dx + dy * dy;
        const float8 along = fabs(as_float8(q.s26ae26ae) - pair->arc);
        const float8 way = select(along, pair->length - along, pair->length - along < along);
        const int8 skip = ((q.s37bf37bf == pair->contour) & (way * way <= 4.0f * dist2)) | (index >= (uint8)(end)) |
                          (index < low);
        const float8 nearest = select(dist2, (float8)(radius2), skip);
        best2 = select(best2, nearest, nearest < best2);
        if (symmetric && any(nearest < (float8)(radius2))) {
            float found[8];
            vstore8(nearest, 0, found);
            for (int k = 0; k < 8; ++k)
                if (found[k] < radius2)
                    atomic_min(&gap2[e + (k & 3)], as_uint(found[k]));
        }
    }
    return best2;
}

// The smallest of a minimum per lane.
VF_INLINE float smallestOf(float4 best2)
{
    const float2 pairs = select(best2.xy, best2.zw, best2.zw < best2.xy);
    return pairs.y < pairs.x ? pairs.y : pairs.x;
}

// Entries a and b (b = a when there is only one) as a pair.
VF_INLINE EntryPair entryPair(__global const uint4 *entries, uint a, uint b, __global const float *contourLength)
{
    const uint4 entryA = entries[a], entryB = entries[b];
    EntryPair pair;
    pair.x = (float8)((float4)(as_float(entryA.x)), (float4)(as_float(entryB.x)));
    pair.y = (float8)((float4)(as_float(entryA.y)), (float4)(as_float(entryB.y)));
    pair.arc = (float8)((float4)(as_float(entryA.z)), (float4)(as_float(entryB.z)));
    pair.length = (float8)((float4)(contourLength[entryA.w]), (float4)(contourLength[entryB.w]));
    pair.contour = (uint8)((uint4)(entryA.w), (uint4)(entryB.w));
    return pair;
}

// The search of the entries at a and, when it is before `to` (the end of their bucket), a + 1: the
// rest of their bucket. Each entry's own minimum goes to gap2 once, at the end.
VF_INLINE void nearestOfPair(__global const uint4 *entries, uint a, uint to, __global const float *contourLength,
                             float radius2, __global uint *gap2)
{
    const bool withB = a + 1 < to;
    const EntryPair pair = entryPair(entries, a, withB ? a + 1 : a, contourLength);
    // Each takes the entries after it; B's lanes take none when it is missing.
    const uint8 afterSelf = (uint8)((uint4)(a + 1), (uint4)(withB ? a + 2 : ~0u));
    const float8 best2 =
        nearestInRun(entries, a + 1, to, afterSelf, &pair, radius2, (float8)(radius2), true, gap2);
    const float nearestA = smallestOf(best2.lo), nearestB = smallestOf(best2.hi);
    if (nearestA < radius2)
        atomic_min(&gap2[a], as_uint(nearestA));
    if (withB && nearestB < radius2)
        atomic_min(&gap2[a + 1], as_uint(nearestB));
}

// ProximityGrid::nearestOtherPart's first look for every grid entry: the squared distance to the
// nearest vertex of another part in its own bucket, when within the search radius, or the radius
// squared, as float bits in gap2 (filled before). Where that is farther than the edge of the
// entry's cell, the rings around it may hold a nearer one (nearestBeyond). Distance is symmetric and so is "another part"
// (same contour, same arcs, same length), so every pair of entries is compared once, by the one
// that comes first: the entry takes the rest of its own bucket and the next bucket of its row,
// then the three buckets of the next row (the forward half of the 3×3 cells), and both ends of a
// pair keep the minimum. A work-item takes VF_LANES buckets in turn: the runs to search are the
// same for every entry of a bucket and come from the bucket's place on the torus, so an entry
// needs no cell arithmetic, and most buckets are empty. A bucket's entries go two at a time
// (nearestOfPair). Work-items run in bucket order, so neighbouring ones search the same cells,
// which a CPU device then finds in its caches.
VF_KERNEL void nearestOtherPart(float radius, __global const uint *bucketStart, __global const uint4 *entries,
                                uint buckets, __global const float *contourLength, __global uint *gap2)
{
    // The bucket count, a power of two of at least 32 (DeviceContours::Impl::grid()), is a
    // multiple of VF_LANES.
    const uint first = VF_LANES * get_global_id(0);
    if (first >= buckets)
        return;
    const float radius2 = radius * radius;
    for (uint bucket = first; bucket < first + VF_LANES; ++bucket) {
        const uint from = bucketStart[bucket], to = bucketStart[bucket + 1];
        for (uint a = from; a < to; a += 2)
            nearestOfPair(entries, a, to, contourLength, radius2, gap2);
    }
}

// The cells [column, column + count) of a torus row, as the entries of one or (where the row wraps)
// two runs of buckets, searched for both entries of `pair`.
VF_INLINE float8 nearestInCells(__global const uint *bucketStart, __global const uint4 *entries, uint rowBase,
                                int column, int count, uint lastColumn, uint8 low, const EntryPair *pair,
                                float radius2, float8 best2)
{
    const uint from = (uint)column & lastColumn, to = (uint)(column + count - 1) & lastColumn;
    if (from <= to)
        return nearestInRun(entries, bucketStart[rowBase + from], bucketStart[rowBase + to + 1], low, pair, radius2,
                            best2, false, 0);
    best2 = nearestInRun(entries, bucketStart[rowBase + from], bucketStart[rowBase + lastColumn + 1], low, pair,
                         radius2, best2, false, 0);
    return nearestInRun(entries, bucketStart[rowBase], bucketStart[rowBase + to + 1], low, pair, radius2, best2, false,
                        0);
}

// How far entry e lies inside its cell: every vertex nearer than that is in its own bucket.
VF_INLINE float insideCell(GRID_ARGS, uint4 e)
{
    const float x = as_float(e.x), y = as_float(e.y);
    const float inX = x - floor(x / cellSize) * cellSize, inY = y - floor(y / cellSize) * cellSize;
    return fmax(0.0f, fmin(fmin(inX, inY), fmin(cellSize - inX, cellSize - inY)));
}

// The first entry of [from, to) whose nearest other part in its own bucket, if any, lies farther
// than the edge of its cell, or `to`.
VF_INLINE uint nextBeyond(GRID_ARGS, __global const uint4 *entries, uint from, uint to, __global const uint *gap2)
{
    for (; from < to; ++from) {
        const float edge = insideCell(GRID_PASS, entries[from]);
        if (as_float(gap2[from]) > edge * edge)
            return from;
    }
    return to;
}

// The rings of cells around the entries of a bucket whose nearest other part in the bucket, if
// any, lies farther than the edge of their cell: ring k holds the cells k away (Chebyshev), and
// once rings 0…k are searched every vertex nearer than k − 1 cells plus that edge distance has
// been seen, so an entry's search stops there when the nearest found is that near, and at the
// search radius at the latest. Dense ink rarely gets here: its nearest other part lies within
// its own cell. The entries that need it go two at a time, as in nearestOtherPart (four
// candidates against both in one 8-wide step), the pair's rings going on while either needs them;
// only their own minima change. A work-item takes VF_LANES buckets in turn.
VF_KERNEL void nearestBeyond(GRID_ARGS, float radius, __global const uint *bucketStart, __global const uint4 *entries,
                             uint buckets, __global const float *contourLength, __global uint *gap2)
{
    const uint first = VF_LANES * get_global_id(0);
    if (first >= buckets)
        return;
    const float radius2 = radius * radius;
    const int rings = (int)ceil(radius / cellSize);
    const uint lastColumn = (1u << columnBits) - 1u, lastRow = (1u << rowBits) - 1u;
    for (uint bucket = first; bucket < first + VF_LANES; ++bucket) {
        const uint to = bucketStart[bucket + 1];
        const int row = (int)(bucket >> columnBits), column = (int)(bucket & lastColumn);
        for (uint a = nextBeyond(GRID_PASS, entries, bucketStart[bucket], to, gap2); a < to;) {
            const uint b = nextBeyond(GRID_PASS, entries, a + 1, to, gap2);
            const bool withB = b < to;
            const EntryPair pair = entryPair(entries, a, withB ? b : a, contourLength);
            const float2 edge = (float2)(insideCell(GRID_PASS, entries[a]), withB ? insideCell(GRID_PASS, entries[b]) : 0.0f);
            const uint8 everyone = (uint8)((uint4)(0u), (uint4)(withB ? 0u : ~0u));
            float8 best2 = (float8)((float4)(as_float(gap2[a])), (float4)(withB ? as_float(gap2[b]) : 0.0f));
            for (int k = 1; k <= rings; ++k) {
                const float2 seen = edge + (float)(k - 1) * cellSize;
                const float2 nearest = (float2)(smallestOf(best2.lo), smallestOf(best2.hi));
                if (all(nearest <= seen * seen))
                    break;
                for (int dy = -k; dy <= k; ++dy) {
                    const uint rowBase = ((uint)(row + dy) & lastRow) << columnBits;
                    if (dy == -k || dy == k) {
                        best2 = nearestInCells(bucketStart, entries, rowBase, column - k, 2 * k + 1, lastColumn,
                                               everyone, &pair, radius2, best2);
                    } else {
                        best2 = nearestInCells(bucketStart, entries, rowBase, column - k, 1, lastColumn, everyone,
                                               &pair, radius2, best2);
                        best2 = nearestInCells(bucketStart, entries, rowBase, column + k, 1, lastColumn, everyone,
                                               &pair, radius2, best2);
                    }
                }
            }
            gap2[a] = as_uint(smallestOf(best2.lo));
            if (withB)
                gap2[b] = as_uint(smallestOf(best2.hi));
            a = withB ? nextBeyond(GRID_PASS, entries, b + 1, to, gap2) : to;
        }
    }
}

// Menger curvature: 1 / radius of the circle through the three points (SpacingField), in lanes.
VF_INLINE floatv mengerCurvature(floatv beforeX, floatv beforeY, floatv x, floatv y, floatv afterX, floatv afterY)
{
    const floatv e0x = x - beforeX, e0y = y - beforeY, e1x = afterX - x, e1y = afterY - y;
    const floatv chordX = afterX - beforeX, chordY = afterY - beforeY;
    const floatv denominator =
        sqrt((e0x * e0x + e0y * e0y) * (e1x * e1x + e1y * e1y) * (chordX * chordX + chordY * chordY));
    return select((floatv)(0.0f), 2.0f * fabs(e0x * e1y - e0y * e1x) / denominator,
                  isless((floatv)(0.0f), denominator));
}

// d_max·exp(−|κ|·Lκ − |ω|/ω_ref)·(1 − exp(−dist/Lp)): eqs. 3, 4, 5 and 7 before smoothing, launched
// over one work-item per VF_LANES vertices. With `proximity`, the squared distances come from
// nearestOtherPart, found through the vertex's grid slot (none within the search radius: no
// proximity term).
VF_KERNEL void rawSpacing(FLOW_ARGS, __global const float4 *motion, CONTOUR_ARGS, uint n, float maxSpacing,
                          float curvatureLength, float vorticityScale, float proximityLength, float searchRadius,
                          int proximity,
                          __global const uint *slot, __global const uint *gap2, __global float *raw)
{
    const uint g = get_global_id(0);
    if (VF_LANES * g >= n)
        return;
    const float radius2 = searchRadius * searchRadius;
    __global const float *positions = (__global const float *)motion;
    const uint first = VF_LANES * g;
    float distance2[VF_LANES];
    for (int k = 0; k < VF_LANES; ++k)
        distance2[k] = proximity ? as_float(gap2[slot[laneVertex(g, k, n)]]) : radius2;
    floatv x, y, beforeX, beforeY, afterX, afterY;
    lanesOf(positions, 4, g, n, &x, &y);
    if (first > 0 && oneContour(contourOf, first - 1, first + VF_LANES, n)) {
        // The lanes and a vertex either side of them on one contour: the neighbours are the lanes
        // one over, two more wide loads.
        consecutiveLanes(positions, 4, first - 1, &beforeX, &beforeY);
        consecutiveLanes(positions, 4, first + 1, &afterX, &afterY);
    } else {
        float before[2][VF_LANES], after[2][VF_LANES];
        for (int k = 0; k < VF_LANES; ++k) {
            const uint i = laneVertex(g, k, n), c = contourOf[i], from = contourOffset[c], count = contourCount[c];
            const float4 b = motion[previousIn(i, from, count)], a = motion[nextIn(i, from, count)];
            before[0][k] = b.x;
            before[1][k] = b.y;
            after[0][k] = a.x;
            after[1][k] = a.y;
        }
        beforeX = VF_VLOAD(0, before[0]);
        beforeY = VF_VLOAD(0, before[1]);
        afterX = VF_VLOAD(0, after[0]);
        afterY = VF_VLOAD(0, after[1]);
    }
    const floatv kappa = mengerCurvature(beforeX, beforeY, x, y, afterX, afterY);
    // exp(−a)·exp(−b) of eqs. 4 and 5 as one exponential.
    floatv factor = exp(-kappa * curvatureLength - fabs(flowVorticityLanes(FLOW_PASS, x, y, 1.0f)) / vorticityScale);
    const floatv gap = VF_VLOAD(0, distance2);
    factor = select(factor, factor * (1.0f - exp(-sqrt(gap) / proximityLength)), isless(gap, (floatv)(radius2)));
    storeLanes(raw, g, n, maxSpacing * factor);
}

// d rounded to VF_SPACING_FRACTION_BITS bits after the binary point (sim/SpacingField.h's
// roundedSpacing, in float).
VF_INLINE floatv roundedSpacing(floatv d)
{
    const int dropped = 23 - VF_SPACING_FRACTION_BITS;
    return as_float8((as_int8(d) + (intv)(1 << (dropped - 1))) & (intv)(~((1 << dropped) - 1)));
}

// Eq. 6 along the closed contour, then + ε, rounded, and the clamp to d_max; launched over one
// work-item per VF_LANES vertices.
VF_KERNEL void smoothSpacing(__global const float *raw, CONTOUR_ARGS, uint n, __constant float *weights, int radius,
                             float minSpacing, float maxSpacing, __global float *spacing)
{
    const uint g = get_global_id(0), first = VF_LANES * g, last = first + VF_LANES - 1;
    if (first >= n)
        return;
    const uint c = contourOf[first], from = contourOffset[c], to = from + contourCount[c];
    floatv s = (floatv)(0.0f);
    if (wholeGroup(g, n) && first >= from + radius && last + radius < to) {
        // All lanes on one contour, away from its ends (all but 2·radius vertices of it): plain
        // neighbours, one vector load per weight.
        for (int k = -radius; k <= radius; ++k)
            s += weights[k + radius] * VF_VLOAD(0, raw + first + k);
    } else {
        float sums[VF_LANES];
        for (int lane = 0; lane < VF_LANES; ++lane) {
            const uint i = laneVertex(g, lane, n), d = contourOf[i];
            float sum = 0.0f;
            for (int k = -radius; k <= radius; ++k)
                sum += weights[k + radius] * raw[stepAlong(i, k, contourOffset[d], contourCount[d])];
            sums[lane] = sum;
        }
        s = VF_VLOAD(0, sums);
    }
    storeLanes(spacing, g, n, fmin(maxSpacing, roundedSpacing(s + minSpacing)));
}
