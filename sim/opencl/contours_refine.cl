// Refinement (paper §3.1, §3.3) by stream compaction; the split and collapse passes share their
// tile bookkeeping and vertex helpers, so they stay in one file (about 740 lines, with the
// collapse's sweep grid; the seam for a split is that grid, from sweepGridPass to sweepsInk, which
// only the collapse kernels call). Each pass decides, for every vertex at once, how many vertices it
// becomes (a split edge: 1 + the vertices inserted after it; a collapse: 0 or 1), scans those
// counts and scatters the store into the other buffer, so every contour stays contiguous and in
// order with no per-contour serial work and perfect balance.
// The counting kernels fuse the first level of the scan: they leave each vertex's offset within
// its tile of VF_LOCAL vertices and each tile's total, which Scan turns into tile bases.
//
// Work follows what changed. A pass looks only at the tiles (tileActive) that the pass before it
// marked: the tiles around every vertex that needs attention, one with a short edge after it (for
// the collapse passes; length < (d_a + d_b)/4, more than 3 vertices) or whose edges the pass
// changed (inserted vertices, a removed or recentred neighbour: for the split passes). A counting
// kernel marks them in the layout it reads (tileMarks, for when nothing moves) and flags its
// vertices' attention in their tile offsets; a scatter marks them again where they land
// (for the layout it writes). The first pass of a step looks at every tile (everything moved);
// a tile nobody marked has nothing a pass could change. Counting kernels skip a tile that is not
// looked at and leave only its total: every vertex in it stays, one to one, so its offsets are
// the vertices' places in the tile and are never written. A work-group (eight tiles) none of
// whose tiles is looked at returns before its barriers; the skipped tiles of other work-groups
// join the scan idle.
#define TILE_ARGS __global const uint *tileActive
#define ATTENTION 0x80000000u  // in a tile offset: the vertex needs attention in the next pass

// The store index vertex i moves to, or the new size of the store for i = n.
VF_INLINE uint scannedOffset(TILE_ARGS, __global const uint *tileOffset, __global const uint *tileBase, uint i)
{
    const uint tile = i / VF_LOCAL;
    return tileBase[tile] + (tileActive[tile] ? tileOffset[i] & ~ATTENTION : i % VF_LOCAL);
}

// Whether vertex i, looked at in this pass, needs attention in the next.
VF_INLINE bool needsAttention(TILE_ARGS, __global const uint *tileOffset, uint i)
{
    return tileActive[i / VF_LOCAL] && (tileOffset[i] & ATTENTION);
}

// Marks the tiles of store indices a, b and c for the next pass (plain stores of the same value).
VF_INLINE void markTiles(__global uint *marks, uint a, uint b, uint c)
{
    marks[a / VF_LOCAL] = 1;
    marks[b / VF_LOCAL] = 1;
    marks[c / VF_LOCAL] = 1;
}

// The counting kernels run over one work-item per VF_LANES of the n + 1 vertices (vertex n produces
// nothing; its offset is the count before it in its tile), so a tile is TILE_ITEMS work-items and
// a work-group VF_LANES tiles.
#define TILE_ITEMS (VF_LOCAL / VF_LANES)

// Whether this work-item's tile is looked at (work-items past vertex n lie in no tile).
VF_INLINE bool inActiveTile(TILE_ARGS, uint n)
{
    const uint first = VF_LANES * get_global_id(0);
    return first <= n && tileActive[first / VF_LOCAL];
}

// A tile that is not looked at keeps its vertices one to one: its total is its vertex count.
VF_INLINE uint skippedTileTotal(uint tile, uint n)
{
    return min((uint)VF_LOCAL, n - tile * VF_LOCAL);
}

// A counting kernel's work-group none of whose tiles is looked at: their totals. True then (the
// same for the whole work-group, which returns before its barriers).
VF_INLINE bool skippedGroup(TILE_ARGS, uint n, __global uint *tileTotals, uint tiles)
{
    const uint groupFirstTile = get_group_id(0) * VF_LANES, lid = get_local_id(0);
    for (uint t = groupFirstTile; t < min(groupFirstTile + VF_LANES, tiles); ++t)
        if (tileActive[t])
            return false;
    const uint tile = VF_LANES * get_global_id(0) / VF_LOCAL;
    if (lid % TILE_ITEMS == 0 && tile < tiles)
        tileTotals[tile] = skippedTileTotal(tile, n);
    if (get_global_id(0) == 0)
        tileTotals[tiles] = 0;
    return true;
}

