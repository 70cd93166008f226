#pragma once
// The contract between the flow and the contour kernels on the device.
//
// Every contour kernel that needs the velocity takes, in this order, the arguments
//     __global const float* u0, __global const float* v0,   // staggered field at time t0, then
//                                                           // (fluid) the field halfway to t1
//     __global const float* u1, __global const float* v1,   // staggered field at time t1; u1
//                                                           // then (fluid) its corner vorticity
//     int nx, int ny, float hx, float hy, float t0, float dt
// (FLOW_ARGS in flow.h.cl) and samples through
//     float2 flowVelocity(FLOW_PARAMS, float2 p, float s);
//     float  flowVorticity(FLOW_PARAMS, float2 p, float s);
// and, for VF_LANES points at once (the lane kernels, flow.h.cl),
//     void   flowVelocityLanes(FLOW_PARAMS, floatv x, floatv y, float s, floatv* u, floatv* v);
//     floatv flowVorticityLanes(FLOW_PARAMS, floatv x, floatv y, float s);
// where s is how far through the span [t0, t0 + dt] (0 … 1; an empty span means its end). The
// span's length is computed here in double: t1 − t0 in float would lose digits as time grows.
// The program prepends one definition of these functions (a flow without lane samplers of its own
// ends with VF_DEFINE_LANES_BY_LANE, which samples lane by lane): flow_fluid.cl (bilinear MAC
// sampling, linear in time between t0 and t1, as sim/FluidFlow, with the halfway field after the
// start field in u0 and v0 so that RK4's middle stages sample one field, not two, and the end
// field's vorticity at the cell corners after it in u1) or the analytic
// flow's expressions translated to OpenCL C (sim/opencl/AnalyticSource). Analytic flows ignore the
// buffers, which are then 1-element placeholders.
#include "sim/opencl/OpenCl.h"

namespace vf::sim::opencl {

struct FlowBinding {
    cl::Buffer u0, v0, u1, v1;
    int nx = 1, ny = 1;
    float hx = 1.0f, hy = 1.0f;
    double t0 = 0.0, t1 = 0.0;

    // Sets the 10 flow arguments of `kernel` starting at argument `first`; returns the next index.
    cl_uint bind(cl::Kernel& kernel, cl_uint first) const
    {
        kernel.setArg(first++, u0);
        kernel.setArg(first++, v0);
        kernel.setArg(first++, u1);
        kernel.setArg(first++, v1);
        kernel.setArg(first++, nx);
        kernel.setArg(first++, ny);
        kernel.setArg(first++, hx);
        kernel.setArg(first++, hy);
        kernel.setArg(first++, float(t0));
        kernel.setArg(first++, float(t1 - t0));
        return first;
    }
};

} // namespace vf::sim::opencl
