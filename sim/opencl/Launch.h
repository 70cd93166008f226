#pragma once
// Kernel launches with the fixed local size every kernel of the OpenCL backend is compiled for
// (reqd_work_group_size): PoCL compiles a kernel once per local size, so one size everywhere means
// one compilation, and GPUs get a full wavefront. Global sizes are rounded up; kernels check bounds.
#include "sim/opencl/FlowBinding.h"

#include <cstddef>
#include <string>

namespace vf::sim::opencl {

inline constexpr std::size_t localSize = 64;

// The contour kernels other than the proximity search take this many vertices per work-item:
// VF_LANES of flow.h.cl.
inline constexpr std::size_t lanes = 8;

inline std::size_t laneGroups(std::size_t vertices)
{
    return (vertices + lanes - 1) / lanes;
}

inline std::size_t roundUpToLocal(std::size_t items)
{
    return (items + localSize - 1) / localSize * localSize;
}

// The build options every program of the backend shares. -cl-denorms-are-zero: on x86, an operand
// below 2^-126 makes an arithmetic instruction take a microcode assist of about a hundred cycles,
// and the compiler applies vector instructions to whole float4 loads whose unused lanes are
// integer bits, such as a grid entry's contour index, which read as denormals (that stall was
// half of the proximity search's time on PoCL). No number the step cares about is that small,
// and a device that flushes them still gives the same result for the same input.
inline std::string commonBuildOptions(bool fp64)
{
    return "-cl-std=CL1.2 -cl-denorms-are-zero -DVF_LOCAL=" + std::to_string(localSize) + (fp64 ? " -DVF_FP64" : "");
}

inline void setKernelArg(cl::Kernel& kernel, cl_uint& index, const FlowBinding& flow)
{
    index = flow.bind(kernel, index);
}

template <typename T>
void setKernelArg(cl::Kernel& kernel, cl_uint& index, const T& value)
{
    kernel.setArg(index++, value);
}

// Sets `args` in order (a FlowBinding counts as its 10 arguments) and enqueues `kernel` over at
// least `items` work-items.
template <typename... Args>
void launch(cl::CommandQueue& queue, cl::Kernel& kernel, std::size_t items, const Args&... args)
{
    cl_uint index = 0;
    (setKernelArg(kernel, index, args), ...);
    queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(roundUpToLocal(items == 0 ? 1 : items)),
                               cl::NDRange(localSize));
}

} // namespace vf::sim::opencl