// Leaves, from the counts `produced` of this work-item's lanes, each vertex's offset within its tile
// with its attention flag (tiles looked at only) and each tile's total; all work-items of the group
// must call it. `itemBefore` holds VF_LOCAL entries.
VF_INLINE void scanTiles(__local uint *scratch, __local uint *itemBefore, const uint *produced, const bool *attention,
                         bool active, uint n, __global uint *tileOffset, __global uint *tileTotals, uint tiles)
{
    const uint lid = get_local_id(0), first = VF_LANES * get_global_id(0), tile = first / VF_LOCAL;
    uint before[VF_LANES], sum = 0;
    for (int k = 0; k < VF_LANES; ++k) {
        before[k] = sum;
        sum += produced[k];
    }
    uint total;
    itemBefore[lid] = VF_LOCAL_SCAN(uint)(scratch, sum, &total);
    barrier(CLK_LOCAL_MEM_FENCE);
    const uint tileItem = lid - lid % TILE_ITEMS, nextTileItem = tileItem + TILE_ITEMS;
    const uint tileStart = itemBefore[tileItem];
    if (active) {
        for (int k = 0; k < VF_LANES && first + k <= n; ++k)
            tileOffset[first + k] = (itemBefore[lid] - tileStart + before[k]) | (attention[k] ? ATTENTION : 0u);
    }
    if (lid == tileItem && tile < tiles)
        tileTotals[tile] = active ? (nextTileItem < VF_LOCAL ? itemBefore[nextTileItem] : total) - tileStart
                                  : skippedTileTotal(tile, n);
    if (first == 0)
        tileTotals[tiles] = 0;  // the scan leaves the new vertex count here
}

// The split of one edge (a, b), exactly as the reference's split pass: while the sub-edge
// after the current vertex needs a vertex (splitPoint: longer than its spacing (d_p + d_q)/2, or a
// map's chord straying), it gets one at that point of the sub-edge at the start of the motion
// (its midpoint unless a crease is there), moved by the motion (eq. 2). Splitting
// is depth first, so vertices come out in contour order. Inserted vertices take min(d_a, d_b):
// with the mean, one half of an edge just over its spacing would fall under half of its own, and
// split and collapse would undo each other. Returns the number of vertices inserted; with `out`
// set, also writes them (at most `limit`) from out[at]. The count and the scatter kernels run
// this same code on the same inputs, so both see the same vertices. Every piece then respects its
// spacing, unless the depth cap stopped a split (*capped is set).
#define SPLIT_DEPTH 24  // at most 2^24 pieces per edge: far beyond any max_vertices

VF_INLINE uint splitEdge(FLOW_PARAMS, MOTION_ARGS, float4 a, float4 b, float spacingA, float spacingB,
                         __global float4 *outMotion, __global float *outSpacing, __global uint *outContour, uint at,
                         uint limit, uint contour, bool *capped)
{
    const float inserted = fmin(spacingA, spacingB);
    float4 pending[SPLIT_DEPTH];  // right ends of the sub-edges still to visit, (position, previous)
    int top = 0;
    pending[0] = b;
    float4 left = a;
    float leftSpacing = spacingA;
    uint count = 0;
    for (;;) {
        const float4 right = pending[top];
        const float rightSpacing = top == 0 ? spacingB : inserted;
        const float s = splitPoint(MOTION_PASS, left, right,
                                   distance(left.xy, right.xy) > 0.5f * (leftSpacing + rightSpacing));
        *capped = *capped || (s >= 0.0f && top + 1 == SPLIT_DEPTH);
        if (s >= 0.0f && top + 1 < SPLIT_DEPTH) {
            const float2 start = mix(left.zw, right.zw, s);
            const float2 p = rewind ? moved(FLOW_PASS, MOTION_PASS, start) : 0.5f * (left.xy + right.xy);
            pending[++top] = (float4)(p, start);
            continue;
        }
        if (top == 0)
            return count;
        if (outMotion && count < limit) {
            outMotion[at + count] = right;
            outSpacing[at + count] = inserted;
            outContour[at + count] = contour;
        }
        ++count;
        left = right;
        leftSpacing = inserted;
        --top;
    }
}

// The length under which an edge from p with spacing d is short (collapse's lower bound): half
// its spacing, less a few roundings of p's coordinates. Positions are floats: at a spacing of 6e-5
// near x = 0.5 a vertex can only be placed to within a thousandth of the spacing, so an edge split
// from one a hair over its spacing, or recentred onto its middle, would otherwise be short by a
// rounding and be recentred to the same place pass after pass (most of the fine-detail session's
// collapse work, before).
VF_INLINE float shortLength(float2 p, float d)
{
    return 0.5f * d - 2.0f * FLT_EPSILON * fmax(fabs(p.x), fabs(p.y));
}

// The colour class of the k-th of `count` vertices in the collapse passes (below).
VF_INLINE uint collapseColour(uint k, uint count)
{
    return (count & 1u) && k == count - 1 ? 2u : k & 1u;
}

// For the host: which collapse passes the short edge after the k-th vertex needs (its victim is
// one of its two ends).
VF_INLINE uint shortEdgeFlags(uint k, uint count)
{
    const uint next = k + 1 == count ? 0 : k + 1;
    return FLAG_SHORT_EDGE(collapseColour(k, count)) | FLAG_SHORT_EDGE(collapseColour(next, count));
}

// ContourTracker's isThinTip: a needle tip that collapse removes.
VF_INLINE bool isThinTip(float2 before, float2 at, float2 after, float spacingBefore, float spacing, float spacingAfter)
{
    const float2 in = at - before, out = after - at;
    if (dot(in, out) > 0.0f)  // most vertices: no lengths needed
        return false;
    const float longest = fmax(fmax(length(in), length(out)), distance(before, after));
    return distance(before, after) <= 0.5f * (spacingBefore + spacingAfter) &&
           fabs(cross2(in, out)) <= VF_TIP_WIDTH * spacing * longest;
}

