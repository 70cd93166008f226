// The contour store of DeviceContours and what every contour kernel shares: neighbours along a
// contour, the motion (RK4 through the flow, eq. 1, or an ink drop's push), advection, strain.
//
// Layout (sim/opencl/DeviceContours.cpp, docs/opencl-backend.md, "Storage"): all
// contours live in flat arrays, each contour contiguous and in order, vertex i of the store
// belonging to contour contourOf[i], which occupies [contourOffset[c], contourOffset[c] +
// contourCount[c]). A vertex's neighbours are i ± 1 wrapped inside that range. motion[i] holds
// (position, previous): the position now and at the start of the current motion, which the
// time-rewinding split (eq. 2) needs.
//
// Requires flow.h.cl and a flow definition (flowVelocity, flowVorticity and their lane forms,
// FlowBinding.h), and workgroup.cl.

typedef VF_ACC acc_t;  // accumulations: double where the device has fp64, else float
typedef VF_ACC2 acc2;
typedef VF_ACC4 acc4;

#define CONTOUR_ARGS                                                                           \
    __global const uint *contourOf, __global const uint *contourOffset, __global const uint *contourCount

// How vertices move in this step: through the flow from t0 to t1 (RK4, motionKind MOTION_FLOW), by
// an ink drop's push (MOTION_DROP: mapA is the centre and the radius), or by a tool's map
// (MOTION_COMB, MOTION_CIRCULAR_COMB, MOTION_SWIRL: mapA to mapC its parameters, below).
// `rewind` is TrackingSettings::timeRewinding: where a split vertex goes (eq. 2 or the chord). A
// map is depicted within `chordTolerance` (ExactMotion in sim/ContourTracker.h; 0 for the flow).
// MOTION_*, STATUS_*, FLAG_* and TERMS_* are defined by the host as build options
// (ContourCodes.h).
#define MOTION_ARGS int motionKind, acc4 mapA, acc4 mapB, acc4 mapC, int rewind, float chordTolerance
#define MOTION_PASS motionKind, mapA, mapB, mapC, rewind, chordTolerance

// Words of the status buffer the host reads once per pass. Flags are raised with atomic_or, the
// strain with atomic_max on the bits of a non-negative float: both results are independent of the
// order in which work-items arrive. STATUS_STICKY holds flags kept over the whole step
// (FLAG_NON_FINITE, FLAG_SPLIT_MISMATCH), STATUS_PASS those of the current refinement pass
// (FLAG_SHORT_EDGE, FLAG_RECENTRED, FLAG_SPLIT_CAPPED), STATUS_STRAIN the strain; STATUS_ACROSS
// and STATUS_OVERFLOW are the collapse's (contours_refine.cl).
#define FLAG_SHORT_EDGE(colour) (FLAG_SHORT_EDGE_0 << (colour))  // a short edge touches a vertex of that colour

VF_DEFINE_LOCAL_SCAN(uint)
VF_DEFINE_LOCAL_SCAN(float)

VF_INLINE uint nextIn(uint i, uint first, uint count)
{
    return i + 1 == first + count ? first : i + 1;
}

VF_INLINE uint previousIn(uint i, uint first, uint count)
{
    return i == first ? first + count - 1 : i - 1;
}

// The vertex `k` places along the contour from `i` (any k, any contour size).
VF_INLINE uint stepAlong(uint i, int k, uint first, uint count)
{
    int at = (int)(i - first) + k;
    if (at < 0 || at >= (int)count)
        at = (at % (int)count + (int)count) % (int)count;
    return first + (uint)at;
}

VF_INLINE float cross2(float2 a, float2 b)
{
    return a.x * b.y - a.y * b.x;
}

// The one-point sampler in the shape of the lane sampler, for the Runge–Kutta template below.
VF_INLINE void flowVelocityOne(FLOW_PARAMS, float x, float y, float s, float *u, float *v)
{
    const float2 w = flowVelocity(FLOW_PASS, (float2)(x, y), s);
    *u = w.x;
    *v = w.y;
}

