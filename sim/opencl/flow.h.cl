// Shared by every program that samples a flow (see sim/opencl/FlowBinding.h). The flow covers the
// span [t0, t0 + dt]; samplers take s, how far through the span (0 … 1), so that step lengths
// never come from differences of large float times.
#define FLOW_ARGS                                                                              \
    __global const float *u0, __global const float *v0, __global const float *u1,              \
        __global const float *v1, int nx, int ny, float hx, float hy, float t0, float dt
#define FLOW_PARAMS FLOW_ARGS
#define FLOW_PASS u0, v0, u1, v1, nx, ny, hx, hy, t0, dt