VF_INLINE bool thinTipAt(__global const float4 *motion, __global const float *spacing, uint v, uint first, uint count)
{
    const uint a = previousIn(v, first, count), b = nextIn(v, first, count);
    return isThinTip(motion[a].xy, motion[v].xy, motion[b].xy, spacing[a], spacing[v], spacing[b]);
}

#define VERTEX_SET(prefix)                                                                     \
    __global float4 *prefix##Motion, __global float *prefix##Spacing, __global uint *prefix##Contour
#define CONST_VERTEX_SET(prefix)                                                               \
    __global const float4 *prefix##Motion, __global const float *prefix##Spacing, __global const uint *prefix##Contour

// The scatter kernels run over one work-item per VF_LANES vertices (a tile holds whole groups of
// them). A group whose vertices all stay, one to one, lands as one block: wide loads and stores.
VF_INLINE void copyLanes(CONST_VERTEX_SET(in), uint first, VERTEX_SET(out), uint at)
{
    __global const float *from = (__global const float *)(inMotion + first);
    __global float *to = (__global float *)(outMotion + at);
    vstore16(vload16(0, from), 0, to);
    vstore16(vload16(1, from), 1, to);
    vstore8(vload8(0, inSpacing + first), 0, outSpacing + at);
    vstore8(vload8(0, inContour + first), 0, outContour + at);
}

// The two counting passes (splitCount, collapseDecide) open and close alike. A group none of whose
// tiles is looked at leaves at once; `first` is the work-item's first vertex, `active` whether its
// tile is looked at, and the group's pass flags (groupFlags) start empty. At the end each lane's
// count of vertices and its need of attention are scanned over the tiles, and the group's flags
// join the pass's status word.
#define VF_BEGIN_COUNTING_PASS                                   \
    __local uint scratch[VF_SCAN_SCRATCH], itemBefore[VF_LOCAL]; \
    __local uint groupFlags;                                     \
    if (skippedGroup(tileActive, n, tileTotals, tiles))          \
        return;                                                  \
    const uint first = VF_LANES * get_global_id(0);              \
    const bool active = inActiveTile(tileActive, n);             \
    if (get_local_id(0) == 0)                                    \
        groupFlags = 0;                                          \
    barrier(CLK_LOCAL_MEM_FENCE)

#define VF_END_COUNTING_PASS(counts, attention)                                                  \
    scanTiles(scratch, itemBefore, counts, attention, active, n, tileOffset, tileTotals, tiles); \
    if (get_local_id(0) == 0 && groupFlags)                                                      \
        atomic_or(&status[STATUS_PASS], groupFlags)

// Per vertex: 1 + the vertices its edge to the next one gets. Also flags short edges by the colours
// of their ends, so the host can skip the collapse passes that would find nothing to do, and a
// split stopped by the depth cap. A split edge or a short one needs attention (marks).
VF_KERNEL void splitCount(FLOW_ARGS, MOTION_ARGS, CONST_VERTEX_SET(in), __global const uint *contourOffset,
                          __global const uint *contourCount, uint n, TILE_ARGS, __global uint *marks,
                          __global uint *tileOffset, __global uint *tileTotals, uint tiles, __global uint *status)
{
    VF_BEGIN_COUNTING_PASS;
    // A group of lanes on one contour, with a vertex either side of it there, whose edges are all
    // well inside (d/2, d) and where the contour nowhere turns back (no needle tip) is settled:
    // every vertex stays one to one, with no flag. The margin keeps the vector lengths from
    // deciding anything the one-vertex test below (distance()) could decide otherwise. A map
    // depicted exactly looks at every edge's chord, whatever its length.
    const bool exact = depictedExactly(MOTION_PASS);
    bool settled = false;
    if (active && !exact && first > 0 && oneContour(inContour, first - 1, first + VF_LANES, n)) {
        __global const float *positions = (__global const float *)inMotion;
        floatv beforeX, beforeY, x, y, afterX, afterY;
        consecutiveLanes(positions, 4, first - 1, &beforeX, &beforeY);
        consecutiveLanes(positions, 4, first, &x, &y);
        consecutiveLanes(positions, 4, first + 1, &afterX, &afterY);
        const floatv outX = afterX - x, outY = afterY - y;
        const floatv length = sqrt(outX * outX + outY * outY);
        const floatv spacing = 0.5f * (VF_VLOAD(0, inSpacing + first) + VF_VLOAD(0, inSpacing + first + 1));
        const floatv forward = (x - beforeX) * outX + (y - beforeY) * outY;
        settled = all((length < 0.99999f * spacing) & (length > 0.50001f * spacing) & (forward > 0.0f));
    }
    uint produced[VF_LANES];
    bool attention[VF_LANES];
    for (int k = 0; k < VF_LANES; ++k) {
        const uint i = first + k;
        produced[k] = settled ? 1 : 0;
        attention[k] = false;
        if (settled || !active || i >= n)
            continue;
        const uint c = inContour[i], from = contourOffset[c], count = contourCount[c];
        const uint j = nextIn(i, from, count);
        const float4 a = inMotion[i], b = inMotion[j];
        const float length = distance(a.xy, b.xy), spacing = 0.5f * (inSpacing[i] + inSpacing[j]);
        produced[k] = 1;
        bool capped = false;
        if (length > spacing || exact)
            produced[k] += splitEdge(FLOW_PASS, MOTION_PASS, a, b, inSpacing[i], inSpacing[j], 0, 0, 0, 0, 0, c,
                                     &capped);
        if (capped)
            atomic_or(&groupFlags, FLAG_SPLIT_CAPPED);
        const bool shortEdge = length < shortLength(a.xy, spacing) && count > 3;
        if (shortEdge)
            atomic_or(&groupFlags, shortEdgeFlags(i - from, count));
        const bool tip = count > 3 && thinTipAt(inMotion, inSpacing, i, from, count);
        if (tip)
            atomic_or(&groupFlags, FLAG_SHORT_EDGE(collapseColour(i - from, count)));
        attention[k] = shortEdge || tip || produced[k] > 1;
        if (attention[k])
            markTiles(marks, previousIn(i, from, count), i, j);
    }
    VF_END_COUNTING_PASS(produced, attention);
}