// Eq. 1: one classic fourth-order Runge–Kutta step over the flow's span [t0, t0 + dt] from (x, y),
// whose velocity at t0 is k1; written once for one point (float, One) and for lanes (floatv,
// Lanes).
#define VF_DEFINE_RUNGE_KUTTA4(T, S)                                                           \
    VF_INLINE void rungeKutta4From##S(FLOW_PARAMS, T x, T y, T k1x, T k1y, T *endX, T *endY)   \
    {                                                                                          \
        const float h = 0.5f * dt;                                                             \
        T k2x, k2y, k3x, k3y, k4x, k4y;                                                        \
        flowVelocity##S(FLOW_PASS, x + h * k1x, y + h * k1y, 0.5f, &k2x, &k2y);                \
        flowVelocity##S(FLOW_PASS, x + h * k2x, y + h * k2y, 0.5f, &k3x, &k3y);                \
        flowVelocity##S(FLOW_PASS, x + dt * k3x, y + dt * k3y, 1.0f, &k4x, &k4y);              \
        *endX = x + (dt / 6.0f) * (k1x + 2.0f * k2x + 2.0f * k3x + k4x);                       \
        *endY = y + (dt / 6.0f) * (k1y + 2.0f * k2y + 2.0f * k3y + k4y);                       \
    }
VF_DEFINE_RUNGE_KUTTA4(float, One)
VF_DEFINE_RUNGE_KUTTA4(floatv, Lanes)

VF_INLINE float2 rungeKutta4(FLOW_PARAMS, float2 p)
{
    float k1x, k1y, x, y;
    flowVelocityOne(FLOW_PASS, p.x, p.y, 0.0f, &k1x, &k1y);
    rungeKutta4FromOne(FLOW_PASS, p.x, p.y, k1x, k1y, &x, &y);
    return (float2)(x, y);
}

// The maps are evaluated in acc_t (double on fp64 devices) from the float positions, and their
// parameters come in acc_t: a comb shears tens of times across its tines, so a float evaluation
// would place vertices near a tine as far off as the float spacing times the shear, across edges
// shorter than that (a fold), and its inverse would not return the ink within the tolerance.
VF_INLINE acc2 exactly(float2 p)
{
    return (acc2)((acc_t)p.x, (acc_t)p.y);
}

VF_INLINE float2 rounded(acc2 p)
{
    return (float2)((float)p.x, (float)p.y);
}

// The drop's push P → C + (P−C)·sqrt(1 + r²/|P−C|²), area-preserving outside the disc.
VF_INLINE acc2 dropPush(acc2 centre, acc_t radius, acc2 p)
{
    const acc2 d = p - centre;
    const acc_t l2 = dot(d, d);
    if (l2 == 0)
        return centre + (acc2)(radius, (acc_t)0);  // the centre itself: any direction is as good
    return centre + d * sqrt(1 + radius * radius / l2);
}

// sim::Comb: mapA is `from` and the unit direction M, mapB the length z, the sharpness, the
// spacing and the tine count, mapC the wave: amplitude, 2π/wavelength and the phase at the origin.
// A wavy comb's wave at p, across the stroke: sign −1 waves the plane, +1 unwaves it.
VF_INLINE acc2 combWaved(acc4 line, acc4 wave, acc2 p, acc_t sign)
{
    const acc2 along = line.zw;
    return p + sign * wave.x * sin(wave.y * dot(p, along) + wave.z) * (acc2)(-along.y, along.x);
}

// The comb's map (sim/Comb.cpp): waved, sheared along M by z·u/(d + u) for each tine, d the
// distance to its line, and unwaved.
VF_INLINE acc2 combShift(acc4 line, acc4 shape, acc4 wave, acc2 p)
{
    const acc2 from = line.xy, along = line.zw, across = (acc2)(-along.y, along.x);
    const acc2 straight = combWaved(line, wave, p, -1);
    const int tines = (int)shape.w;
    acc_t shift = 0;
    for (int k = 0; k < tines; ++k) {
        const acc2 tine = from + ((acc_t)k - (acc_t)0.5 * (acc_t)(tines - 1)) * shape.z * across;
        shift += shape.x * shape.y / (fabs(dot(straight - tine, across)) + shape.y);
    }
    return combWaved(line, wave, straight + shift * along, 1);
}

// sim::wholeCrossing: where w, linear from wa to wb, passes strictly a whole number in [0, last],
// the one nearest the middle, as the fraction there, or -1.
VF_INLINE float wholeCrossing(acc_t wa, acc_t wb, acc_t last)
{
    const acc_t first = fmax(floor(fmin(wa, wb)) + 1, (acc_t)0), final = fmin(ceil(fmax(wa, wb)) - 1, last);
    if (!(first <= final))
        return -1.0f;
    return (float)((clamp(rint((acc_t)0.5 * (wa + wb)), first, final) - wa) / (wb - wa));
}

