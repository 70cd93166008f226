// Shared by every program that samples a flow (see sim/opencl/FlowBinding.h). The flow covers the
// span [t0, t0 + dt]; samplers take s, how far through the span (0 … 1), so that step lengths
// never come from differences of large float times.
#define FLOW_ARGS __global const float *flowField, int nx, int ny, float hx, float hy, float t0, float dt
#define FLOW_PARAMS FLOW_ARGS
#define FLOW_PASS flowField, nx, ny, hx, hy, t0, dt

#ifndef VF_INLINE
#define VF_INLINE inline __attribute__((always_inline))
#endif

// Lanes: the contour kernels (all but the proximity search) give each work-item VF_LANES
// consecutive vertices, as vectors x and y apart where they do the same to each. PoCL vectorises
// no work-item loop of those kernels (LLVM's SLP pass turns neighbouring loads into float2 before
// PoCL's loop vectoriser sees them, and that vectoriser refuses vector values), and RK4's four
// dependent samples leave a CPU core waiting on latency. As eight lanes the same arithmetic runs
// about 2.7 times faster on PoCL. The lane code is written for eight (float8, and float16 loads of
// whole groups in contours.cl); `lanes` in Launch.h is the same number.
#define VF_LANES 8
typedef float8 floatv;
typedef int8 intv;
#define VF_CONVERT_FLOATV convert_float8
#define VF_CONVERT_INTV convert_int8
#define VF_VLOAD vload8
#define VF_VSTORE vstore8

// f[k] for every lane's k.
VF_INLINE floatv gatherLanes(__global const float *f, intv k)
{
    return (floatv)(f[k.s0], f[k.s1], f[k.s2], f[k.s3], f[k.s4], f[k.s5], f[k.s6], f[k.s7]);
}

// For flows that have no lane sampler of their own (the analytic flows): flowVelocityLanes and
// flowVorticityLanes from flowVelocity and flowVorticity, one lane after the other.
#define VF_DEFINE_LANES_BY_LANE                                                                \
    VF_INLINE void flowVelocityLanes(FLOW_PARAMS, floatv x, floatv y, float s, floatv *u, floatv *v) \
    {                                                                                          \
        float xs[VF_LANES], ys[VF_LANES], us[VF_LANES], vs[VF_LANES];                          \
        VF_VSTORE(x, 0, xs);                                                                   \
        VF_VSTORE(y, 0, ys);                                                                   \
        for (int k = 0; k < VF_LANES; ++k) {                                                   \
            const float2 w = flowVelocity(FLOW_PASS, (float2)(xs[k], ys[k]), s);               \
            us[k] = w.x;                                                                       \
            vs[k] = w.y;                                                                       \
        }                                                                                      \
        *u = VF_VLOAD(0, us);                                                                  \
        *v = VF_VLOAD(0, vs);                                                                  \
    }                                                                                          \
    VF_DEFINE_VORTICITY_BY_LANE(flowVorticityLanes)

// NAME(FLOW_PARAMS, x, y, s): flowVorticity of each lane, one after the other.
#define VF_DEFINE_VORTICITY_BY_LANE(NAME)                                                      \
    VF_INLINE floatv NAME(FLOW_PARAMS, floatv x, floatv y, float s)                            \
    {                                                                                          \
        float xs[VF_LANES], ys[VF_LANES];                                                      \
        VF_VSTORE(x, 0, xs);                                                                   \
        VF_VSTORE(y, 0, ys);                                                                   \
        for (int k = 0; k < VF_LANES; ++k)                                                     \
            xs[k] = flowVorticity(FLOW_PASS, (float2)(xs[k], ys[k]), s);                       \
        return VF_VLOAD(0, xs);                                                                \
    }
