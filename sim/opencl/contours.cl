// The contour store of DeviceContours and what every contour kernel shares: neighbours along a
// contour, the motion (RK4 through the flow, eq. 1, or an ink drop's push), advection, strain.
//
// Layout (sim/opencl/DeviceContours.cpp, docs/ARCHITECTURE.md "OpenCL contour tracking"): all
// contours live in flat arrays, each contour contiguous and in order, vertex i of the store
// belonging to contour contourOf[i], which occupies [contourOffset[c], contourOffset[c] +
// contourCount[c]). A vertex's neighbours are i ± 1 wrapped inside that range. motion[i] holds
// (position, previous): the position now and at the start of the current motion, which the
// time-rewinding split (eq. 2) needs.
//
// Requires flow.h.cl and a flow definition (flowVelocity, flowVorticity), and workgroup.cl.

typedef VF_ACC acc_t;  // accumulations: double where the device has fp64, else float
typedef VF_ACC2 acc2;
typedef VF_ACC4 acc4;

#define CONTOUR_ARGS                                                                           \
    __global const uint *contourOf, __global const uint *contourOffset, __global const uint *contourCount

// How vertices move in this step: through the flow from t0 to t1 (RK4), or by an ink drop's push.
// `rewind` is TrackingSettings::timeRewinding: where a split vertex goes (eq. 2 or the chord).
#define MOTION_FLOW 0
#define MOTION_DROP 1
#define MOTION_ARGS int motionKind, float2 dropCentre, float dropRadius, int rewind
#define MOTION_PASS motionKind, dropCentre, dropRadius, rewind

// Words of the status buffer the host reads once per pass. Flags are raised with atomic_or, the
// strain with atomic_max on the bits of a non-negative float: both results are independent of the
// order in which work-items arrive.
#define STATUS_STICKY 0  // flags kept over the whole step
#define STATUS_PASS 1    // flags of the current refinement pass
#define STATUS_STRAIN 2
#define FLAG_NON_FINITE 1u
#define FLAG_SPLIT_MISMATCH 2u
#define FLAG_SHORT_EDGE(colour) (1u << (colour))  // a short edge touches a vertex of that colour
#define FLAG_RECENTRED 8u
#define FLAG_SPLIT_CAPPED 16u

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

// Eq. 1: one classic fourth-order Runge–Kutta step over the flow's span [t0, t0 + dt], from the
// velocity k1 at p at t0.
VF_INLINE float2 rungeKutta4From(FLOW_PARAMS, float2 p, float2 k1)
{
    const float h = 0.5f * dt;
    const float2 k2 = flowVelocity(FLOW_PASS, p + h * k1, 0.5f);
    const float2 k3 = flowVelocity(FLOW_PASS, p + h * k2, 0.5f);
    const float2 k4 = flowVelocity(FLOW_PASS, p + dt * k3, 1.0f);
    return p + (dt / 6.0f) * (k1 + 2.0f * k2 + 2.0f * k3 + k4);
}

VF_INLINE float2 rungeKutta4(FLOW_PARAMS, float2 p)
{
    return rungeKutta4From(FLOW_PASS, p, flowVelocity(FLOW_PASS, p, 0.0f));
}

// The drop's push P → C + (P−C)·sqrt(1 + r²/|P−C|²), area-preserving outside the disc.
VF_INLINE float2 dropPush(float2 centre, float radius, float2 p)
{
    const float2 d = p - centre;
    const float l2 = dot(d, d);
    if (l2 == 0.0f)
        return centre + (float2)(radius, 0.0f);  // the centre itself: any direction is as good
    return centre + d * sqrt(1.0f + radius * radius / l2);
}

// Where a point that sat at `start` when the motion began is now.
VF_INLINE float2 moved(FLOW_PARAMS, MOTION_ARGS, float2 start)
{
    return motionKind == MOTION_DROP ? dropPush(dropCentre, dropRadius, start) : rungeKutta4(FLOW_PASS, start);
}

// With `startKnown` (a flow motion only), startVelocity[i] is the flow's velocity at vertex i at
// t0, sampled by the strain check: RK4's first stage, bit for bit.
VF_KERNEL void advect(FLOW_ARGS, MOTION_ARGS, __global float4 *motion, uint n, __global const float2 *startVelocity,
                      int startKnown, __global uint *status)
{
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const float2 start = motion[i].xy;
    const float2 p =
        startKnown ? rungeKutta4From(FLOW_PASS, start, startVelocity[i]) : moved(FLOW_PASS, MOTION_PASS, start);
    if (!isfinite(p.x) || !isfinite(p.y))
        atomic_or(&status[STATUS_STICKY], FLAG_NON_FINITE);
    motion[i] = (float4)(p, start);
}

// The positions alone, packed for a display's readback (DeviceContours::requestRead).
VF_KERNEL void positionsOf(__global const float4 *motion, uint n, __global float2 *positions)
{
    const uint i = get_global_id(0);
    if (i < n)
        positions[i] = motion[i].xy;
}

VF_DEFINE_LOCAL_REDUCE(float, maxFloat, fmax)

// Largest |u(v_b) − u(v_a)|·stepLength / d_e over the edges (ContourTracker::strainInSpacings),
// with the flow at the end of its span. Each vertex samples the flow once, and leaves the sample
// in velocityAt for the advection's first stage; the next vertex's velocity comes from its
// neighbour in the work-group, sampled again only across a tile or a contour's closing edge.
VF_KERNEL void strain(FLOW_ARGS, float stepLength, __global const float4 *motion, __global const float *spacing,
                      CONTOUR_ARGS, uint n, __global float2 *velocityAt, __global uint *status)
{
    __local float2 velocity[VF_LOCAL];
    __local float scratch[VF_SCAN_SCRATCH];
    const uint i = get_global_id(0), lid = get_local_id(0);
    const float2 u = i < n ? flowVelocity(FLOW_PASS, motion[i].xy, 1.0f) : (float2)(0.0f);
    if (i < n)
        velocityAt[i] = u;
    velocity[lid] = u;
    barrier(CLK_LOCAL_MEM_FENCE);
    float s = 0.0f;
    if (i < n) {
        const uint c = contourOf[i];
        const uint j = nextIn(i, contourOffset[c], contourCount[c]);
        const float2 uj =
            j == i + 1 && lid + 1 < VF_LOCAL ? velocity[lid + 1] : flowVelocity(FLOW_PASS, motion[j].xy, 1.0f);
        s = distance(u, uj) * stepLength / (0.5f * (spacing[i] + spacing[j]));
    }
    const float worst = VF_LOCAL_REDUCE(maxFloat)(scratch, s);
    if (lid == 0)
        atomic_max(&status[STATUS_STRAIN], as_uint(worst));
}