// Comb::tineCrossing: where the segment a–b crosses a tine's line (the crossing nearest its middle),
// as a fraction along it, or -1.
VF_INLINE float tineCrossing(acc4 line, acc4 shape, acc4 wave, acc2 a, acc2 b)
{
    a = combWaved(line, wave, a, -1);
    b = combWaved(line, wave, b, -1);
    const acc2 across = (acc2)(-line.w, line.z);
    const int tines = (int)shape.w;
    const acc_t unit = shape.z > 0 ? shape.z : 1, last = shape.z > 0 ? (acc_t)(tines - 1) : 0;
    const acc2 firstTine = line.xy - (acc_t)0.5 * (acc_t)(tines - 1) * shape.z * across;
    return wholeCrossing(dot(a - firstTine, across) / unit, dot(b - firstTine, across) / unit, last);
}

// p turned about `centre` by `angle`.
VF_INLINE acc2 turned(acc2 p, acc2 centre, acc_t angle)
{
    const acc_t c = cos(angle), s = sin(angle);
    const acc2 d = p - centre;
    return centre + (acc2)(c * d.x - s * d.y, s * d.x + c * d.y);
}

// sim::CircularComb (sim/Whirl.h): mapA is the centre, the first tine's radius and the spacing,
// mapB the angle, the sharpness and the tine count.
VF_INLINE acc2 circularComb(acc4 rings, acc4 pull, acc2 p)
{
    const acc_t rho = distance(p, rings.xy);
    acc_t theta = 0;
    for (int k = 0; k < (int)pull.z; ++k)
        theta += pull.x * pull.y / (fabs(rho - (rings.z + (acc_t)k * rings.w)) + pull.y);
    return turned(p, rings.xy, theta);
}

// CircularComb::tineCrossing: where the segment a–b crosses a tine's circle, ρ taken as linear.
VF_INLINE float ringCrossing(acc4 rings, acc4 pull, acc2 a, acc2 b)
{
    const acc_t unit = rings.w > 0 ? rings.w : 1, last = rings.w > 0 ? pull.z - 1 : 0;
    return wholeCrossing((distance(a, rings.xy) - rings.z) / unit, (distance(b, rings.xy) - rings.z) / unit, last);
}

// sim::Swirl: mapA is the centre, the radius and the angle.
VF_INLINE acc2 swirl(acc4 vortex, acc2 p)
{
    const acc_t rho = distance(p, vortex.xy) / vortex.z;
    return turned(p, vortex.xy, vortex.w * exp(-rho * rho));
}

// Where a map (a drop or a tool's, not the flow) takes `start`.
VF_INLINE float2 mapped(MOTION_ARGS, float2 start)
{
    const acc2 p = exactly(start);
    switch (motionKind) {
    case MOTION_DROP:
        return rounded(dropPush(mapA.xy, mapA.z, p));
    case MOTION_COMB:
        return rounded(combShift(mapA, mapB, mapC, p));
    case MOTION_CIRCULAR_COMB:
        return rounded(circularComb(mapA, mapB, p));
    default:
        return rounded(swirl(mapA, p));
    }
}

// Where the segment a–b crosses a crease of the map, as a fraction along it, or -1.
VF_INLINE float creaseCrossing(MOTION_ARGS, float2 a, float2 b)
{
    if (motionKind == MOTION_COMB)
        return tineCrossing(mapA, mapB, mapC, exactly(a), exactly(b));
    return motionKind == MOTION_CIRCULAR_COMB ? ringCrossing(mapA, mapB, exactly(a), exactly(b)) : -1.0f;
}

// Whether a map is depicted within its chord tolerance (the flow is not).
VF_INLINE bool depictedExactly(MOTION_ARGS)
{
    return motionKind != MOTION_FLOW && rewind && chordTolerance > 0.0f;
}

// ContourTracker's chordTolerances: how far the chord of the edge (position, previous position)
// left–right may stray from the curve, now (x) and at the start of the motion (y). A tool's map
// keeps areas, so a stray across an edge widens by what the map presses the edge along, and by
// what it stretches it when the inverse undoes the map.
VF_INLINE float2 chordTolerances(MOTION_ARGS, float4 left, float4 right)
{
    const float before = distance(left.zw, right.zw);
    if (motionKind == MOTION_DROP || !(before > 0.0f))
        return (float2)(chordTolerance);
    const float stretch = distance(left.xy, right.xy) / before;
    return (float2)(chordTolerance / clamp(stretch, 1.0f, 8.0f), chordTolerance * fmin(stretch, 1.0f));
}

