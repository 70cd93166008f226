// Per-contour sums without per-contour serial passes over long contours: every tile of VF_LOCAL
// vertices is summed by its work-group (a fixed pairwise tree), then one work-item per contour
// adds the tiles lying wholly inside its range plus its (at most 2·VF_LOCAL) loose vertices at
// either end. All of it in acc_t (double on fp64 devices), in an order fixed by the indices.
//
// Two uses: the optional area correction (sim/AreaCorrection: v_i ← v_i + λ·u_i, u_i = g_i /
// max(|g_i|, shortEdge), g_i = ½·J·(v_{i+1} − v_{i−1}) the area gradient, u_i = 0 where held, λ in
// closed form), and
// the winding numbers that raise the area targets of the contours an ink drop lands in.
// The mode (host-defined codes): TERMS_AREA sums (2·area term, g_i·u_i, 2·area term of the u
// polygon, 0), TERMS_WINDING (winding contribution of the edge around `point`, 0, 0, 0).

VF_INLINE acc_t crossWide(acc2 a, acc2 b)
{
    return a.x * b.y - a.y * b.x;
}

// ∂A/∂v_i for the shoelace area, from the neighbours before and after.
VF_INLINE acc2 areaGradient(acc2 before, acc2 after)
{
    const acc2 d = after - before;
    return (acc_t)0.5 * (acc2)(d.y, -d.x);
}

// Which vertices the correction holds still (sim::ContourTracker::correctAreas): with `hold`, those
// whose nearest other part lies within √holdWithin2, from each vertex's grid slot and each grid
// entry's squared distance to its nearest other part (float bits), as the proximity search leaves
// them; and those at or beside a turn sharper than a right angle (sim/AreaCorrection.h).
#define HOLD_ARGS int hold, float holdWithin2, __global const uint *slot, __global const uint *gap2
#define HOLD_PASS hold, holdWithin2, slot, gap2

VF_INLINE bool turnsSharply(__global const float4 *motion, uint i, uint first, uint count)
{
    const float2 p = motion[i].xy;
    return dot(p - motion[previousIn(i, first, count)].xy, motion[nextIn(i, first, count)].xy - p) < 0.0f;
}

VF_INLINE bool heldAt(HOLD_ARGS, __global const float4 *motion, uint i, uint first, uint count)
{
    if (!hold)
        return false;
    const uint a = previousIn(i, first, count), b = nextIn(i, first, count);
    return as_float(gap2[slot[i]]) < holdWithin2 || turnsSharply(motion, a, first, count) ||
           turnsSharply(motion, i, first, count) || turnsSharply(motion, b, first, count);
}

// How the correction moves a vertex per unit λ: along the unit normal, shorter where the
// neighbours are closer than `shortEdge` (> 0).
VF_INLINE acc2 correctionDirection(acc2 gradient, acc_t shortEdge)
{
    return gradient / max(sqrt(dot(gradient, gradient)), shortEdge);
}

VF_INLINE acc4 contourTerms(int mode, float2 point, float shortEdge, HOLD_ARGS, __global const float4 *motion, uint i,
                            uint first, uint count)
{
    const uint b = nextIn(i, first, count);
    const acc2 p = exactly(motion[i].xy), q = exactly(motion[b].xy);
    if (mode == TERMS_WINDING) {
        // Sunday's crossing rule, as sim::windingNumber.
        const acc2 x = (acc2)((acc_t)point.x, (acc_t)point.y);
        const acc_t side = (q.x - p.x) * (x.y - p.y) - (x.x - p.x) * (q.y - p.y);
        acc_t w = 0;
        if (p.y <= x.y && q.y > x.y && side > 0)
            w = 1;
        else if (p.y > x.y && q.y <= x.y && side < 0)
            w = -1;
        return (acc4)(w, 0, 0, 0);
    }
    // Products of floats are exact in double, so the area's shoelace terms carry no rounding there.
    const acc2 g = areaGradient(exactly(motion[previousIn(i, first, count)].xy), q);
    const acc2 u = heldAt(HOLD_PASS, motion, i, first, count) ? (acc2)(0) : correctionDirection(g, shortEdge);
    const acc2 after = exactly(motion[nextIn(b, first, count)].xy);
    const acc2 uNext = heldAt(HOLD_PASS, motion, b, first, count) ? (acc2)(0)
                                                                  : correctionDirection(areaGradient(p, after), shortEdge);
    return (acc4)(crossWide(p, q), dot(g, u), crossWide(u, uNext), 0);
}