// Whether any of the group's vertices (from `first`) needs attention: its tile is looked at and
// its flag set.
VF_INLINE bool groupNeedsAttention(TILE_ARGS, __global const uint *tileOffset, uint first)
{
    return tileActive[first / VF_LOCAL] && any((vload8(0, tileOffset + first) & (uint8)(ATTENTION)) != (uint8)(0u));
}

VF_KERNEL void splitScatter(FLOW_ARGS, MOTION_ARGS, CONST_VERTEX_SET(in), __global const uint *contourOffset,
                            __global const uint *contourCount, uint n, TILE_ARGS, __global const uint *tileOffset,
                            __global const uint *tileBase, VERTEX_SET(out), __global uint *marks,
                            __global uint *status)
{
    const uint g = get_global_id(0), first = VF_LANES * g;
    if (first >= n)
        return;
    const uint groupAt = scannedOffset(tileActive, tileOffset, tileBase, first);
    if (wholeGroup(g, n) && scannedOffset(tileActive, tileOffset, tileBase, first + VF_LANES) - groupAt == VF_LANES &&
        !groupNeedsAttention(tileActive, tileOffset, first)) {
        copyLanes(inMotion, inSpacing, inContour, first, outMotion, outSpacing, outContour, groupAt);
        return;
    }
    for (uint i = first; i < min(first + VF_LANES, n); ++i) {
        const uint at = scannedOffset(tileActive, tileOffset, tileBase, i);
        const uint expected = scannedOffset(tileActive, tileOffset, tileBase, i + 1) - at - 1;
        const uint c = inContour[i], from = contourOffset[c], count = contourCount[c];
        outMotion[at] = inMotion[i];
        outSpacing[at] = inSpacing[i];
        outContour[at] = c;
        const uint j = nextIn(i, from, count);
        if (needsAttention(tileActive, tileOffset, i))
            markTiles(marks, scannedOffset(tileActive, tileOffset, tileBase, previousIn(i, from, count)), at + expected,
                      scannedOffset(tileActive, tileOffset, tileBase, j));
        if (expected == 0)
            continue;
        for (uint k = 0; k <= expected; k += VF_LOCAL)
            marks[(at + k) / VF_LOCAL] = 1;
        bool capped = false;
        const uint inserted = splitEdge(FLOW_PASS, MOTION_PASS, inMotion[i], inMotion[j], inSpacing[i], inSpacing[j],
                                        outMotion, outSpacing, outContour, at + 1, expected, c, &capped);
        if (inserted != expected)
            atomic_or(&status[STATUS_STICKY], FLAG_SPLIT_MISMATCH);  // a bug, reported by the host
    }
}

// After a scatter: where each contour now starts and how many vertices it has.
VF_KERNEL void recountContours(__global uint *contourOffset, __global uint *contourCount, uint contours,
                               TILE_ARGS, __global const uint *tileOffset, __global const uint *tileBase)
{
    const uint c = get_global_id(0);
    if (c >= contours)
        return;
    const uint first = contourOffset[c], end = first + contourCount[c];
    const uint newFirst = scannedOffset(tileActive, tileOffset, tileBase, first);
    contourOffset[c] = newFirst;
    contourCount[c] = scannedOffset(tileActive, tileOffset, tileBase, end) - newFirst;
}

// Collapse. The reference walks each ring and removes, for every edge shorter than half its
// spacing, the straighter endpoint (smaller turning angle), so corners and curl tips survive; a
// vertex whose removal would leave an edge longer than its spacing is recentred instead. Here all
// vertices decide at once, in three colour classes so that no two neighbours act in the same
// pass: a vertex only reads its neighbours, which then stay put. Even contours alternate colours
// 0 and 1; odd ones give their last vertex colour 2. A contour never drops under 3 vertices: one
// of 5 or more keeps at least 3 whichever colour acts, and one of 4 lets its second same-colour
// vertex go only when the first stays.
#define ACTION_KEEP 0u
#define ACTION_DELETE 1u
#define ACTION_RECENTRE 2u

