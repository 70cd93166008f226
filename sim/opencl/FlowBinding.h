#pragma once
// The contract between the flow and the contour kernels on the device.
//
// Every contour kernel that needs the velocity takes, in this order, the arguments
//     __global const float* flowField,   // the flow's data; (fluid) its stream functions
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
// ends with VF_DEFINE_LANES_BY_LANE, which samples lane by lane): flow_fluid.cl (the curl of the
// cubic B-spline stream function of the fluid's field, as sim/StreamFunction, linear in time
// between t0 and t1 as sim/FluidFlow; flowField holds the stream functions at the step's start,
// halfway through it and at its end, so RK4's middle stages sample one field, not two) or the
// analytic flow's expressions translated to OpenCL C (sim/opencl/AnalyticSource), which ignore
// flowField, then a 1-element placeholder.
#include "sim/opencl/OpenCl.h"

namespace vf::sim::opencl {

struct FlowBinding {
    cl::Buffer field;
    int nx = 1, ny = 1;
    float hx = 1.0f, hy = 1.0f;
    double t0 = 0.0, t1 = 0.0;

    // Sets the 7 flow arguments of `kernel` starting at argument `first`; returns the next index.
    cl_uint bind(cl::Kernel& kernel, cl_uint first) const
    {
        kernel.setArg(first++, field);
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