#define VF_ADD(a, b) ((a) + (b))
VF_DEFINE_LOCAL_REDUCE(acc4, sumAcc4, VF_ADD)

VF_KERNEL void contourTermTiles(int mode, float2 point, float shortEdge, HOLD_ARGS, __global const float4 *motion,
                                CONTOUR_ARGS, uint n, __global acc4 *tileTotals)
{
    __local acc4 scratch[VF_SCAN_SCRATCH];
    const uint i = get_global_id(0);
    acc4 terms = 0;
    if (i < n) {
        const uint c = contourOf[i];
        terms = contourTerms(mode, point, shortEdge, HOLD_PASS, motion, i, contourOffset[c], contourCount[c]);
    }
    const acc4 total = VF_LOCAL_REDUCE(sumAcc4)(scratch, terms);
    if (get_local_id(0) == 0)
        tileTotals[get_group_id(0)] = total;
}

// The λ of AreaCorrection: A(λ) = A + λ·Σ g·u + λ²·A(u) = target, the root nearest zero.
VF_INLINE acc_t areaLambda(acc_t area, acc_t rate, acc_t directionArea, acc_t target)
{
    if (rate <= 0)
        return 0;
    const acc_t a = directionArea, b = rate, c = area - target;
    const acc_t disc = b * b - 4 * a * c;
    if (disc < 0)
        return 0;
    return -2 * c / (b + sqrt(disc));  // the numerically stable form of the smaller root
}

// Per contour: in TERMS_AREA mode the area correction's λ (at most `maxOffset` either way), in
// TERMS_WINDING mode the target area grows by winding number × `dropArea`.
VF_KERNEL void contourTermSums(int mode, float2 point, float shortEdge, HOLD_ARGS, float maxOffset, acc_t dropArea,
                               __global const float4 *motion,
                               __global const uint *contourOffset, __global const uint *contourCount, uint contours,
                               __global const acc4 *tileTotals, __global acc_t *targetArea, __global acc_t *lambda)
{
    const uint c = get_global_id(0);
    if (c >= contours)
        return;
    const uint first = contourOffset[c], count = contourCount[c], end = first + count;
    const uint wholeFrom = (first + VF_LOCAL - 1) / VF_LOCAL, wholeTo = end / VF_LOCAL;  // tiles inside
    acc4 sum = 0;
    if (wholeFrom < wholeTo) {
        for (uint i = first; i < wholeFrom * VF_LOCAL; ++i)
            sum += contourTerms(mode, point, shortEdge, HOLD_PASS, motion, i, first, count);
        for (uint t = wholeFrom; t < wholeTo; ++t)
            sum += tileTotals[t];
        for (uint i = wholeTo * VF_LOCAL; i < end; ++i)
            sum += contourTerms(mode, point, shortEdge, HOLD_PASS, motion, i, first, count);
    } else {
        for (uint i = first; i < end; ++i)
            sum += contourTerms(mode, point, shortEdge, HOLD_PASS, motion, i, first, count);
    }
    if (mode == TERMS_WINDING)
        targetArea[c] += sum.x * dropArea;
    else
        lambda[c] = count < 3 ? 0
                              : clamp(areaLambda((acc_t)0.5 * sum.x, sum.y, (acc_t)0.5 * sum.z, targetArea[c]),
                                      -(acc_t)maxOffset, (acc_t)maxOffset);
}

VF_KERNEL void correctArea(float shortEdge, HOLD_ARGS, __global const float4 *motion, CONTOUR_ARGS, uint n,
                           __global const acc_t *lambda, __global float4 *corrected)
{
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const uint c = contourOf[i], first = contourOffset[c], count = contourCount[c];
    const float4 m = motion[i];
    if (heldAt(HOLD_PASS, motion, i, first, count)) {
        corrected[i] = m;
        return;
    }
    const acc2 before = exactly(motion[previousIn(i, first, count)].xy), after = exactly(motion[nextIn(i, first, count)].xy);
    const acc2 g = areaGradient(before, after);
    const acc2 p = exactly(m.xy) + lambda[c] * correctionDirection(g, shortEdge);
    corrected[i] = (float4)((float)p.x, (float)p.y, m.zw);
}