// Moves v to the time-rewound midpoint of its neighbours (eq. 2), as if v had been removed and
// the merged edge split again. Where the curve between them is lopsided, so that one half would
// come out short, a few corrections move the rewound point along the edge (recentredFraction, as
// ContourTracker's).
VF_INLINE float recentredFraction(float s, float toA, float toB, float needA, float needB)
{
    const float length = toA + toB;
    if (!(length > 0.0f))
        return s;
    const float place = toA / length, lo = needA / length, hi = 1.0f - needB / length;
    const float wanted = lo <= hi ? clamp(0.5f, lo, hi) : needA / (needA + needB);
    return clamp(s + (wanted - place), 0.0f, 1.0f);
}

// *settles: neither of v's new edges is short (shortLength), after at most
// VF_RECENTRE_CORRECTIONS corrections (ContourTracker's recentreCorrections).
VF_INLINE float4 recentred(FLOW_PARAMS, MOTION_ARGS, float4 a, float4 b, float spacingA, float spacingB, bool *settles)
{
    const float dv = fmin(spacingA, spacingB);
    const float needA = shortLength(a.xy, 0.5f * (spacingA + dv)), needB = shortLength(b.xy, 0.5f * (spacingB + dv));
    float s = 0.5f;
    float2 start = mix(a.zw, b.zw, s);
    float2 x = rewind ? moved(FLOW_PASS, MOTION_PASS, start) : mix(a.xy, b.xy, s);
    for (int k = 0;; ++k) {
        const float toA = distance(x, a.xy), toB = distance(x, b.xy);
        *settles = toA >= needA && toB >= needB;
        if (*settles || k == VF_RECENTRE_CORRECTIONS)
            break;
        s = recentredFraction(s, toA, toB, needA, needB);
        start = mix(a.zw, b.zw, s);
        x = rewind ? moved(FLOW_PASS, MOTION_PASS, start) : mix(a.xy, b.xy, s);
    }
    return (float4)(x, start);
}

VF_INLINE float turning(float2 before, float2 at, float2 after)
{
    const float2 e0 = at - before, e1 = after - at;
    return fabs(atan2(cross2(e0, e1), dot(e0, e1)));
}

// The reference's VertexGrid::anyInside on the sweep grid (sweepGridPass), built on the positions
// this colour's pass starts from (DeviceContours::Impl::collapsePass): whether a vertex lies in the
// closed triangle a, x, b other than a, b and v, the vertex removed (x = v) or moved (a recentring's
// new place x is not in the grid). Another vertex at v's place counts, as one at a's or b's does for
// a recentring: a contour touching itself or another there, whose edges may leave that corner
// into the triangle and out across a new edge. Removals of one pass, each checked against the same
// positions, cannot cross each other's new edges: two triangles that meet with no corner of one
// inside the other have two pairs of crossing sides. In float a point counts as outside only where
// one side's sign is sure against the other two's rounding, and a triangle over more than
// VF_SWEEP_CELLS cells each way sweeps ink: an unsure case keeps the contour as it is.
#define SWEEP_ARGS                                                                                 \
    GRID_ARGS, __global const uint *bucketStart, __global const float2 *entries, __global const float2 *overflow, \
        uint overflowCount
#define SWEEP_PASS GRID_PASS, bucketStart, entries, overflow, overflowCount
#define MOVING_SWEEP_ARGS                                                                                         \
    GRID_ARGS, __global const uint *bucketStart, __global float2 *entries, __global float2 *overflow,            \
        uint overflowCount, __global uint *status
#define MOVING_SWEEP_PASS GRID_PASS, bucketStart, entries, overflow, overflowCount, status
#define VF_SWEEP_CELLS 4

// The sweep grid, by counting sort as the proximity grid's, of positions only: launched once to
// count each vertex into its bucket (`scatter` 0), and after the scan of the counts once more to
// put its position at its place there (`scatter` 1).
VF_KERNEL void sweepGridPass(__global const float4 *motion, uint n, GRID_ARGS, int scatter,
                             __global uint *bucketCountsThenStarts, __global uint *rank, __global float2 *entries)
{
    const uint g = get_global_id(0), first = VF_LANES * g;
    if (first >= n)
        return;
    float xs[VF_LANES], ys[VF_LANES];
    int bucket[VF_LANES];
    lanePositionsAndBuckets(motion, g, n, GRID_PASS, xs, ys, bucket);
    if (!scatter) {
        countIntoBuckets(bucket, first, (int)min((uint)VF_LANES, n - first), bucketCountsThenStarts, rank);
        return;
    }
    for (int k = 0; k < VF_LANES && first + k < n; ++k)
        entries[bucketCountsThenStarts[bucket[k]] + rank[first + k]] = (float2)(xs[k], ys[k]);
}

// The bucket of p in the sweep grid, as bucketLanes finds it.
VF_INLINE int sweepBucket(GRID_ARGS, float2 p)
{
    int bucket[VF_LANES];
    bucketLanes(GRID_PASS, (floatv)(p.x), (floatv)(p.y), bucket);
    return bucket[0];
}

