#pragma once
// The OpenCL device a simulation runs on: context, in-order queue, and program builds that report
// the compiler's log. Created on the thread that owns the simulation.
#include "sim/opencl/OpenCl.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace vf::sim::opencl {

// Anything that stops the OpenCL backend from running: no platform or device, a failed kernel
// build (with its log), an allocation the device cannot make. One line, the first of what()
// (a build log follows on later lines).
class DeviceError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Device {
public:
    // Picks the device: `index` into the `vectorfluid devices` listing when given, else the
    // environment variable VF_OPENCL_DEVICE when set, else the first GPU, else the first CPU.
    // Throws DeviceError.
    static Device open(std::optional<int> index = std::nullopt);
    // The device open() would pick, for its facts alone: no context, no queue.
    static cl::Device find(std::optional<int> index = std::nullopt);
    // A string fact of a device (CL_DEVICE_NAME, CL_DRIVER_VERSION, ...) without the NULs some
    // drivers leave at its end.
    static std::string text(const cl::Device& device, cl_device_info what);

    const cl::Context& context() const { return m_context; }
    const cl::Device& device() const { return m_device; }
    cl::CommandQueue& queue() { return m_queue; }
    std::string name() const;
    bool hasFp64() const;
    std::uint64_t maxAllocation() const;  // CL_DEVICE_MAX_MEM_ALLOC_SIZE
    std::uint64_t globalMemory() const;

    // Builds OpenCL C `source` (usually embedded kernel files joined, see kernelSource()) with
    // `options` ("-D..." defines and the like). `what` names it in errors. Throws DeviceError
    // carrying the build log.
    cl::Program build(const std::string& source, const std::string& what, const std::string& options = {}) const;

private:
    Device(cl::Device device);

    cl::Device m_device;
    cl::Context m_context;
    cl::CommandQueue m_queue;
};

} // namespace vf::sim::opencl