// Whether x lies farther than `tolerance` from the segment a–b. The tolerance is at least two
// roundings of the coordinates: below that, a float cannot tell a stray from its rounding.
VF_INLINE bool straysFrom(float tolerance, float2 x, float2 a, float2 b)
{
    const float2 reach = fmax(fmax(fabs(a), fabs(b)), fabs(x));
    const float resolved = fmax(tolerance, 2.0f * FLT_EPSILON * fmax(reach.x, reach.y));
    const float2 edge = b - a, toX = x - a;
    const float along = clamp(dot(toX, edge) / fmax(dot(edge, edge), FLT_MIN), 0.0f, 1.0f);
    const float2 off = toX - along * edge;
    return dot(off, off) > resolved * resolved;
}

// Whether fraction s of the segment a–b lies farther from both its ends than eight roundings of the
// coordinates: a crease not yet on a vertex (one placed on it is found again some roundings off).
VF_INLINE bool creaseInside(float2 a, float2 b, float s)
{
    const float2 reach = fmax(fabs(a), fabs(b));
    return fmin(s, 1.0f - s) * distance(a, b) > 8.0f * FLT_EPSILON * fmax(reach.x, reach.y);
}

// ContourTracker's splitPoint: where the edge (position, previous position) left–right needs a
// vertex, as a fraction along it, or -1. A map depicted exactly puts one at a crease inside it (a
// hairpin's tip) or where its chord strays from the mapped curve at the crease; else an edge gets
// one in the middle when it is longer than its spacing (`tooLong`) or, for a map depicted exactly,
// when its chord strays there.
VF_INLINE float splitPoint(MOTION_ARGS, float4 left, float4 right, bool tooLong)
{
    if (!depictedExactly(MOTION_PASS))
        return tooLong ? 0.5f : -1.0f;
    const float s = creaseCrossing(MOTION_PASS, left.zw, right.zw);
    const float tolerance = chordTolerances(MOTION_PASS, left, right).x;
    if (s >= 0.0f && (creaseInside(left.zw, right.zw, s) ||
                      straysFrom(tolerance, mapped(MOTION_PASS, mix(left.zw, right.zw, s)), left.xy, right.xy)))
        return s;
    return tooLong || straysFrom(tolerance, mapped(MOTION_PASS, 0.5f * (left.zw + right.zw)), left.xy, right.xy)
               ? 0.5f
               : -1.0f;
}

// Where a point that sat at `start` when the motion began is now.
VF_INLINE float2 moved(FLOW_PARAMS, MOTION_ARGS, float2 start)
{
    return motionKind == MOTION_FLOW ? rungeKutta4(FLOW_PASS, start) : mapped(MOTION_PASS, start);
}

// Work-item g's lanes hold vertices VF_LANES·g + k (k < VF_LANES); those past the last vertex repeat
// it, and what they compute is dropped.
VF_INLINE uint laneVertex(uint g, int k, uint n)
{
    return min(VF_LANES * g + (uint)k, n - 1);
}

// Whether every lane of work-item g holds a vertex.
VF_INLINE bool wholeGroup(uint g, uint n)
{
    return VF_LANES * g + VF_LANES <= n;
}

// Whether the vertices from … to (to < n) all lie on one contour: contours are contiguous, so the
// two ends tell. Then no vertex but `to` is its contour's last, and each one's next vertex is the
// one after it in the store.
VF_INLINE bool oneContour(__global const uint *contourOf, uint from, uint to, uint n)
{
    return to < n && contourOf[from] == contourOf[to];
}

// The first two floats of the VF_LANES (8) records from `first` on, in an array of 2 or 4 floats
// per vertex: one or two wide loads.
VF_INLINE void consecutiveLanes(__global const float *records, uint stride, uint first, floatv *x, floatv *y)
{
    __global const float *group = records + stride * first;
    if (stride == 4) {
        const float16 a = vload16(0, group), b = vload16(1, group);
        *x = (floatv)(a.s048c, b.s048c);
        *y = (floatv)(a.s159d, b.s159d);
    } else {
        const float16 a = vload16(0, group);
        *x = a.even;
        *y = a.odd;
    }
}