// The sweep grid follows the vertices a collapse pass deletes or recentres (collapseScatter,
// recentreInPlace), so that the next colour's pass checks against the positions it starts from
// without the grid being built again. A deleted vertex's entry becomes SWEEP_FORGOTTEN, below every
// triangle's box; a recentred vertex's entry takes its new position, or, where that lies in another
// bucket, is forgotten and the position goes to the overflow list (appended at STATUS_OVERFLOW, at
// most VF_SWEEP_OVERFLOW), where it then moves or is forgotten as in the grid. The decisions count
// the recentrings into another bucket (STATUS_ACROSS); the host builds the grid again before the
// list could fill, and gives the kernels the count of entries the list may hold (overflowCount),
// those not yet written being SWEEP_FORGOTTEN (DeviceContours::Impl::buildSweepGrid). An entry is
// claimed by a compare-and-swap of its x, so of equal positions exactly one moves.
#define SWEEP_FORGOTTEN (-FLT_MAX)

// Claims the entry at `from` among entries[begin, end): its x becomes SWEEP_FORGOTTEN. Its index, or end.
VF_INLINE uint claimEntry(__global float2 *entries, uint begin, uint end, float2 from)
{
    __global uint *words = (__global uint *)entries;
    for (uint k = begin; k < end; ++k)
        if (entries[k].y == from.y &&
            atomic_cmpxchg(&words[2 * k], as_uint(from.x), as_uint(SWEEP_FORGOTTEN)) == as_uint(from.x))
            return k;
    return end;
}

VF_INLINE void moveSweepEntry(MOVING_SWEEP_ARGS, float2 from, float2 to)
{
    const int bucket = sweepBucket(GRID_PASS, from);
    const uint k = claimEntry(entries, bucketStart[bucket], bucketStart[bucket + 1], from);
    if (k == bucketStart[bucket + 1]) {
        const uint j = claimEntry(overflow, 0, overflowCount, from);
        if (j < overflowCount && to.x != SWEEP_FORGOTTEN)
            overflow[j] = to;
        return;
    }
    if (to.x == SWEEP_FORGOTTEN)
        return;
    if (sweepBucket(GRID_PASS, to) == bucket) {
        entries[k] = to;
        return;
    }
    const uint slot = atomic_inc(&status[STATUS_OVERFLOW]);
    if (slot < VF_SWEEP_OVERFLOW)
        overflow[slot] = to;
}

// Twice the signed area of from, to, p, and in *slack a bound on its rounding.
VF_INLINE float sideOf(float2 from, float2 to, float2 p, float *slack)
{
    const float2 e = to - from, d = p - from;
    *slack = 8.0f * FLT_EPSILON * (fabs(e.x * d.y) + fabs(e.y * d.x));
    return cross2(e, d);
}

VF_INLINE bool surelyOutside(float2 a, float2 b, float2 c, float2 p)
{
    float slackAB, slackBC, slackCA;
    const float ab = sideOf(a, b, p, &slackAB), bc = sideOf(b, c, p, &slackBC), ca = sideOf(c, a, p, &slackCA);
    const bool left = ab > slackAB || bc > slackBC || ca > slackCA;
    const bool right = ab < -slackAB || bc < -slackBC || ca < -slackCA;
    return left && right;
}

// The places of the three vertices a sweep expects in the grid (a, b and the one removed or
// moved), and how many entries it has met at each.
typedef struct {
    float2 place[3];
    uint met[3];
} OwnVertices;

// Whether entry p is ink for the triangle a, x, b; an entry at an own vertex's place is counted
// instead.
VF_INLINE bool inkAt(float2 p, float2 low, float2 high, float2 a, float2 x, float2 b, OwnVertices *own)
{
    if (any(p < low) || any(p > high))
        return false;
    bool ownPlace = false;
    for (int k = 0; k < 3; ++k)
        if (all(p == own->place[k])) {
            ++own->met[k];
            ownPlace = true;
        }
    return !ownPlace && !surelyOutside(a, x, b, p);
}

// Whether more entries lie at own vertex k's place than own vertices do.
VF_INLINE bool anotherAt(const OwnVertices *own, int k)
{
    uint owners = 0;
    for (int j = 0; j < 3; ++j)
        owners += all(own->place[j] == own->place[k]) ? 1u : 0u;
    return own->met[k] > owners;
}

// Whether the triangle a, x, b sweeps ink, where v, between a and b, is removed (x = v) or moved
// to x.
VF_INLINE bool sweepsInk(SWEEP_ARGS, float2 a, float2 x, float2 b, float2 v)
{
    const float2 low = fmin(a, fmin(x, b)), high = fmax(a, fmax(x, b));
    const int x0 = (int)floor(low.x / cellSize), x1 = (int)floor(high.x / cellSize);
    const int y0 = (int)floor(low.y / cellSize), y1 = (int)floor(high.y / cellSize);
    if (x1 - x0 >= VF_SWEEP_CELLS || y1 - y0 >= VF_SWEEP_CELLS)
        return true;
    OwnVertices own = {{a, b, v}, {0, 0, 0}};
    const int columnMask = (1 << columnBits) - 1, rowMask = (1 << rowBits) - 1;
    for (int row = y0; row <= y1; ++row)
        for (int column = x0; column <= x1; ++column) {
            const uint bucket = ((uint)(row & rowMask) << columnBits) + (uint)(column & columnMask);
            for (uint k = bucketStart[bucket], end = bucketStart[bucket + 1]; k < end; ++k)
                if (inkAt(entries[k], low, high, a, x, b, &own))
                    return true;
        }
    for (uint k = 0; k < overflowCount; ++k)
        if (inkAt(overflow[k], low, high, a, x, b, &own))
            return true;
    // Another vertex at a's or b's place shares an end with a removal's new edge a–b, which so
    // cannot cross its edges, but not with a recentring's x–b or a–x.
    return anotherAt(&own, 2) || (any(x != v) && (anotherAt(&own, 0) || anotherAt(&own, 1)));
}

