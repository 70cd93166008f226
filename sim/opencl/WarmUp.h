#pragma once
// A device's kernels compiled before a session needs them. PoCL compiles each kernel for its local
// size at its first launch (about a second each on a CPU) and keeps the result in its cache, so on
// a fresh installation a session's first steps, drop and comb would each stall for seconds.
// warmUpKernels launches them through a small session of its own, so that a caller (the app) can
// run the reference backend meanwhile and move to the device once they are compiled.
#include <atomic>
#include <optional>
#include <string>

namespace vf::sim::opencl {

// What compiled kernels depend on: the embedded sources (their digest), the device and its driver.
// Where a warm-up was made for the same identity, its kernels are already compiled and cached.
// Throws DeviceError where there is no such device.
std::string kernelIdentity(std::optional<int> device);

// Runs the small session on the device: fluid steps with a stylus and area correction, a pinch cut,
// a drop, a comb, a snapshot restored and a frame read back. `stop` is looked at between them (each
// compiles a few kernels at most). Throws DeviceError as the backend does.
void warmUpKernels(std::optional<int> device, const std::atomic<bool>& stop);

} // namespace vf::sim::opencl