// The length of the edge from each of the VF_LANES vertices from `first` on to the vertex after it
// in the store (all on one contour: see oneContour).
VF_INLINE floatv edgesOnward(__global const float4 *motion, uint first)
{
    floatv x, y, nextX, nextY;
    consecutiveLanes((__global const float *)motion, 4, first, &x, &y);
    consecutiveLanes((__global const float *)motion, 4, first + 1, &nextX, &nextY);
    const floatv dx = nextX - x, dy = nextY - y;
    return sqrt(dx * dx + dy * dy);
}

// The first two floats of each lane's record in an array of 2 or 4 floats per vertex.
VF_INLINE void lanesOf(__global const float *records, uint stride, uint g, uint n, floatv *x, floatv *y)
{
    if (wholeGroup(g, n)) {
        consecutiveLanes(records, stride, VF_LANES * g, x, y);
        return;
    }
    float xs[VF_LANES], ys[VF_LANES];
    for (int k = 0; k < VF_LANES; ++k) {
        const uint at = stride * laneVertex(g, k, n);
        xs[k] = records[at];
        ys[k] = records[at + 1];
    }
    *x = VF_VLOAD(0, xs);
    *y = VF_VLOAD(0, ys);
}

// values[i] = each lane's value, for the lanes that hold a vertex.
VF_INLINE void storeLanes(__global float *values, uint g, uint n, floatv v)
{
    if (wholeGroup(g, n)) {
        VF_VSTORE(v, g, values);
        return;
    }
    float vs[VF_LANES];
    VF_VSTORE(v, 0, vs);
    for (int k = 0; k < VF_LANES && VF_LANES * g + k < n; ++k)
        values[VF_LANES * g + k] = vs[k];
}

// Launched over one work-item per VF_LANES vertices. With `startKnown` (a flow motion only),
// startVelocity[i] is the flow's velocity at vertex i at t0, sampled by the strain check: RK4's
// first stage, bit for bit.
VF_KERNEL void advect(FLOW_ARGS, MOTION_ARGS, __global float4 *motion, uint n, __global const float2 *startVelocity,
                      int startKnown, __global uint *status)
{
    const uint g = get_global_id(0);
    if (VF_LANES * g >= n)
        return;
    floatv x, y;
    lanesOf((__global const float *)motion, 4, g, n, &x, &y);
    floatv endX = x, endY = y;
    if (motionKind == MOTION_FLOW) {
        floatv k1x, k1y;
        if (startKnown)
            lanesOf((__global const float *)startVelocity, 2, g, n, &k1x, &k1y);
        else
            flowVelocityLanes(FLOW_PASS, x, y, 0.0f, &k1x, &k1y);
        rungeKutta4FromLanes(FLOW_PASS, x, y, k1x, k1y, &endX, &endY);
    }
    __global float4 *group = motion + VF_LANES * g;
    if (wholeGroup(g, n) && motionKind == MOTION_FLOW) {
        if (!all(isfinite(endX) & isfinite(endY)))
            atomic_or(&status[STATUS_STICKY], FLAG_NON_FINITE);
        vstore16((float16)(endX.s0, endY.s0, x.s0, y.s0, endX.s1, endY.s1, x.s1, y.s1,
                           endX.s2, endY.s2, x.s2, y.s2, endX.s3, endY.s3, x.s3, y.s3), 0, (__global float *)group);
        vstore16((float16)(endX.s4, endY.s4, x.s4, y.s4, endX.s5, endY.s5, x.s5, y.s5,
                           endX.s6, endY.s6, x.s6, y.s6, endX.s7, endY.s7, x.s7, y.s7), 1, (__global float *)group);
        return;
    }
    // The last group, or a map (one vertex at a time).
    float xs[VF_LANES], ys[VF_LANES], ends[2][VF_LANES];
    VF_VSTORE(x, 0, xs);
    VF_VSTORE(y, 0, ys);
    VF_VSTORE(endX, 0, ends[0]);
    VF_VSTORE(endY, 0, ends[1]);
    for (int k = 0; k < VF_LANES && VF_LANES * g + k < n; ++k) {
        const float2 start = (float2)(xs[k], ys[k]);
        const float2 p = motionKind == MOTION_FLOW ? (float2)(ends[0][k], ends[1][k]) : mapped(MOTION_PASS, start);
        if (!isfinite(p.x) || !isfinite(p.y))
            atomic_or(&status[STATUS_STICKY], FLAG_NON_FINITE);
        group[k] = (float4)(p, start);
    }
}

// The positions alone, packed for a display's readback (DeviceContours::requestRead).
VF_KERNEL void positionsOf(__global const float4 *motion, uint n, __global float2 *positions)
{
    const uint i = get_global_id(0);
    if (i < n)
        positions[i] = motion[i].xy;
}