// *leavesBucket: a recentring takes v into another bucket of the sweep grid.
VF_INLINE uint collapseAction(FLOW_PARAMS, MOTION_ARGS, SWEEP_ARGS, __global const float4 *motion,
                              __global const float *spacing, uint v, uint first, uint count, bool *leavesBucket)
{
    const uint a = previousIn(v, first, count), b = nextIn(v, first, count);
    const float2 pa = motion[a].xy, pv = motion[v].xy, pb = motion[b].xy;
    const float da = spacing[a], dv = spacing[v], db = spacing[b];
    if (isThinTip(pa, pv, pb, da, dv, db) && !sweepsInk(SWEEP_PASS, pa, pv, pb, pv))
        return ACTION_DELETE;
    const bool shortBefore = distance(pa, pv) < shortLength(pv, 0.5f * (da + dv));
    const bool shortAfter = distance(pv, pb) < shortLength(pv, 0.5f * (dv + db));
    if (!shortBefore && !shortAfter)
        return ACTION_KEEP;
    // The reference's victim of edge (p, q) is p when turning(p) < turning(q), else q.
    const float here = turning(pa, pv, pb);
    const bool victim =
        (shortBefore && !(turning(motion[previousIn(a, first, count)].xy, pa, pv) < here)) ||
        (shortAfter && here < turning(pv, pb, motion[nextIn(b, first, count)].xy));
    if (!victim)
        return ACTION_KEEP;
    // A map depicted exactly keeps a vertex whose removal would leave a chord straying from the
    // mapped curve, or from the edge it came from (ContourTracker's holdsShape).
    if (depictedExactly(MOTION_PASS)) {
        const float2 tolerance = chordTolerances(MOTION_PASS, motion[a], motion[b]);
        if (straysFrom(tolerance.x, pv, pa, pb) || straysFrom(tolerance.y, motion[v].zw, motion[a].zw, motion[b].zw))
            return ACTION_KEEP;
    }
    // Removed or recentred only where that sweeps over no ink: a recentring is a removal, then an
    // insertion at x.
    if (sweepsInk(SWEEP_PASS, pa, pv, pb, pv))
        return ACTION_KEEP;
    if (distance(pa, pb) <= 0.5f * (da + db))
        return ACTION_DELETE;
    // Recentred only where that lengthens both edges enough; else the short edge stays (a lower bound
    // topology does not need) rather than v being moved to the same place round after round.
    bool settles;
    const float2 x = recentred(FLOW_PASS, MOTION_PASS, motion[a], motion[b], da, db, &settles).xy;
    if (!settles || sweepsInk(SWEEP_PASS, pa, x, pb, pv))
        return ACTION_KEEP;
    *leavesBucket = sweepBucket(GRID_PASS, x) != sweepBucket(GRID_PASS, pv);
    return ACTION_RECENTRE;
}

VF_KERNEL void collapseDecide(FLOW_ARGS, MOTION_ARGS, SWEEP_ARGS, __global const float4 *motion,
                              __global const float *spacing, CONTOUR_ARGS, uint n, uint colour, TILE_ARGS,
                              __global uint *marks,
                              __global uint *action, __global uint *tileOffset, __global uint *tileTotals, uint tiles,
                              __global uint *status)
{
    VF_BEGIN_COUNTING_PASS;
    uint kept[VF_LANES];
    bool attention[VF_LANES];
    for (int lane = 0; lane < VF_LANES; ++lane) {
        const uint i = first + lane;
        kept[lane] = 0;
        attention[lane] = false;
        if (!active || i >= n)
            continue;
        uint act = ACTION_KEEP;
        const uint c = contourOf[i], from = contourOffset[c], count = contourCount[c], k = i - from;
        bool leavesBucket = false;
        if (count > 3 && collapseColour(k, count) == colour) {
            act = collapseAction(FLOW_PASS, MOTION_PASS, SWEEP_PASS, motion, spacing, i, from, count, &leavesBucket);
            bool unused = false;
            if (count == 4 && k >= 2 && act == ACTION_DELETE &&
                collapseAction(FLOW_PASS, MOTION_PASS, SWEEP_PASS, motion, spacing, i - 2, from, count, &unused) ==
                    ACTION_DELETE)
                act = ACTION_KEEP;
        }
        const uint j = nextIn(i, from, count);
        const float length = distance(motion[i].xy, motion[j].xy), spacingIJ = 0.5f * (spacing[i] + spacing[j]);
        const bool shortEdge = count > 3 && length < shortLength(motion[i].xy, spacingIJ);
        if (shortEdge)
            atomic_or(&groupFlags, shortEdgeFlags(k, count));
        const bool tip = count > 3 && act == ACTION_KEEP && thinTipAt(motion, spacing, i, from, count);
        if (tip)
            atomic_or(&groupFlags, FLAG_SHORT_EDGE(collapseColour(k, count)));
        if (act == ACTION_RECENTRE)
            atomic_or(&groupFlags, FLAG_RECENTRED);
        if (act == ACTION_RECENTRE && leavesBucket)
            atomic_inc(&status[STATUS_ACROSS]);
        // A long edge (left by a recentring of an earlier colour) is for the next split pass.
        attention[lane] = shortEdge || tip || length > spacingIJ || act != ACTION_KEEP;
        if (attention[lane])
            markTiles(marks, previousIn(i, from, count), i, j);
        action[i] = act;
        kept[lane] = act != ACTION_DELETE;
    }
    VF_END_COUNTING_PASS(kept, attention);
}

