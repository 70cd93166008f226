#pragma once
// The OpenCL C sources (sim/opencl/*.cl), embedded into the binary at build time.
#include <initializer_list>
#include <string>
#include <string_view>

namespace vf::sim::opencl {

// The text of the kernel file `name` (e.g. "contours.cl"); empty when there is no such file.
std::string_view kernelSource(std::string_view name);

// The named kernel files joined in order, as one program source. Throws std::logic_error for a
// name that is not embedded (a build mistake, not a user error).
std::string joinedKernelSources(std::initializer_list<std::string_view> names);

} // namespace vf::sim::opencl