// Contour surgery's new layout (DeviceContours::cutPinches): new vertex i is old vertex
// fromThenContour[i], of new contour newContour[i], which then replaces it.
VF_KERNEL void gatherVertices(__global const float4 *motion, __global const float *spacing, uint n,
                              __global const uint *newContour, __global float4 *toMotion, __global float *toSpacing,
                              __global uint *fromThenContour)
{
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const uint from = fromThenContour[i];
    toMotion[i] = motion[from];
    toSpacing[i] = spacing[from];
    fromThenContour[i] = newContour[i];
}

VF_DEFINE_LOCAL_REDUCE(float, maxFloat, fmax)

// Largest |u(v_b) − u(v_a)|·stepLength / d_e over the edges (ContourTracker::strainInSpacings),
// with the flow at the end of its span; launched over one work-item per VF_LANES vertices. Each
// vertex samples the flow once, and leaves the sample in velocityAt for the advection's first
// stage; an edge's far end takes its neighbour's sample, and samples it again only across a tile
// or a contour's closing edge.
VF_KERNEL void strain(FLOW_ARGS, float stepLength, __global const float4 *motion, __global const float *spacing,
                      CONTOUR_ARGS, uint n, __global float2 *velocityAt, __global uint *status)
{
    __local float2 firstLane[VF_LOCAL];
    __local float scratch[VF_SCAN_SCRATCH];
    const uint g = get_global_id(0), lid = get_local_id(0), first = VF_LANES * g;
    const bool active = first < n;
    floatv ux = (floatv)(0.0f), uy = (floatv)(0.0f);
    if (active) {
        floatv x, y;
        lanesOf((__global const float *)motion, 4, g, n, &x, &y);
        flowVelocityLanes(FLOW_PASS, x, y, 1.0f, &ux, &uy);
    }
    firstLane[lid] = (float2)(ux.s0, uy.s0);
    barrier(CLK_LOCAL_MEM_FENCE);
    float s = 0.0f;
    if (oneContour(contourOf, first, first + VF_LANES, n)) {
        // Each edge's far end is the next lane.
        const float2 after = lid + 1 < VF_LOCAL ? firstLane[lid + 1]
                                                : flowVelocity(FLOW_PASS, motion[first + VF_LANES].xy, 1.0f);
        const floatv dx = (floatv)(ux.s1234, ux.s567, after.x) - ux, dy = (floatv)(uy.s1234, uy.s567, after.y) - uy;
        const floatv edgeSpacing = 0.5f * (VF_VLOAD(0, spacing + first) + VF_VLOAD(0, spacing + first + 1));
        const floatv strains = sqrt(dx * dx + dy * dy) * stepLength / edgeSpacing;
        const float4 halves = fmax(strains.lo, strains.hi);
        s = fmax(0.0f, fmax(fmax(halves.x, halves.y), fmax(halves.z, halves.w)));  // NaN lanes drop out
        vstore16((float16)(ux.s0, uy.s0, ux.s1, uy.s1, ux.s2, uy.s2, ux.s3, uy.s3, ux.s4, uy.s4, ux.s5, uy.s5, ux.s6,
                           uy.s6, ux.s7, uy.s7),
                 0, (__global float *)(velocityAt + first));
    } else if (active) {
        float u[2][VF_LANES];
        VF_VSTORE(ux, 0, u[0]);
        VF_VSTORE(uy, 0, u[1]);
        for (int k = 0; k < VF_LANES && first + k < n; ++k) {
            const uint i = first + k, c = contourOf[i];
            const uint j = nextIn(i, contourOffset[c], contourCount[c]);
            const float2 ui = (float2)(u[0][k], u[1][k]);
            velocityAt[i] = ui;
            float2 uj;
            if (j == i + 1 && k + 1 < VF_LANES)
                uj = (float2)(u[0][k + 1], u[1][k + 1]);
            else if (j == i + 1 && lid + 1 < VF_LOCAL)
                uj = firstLane[lid + 1];
            else
                uj = flowVelocity(FLOW_PASS, motion[j].xy, 1.0f);
            s = fmax(s, distance(ui, uj) * stepLength / (0.5f * (spacing[i] + spacing[j])));
        }
    }
    const float worst = VF_LOCAL_REDUCE(maxFloat)(scratch, s);
    if (lid == 0)
        atomic_max(&status[STATUS_STRAIN], as_uint(worst));
}
