#include "sim/opencl/DeviceList.h"

#include "sim/opencl/OpenCl.h"

namespace vf::sim::opencl {

namespace {

std::string typeName(cl_device_type type)
{
    if (type & CL_DEVICE_TYPE_GPU)
        return "GPU";
    if (type & CL_DEVICE_TYPE_CPU)
        return "CPU";
    if (type & CL_DEVICE_TYPE_ACCELERATOR)
        return "accelerator";
    return "other";
}

} // namespace

DeviceListing listDevices()
{
    DeviceListing listing;
    try {
        std::vector<cl::Platform> platforms;
        cl::Platform::get(&platforms);
        for (const cl::Platform& platform : platforms) {
            std::vector<cl::Device> devices;
            platform.getDevices(CL_DEVICE_TYPE_ALL, &devices);
            for (const cl::Device& d : devices) {
                listing.devices.push_back({int(listing.devices.size()), platform.getInfo<CL_PLATFORM_NAME>(),
                                           d.getInfo<CL_DEVICE_NAME>(), typeName(d.getInfo<CL_DEVICE_TYPE>()),
                                           d.getInfo<CL_DEVICE_VERSION>(), d.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>(),
                                           d.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>()});
            }
        }
        if (listing.devices.empty())
            listing.error = "no OpenCL platform offers a device";
    } catch (const cl::Error& e) {
        listing.devices.clear();
        listing.error = std::string(e.what()) + " failed (OpenCL error " + std::to_string(e.err()) + ")";
    }
    return listing;
}

} // namespace vf::sim::opencl
