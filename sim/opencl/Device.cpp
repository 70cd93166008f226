#include "sim/opencl/Device.h"

#include <cstdlib>
#include <vector>

namespace vf::sim::opencl {

namespace {

std::vector<cl::Device> allDevices()
{
    std::vector<cl::Platform> platforms;
    cl::Platform::get(&platforms);
    std::vector<cl::Device> all;
    for (const cl::Platform& platform : platforms) {
        std::vector<cl::Device> devices;
        platform.getDevices(CL_DEVICE_TYPE_ALL, &devices);
        all.insert(all.end(), devices.begin(), devices.end());
    }
    return all;
}

std::optional<int> indexFromEnvironment()
{
    const char* value = std::getenv("VF_OPENCL_DEVICE");
    if (!value || !*value)
        return std::nullopt;
    char* end = nullptr;
    const long index = std::strtol(value, &end, 10);
    if (*end != '\0' || index < 0)
        throw DeviceError("VF_OPENCL_DEVICE='" + std::string(value) + "' is not a device number");
    return int(index);
}

cl::Device choose(const std::vector<cl::Device>& devices, std::optional<int> index)
{
    if (index) {
        if (*index >= int(devices.size()))
            throw DeviceError("there is no OpenCL device " + std::to_string(*index) + " (" +
                              std::to_string(devices.size()) + " found; see `vectorfluid devices`)");
        return devices[*index];
    }
    for (cl_device_type wanted : {CL_DEVICE_TYPE_GPU, CL_DEVICE_TYPE_CPU})
        for (const cl::Device& d : devices)
            if (d.getInfo<CL_DEVICE_TYPE>() & wanted)
                return d;
    if (devices.empty())
        throw DeviceError("no OpenCL device found");
    return devices.front();
}

} // namespace

Device Device::open(std::optional<int> index)
{
    return Device(find(index));
}

cl::Device Device::find(std::optional<int> index)
{
    try {
        if (!index)
            index = indexFromEnvironment();
        return choose(allDevices(), index);
    } catch (const cl::Error& e) {
        // No ICD, or an ICD with no platform: the loader answers CL_PLATFORM_NOT_FOUND_KHR.
        throw DeviceError("no OpenCL device available (" + std::string(e.what()) + ", error " +
                          std::to_string(e.err()) + ")");
    }
}

Device::Device(cl::Device device)
    : m_device(std::move(device))
    , m_context(m_device)
    , m_queue(m_context, m_device)
{
}

std::string Device::name() const
{
    return text(m_device, CL_DEVICE_NAME);
}

std::string Device::text(const cl::Device& device, cl_device_info what)
{
    std::string text;
    device.getInfo(what, &text);
    while (!text.empty() && text.back() == '\0')
        text.pop_back();
    return text;
}

bool Device::hasFp64() const
{
    return m_device.getInfo<CL_DEVICE_EXTENSIONS>().find("cl_khr_fp64") != std::string::npos;
}

std::uint64_t Device::maxAllocation() const
{
    return m_device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
}

std::uint64_t Device::globalMemory() const
{
    return m_device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
}

cl::Program Device::build(const std::string& source, const std::string& what, const std::string& options) const
{
    cl::Program program(m_context, source);
    // -w (OpenCL's own option): PoCL's compiler prints "N warnings generated." straight to the
    // process's stderr, which must carry nothing but the one line of an error. A failed build
    // still brings its errors in the log below.
    const std::string quiet = "-w " + options;
    try {
        program.build({m_device}, quiet.c_str());
    } catch (const cl::BuildError& e) {
        // Khronos CLHPP: the log per device travels with the exception.
        std::string log;
        for (const auto& [device, text] : e.getBuildLog())
            log += text;
        throw DeviceError("OpenCL kernel build failed for " + what + " on " + name() + "\n" + log);
    } catch (const cl::Error& e) {
        throw DeviceError("OpenCL kernel build failed for " + what + " (" + e.what() + ", error " +
                          std::to_string(e.err()) + ")");
    }
    return program;
}

} // namespace vf::sim::opencl