// Writes v recentred at `at`, and moves its entry in the sweep grid there.
VF_INLINE void writeRecentred(FLOW_PARAMS, MOTION_ARGS, MOVING_SWEEP_ARGS, __global const float4 *inMotion,
                              __global const float *inSpacing, uint v, uint first, uint count,
                              __global float4 *outMotion, __global float *outSpacing, uint at)
{
    const uint a = previousIn(v, first, count), b = nextIn(v, first, count);
    const float2 from = inMotion[v].xy;
    bool settles;
    const float4 x = recentred(FLOW_PASS, MOTION_PASS, inMotion[a], inMotion[b], inSpacing[a], inSpacing[b], &settles);
    outMotion[at] = x;
    outSpacing[at] = fmin(inSpacing[a], inSpacing[b]);
    moveSweepEntry(MOVING_SWEEP_PASS, from, x.xy);
}

// Every vertex that acts needs attention, so a group with none stays as it is.
VF_KERNEL void collapseScatter(FLOW_ARGS, MOTION_ARGS, CONST_VERTEX_SET(in), __global const uint *contourOffset,
                               __global const uint *contourCount, uint n, TILE_ARGS, __global const uint *action,
                               __global const uint *tileOffset, __global const uint *tileBase, VERTEX_SET(out),
                               __global uint *marks, MOVING_SWEEP_ARGS)
{
    const uint g = get_global_id(0), first = VF_LANES * g;
    if (first >= n)
        return;
    if (wholeGroup(g, n) && !groupNeedsAttention(tileActive, tileOffset, first)) {
        copyLanes(inMotion, inSpacing, inContour, first, outMotion, outSpacing, outContour,
                  scannedOffset(tileActive, tileOffset, tileBase, first));
        return;
    }
    for (uint i = first; i < min(first + VF_LANES, n); ++i) {
        const bool attention = needsAttention(tileActive, tileOffset, i);
        const uint act = attention ? action[i] : ACTION_KEEP;
        const uint c = inContour[i], from = contourOffset[c], count = contourCount[c];
        if (attention) {
            // The neighbours of a vertex that acts keep their places in this pass.
            const uint before = scannedOffset(tileActive, tileOffset, tileBase, previousIn(i, from, count));
            const uint after = scannedOffset(tileActive, tileOffset, tileBase, nextIn(i, from, count));
            markTiles(marks, before, act == ACTION_DELETE ? before : scannedOffset(tileActive, tileOffset, tileBase, i),
                      after);
        }
        if (act == ACTION_DELETE) {
            moveSweepEntry(MOVING_SWEEP_PASS, inMotion[i].xy, (float2)(SWEEP_FORGOTTEN, inMotion[i].y));
            continue;
        }
        const uint at = scannedOffset(tileActive, tileOffset, tileBase, i);
        outContour[at] = c;
        if (act == ACTION_RECENTRE) {
            writeRecentred(FLOW_PASS, MOTION_PASS, MOVING_SWEEP_PASS, inMotion, inSpacing, i, from, count,
                           outMotion, outSpacing, at);
        } else {
            outMotion[at] = inMotion[i];
            outSpacing[at] = inSpacing[i];
        }
    }
}

// A collapse pass that only recentres needs no compaction: recentred vertices move in place
// (their neighbours do not act in the same pass, so nothing they read changes). One work-item per
// VF_LANES vertices.
VF_KERNEL void recentreInPlace(FLOW_ARGS, MOTION_ARGS, __global float4 *motion, __global float *spacing, CONTOUR_ARGS,
                               uint n, TILE_ARGS, __global const uint *action, MOVING_SWEEP_ARGS)
{
    const uint first = VF_LANES * get_global_id(0);
    if (first >= n || !tileActive[first / VF_LOCAL])
        return;
    for (uint i = first; i < min(first + VF_LANES, n); ++i) {
        if (action[i] != ACTION_RECENTRE)
            continue;
        const uint c = contourOf[i];
        writeRecentred(FLOW_PASS, MOTION_PASS, MOVING_SWEEP_PASS, motion, spacing, i, contourOffset[c],
                       contourCount[c], motion, spacing, i);
    }
}
