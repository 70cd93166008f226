#pragma once
// Enumerates OpenCL platforms and devices (the `vectorfluid devices` listing and device choice).
#include <cstdint>
#include <string>
#include <vector>

namespace vf::sim::opencl {

struct DeviceInfo {
    int index = 0;  // position in the flat listing, as --device N takes it
    std::string platform;
    std::string name;
    std::string type;  // "GPU", "CPU", "accelerator", "other"
    std::string version;
    unsigned computeUnits = 0;
    std::uint64_t globalMemory = 0;
};

struct DeviceListing {
    std::vector<DeviceInfo> devices;
    std::string error;  // why none could be listed; empty on success
};

DeviceListing listDevices();

} // namespace vf::sim::opencl
