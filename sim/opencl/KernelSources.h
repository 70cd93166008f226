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

// The SHA-1 of every kernel file's name and text, taken when they were embedded: what compiled
// kernels depend on, beside the device and its driver.
std::string_view kernelSourcesDigest();

} // namespace vf::sim::opencl
