#pragma once
// In-place exclusive prefix sums on the device (scan.cl), for uint or the accumulation type.
// Work-efficient and deterministic: blocks of 512 entries are scanned by one work-group each, the
// block totals are scanned recursively the same way and added back; arrays of up to 32768 entries
// are scanned by one work-group in one launch. The contour kernels fuse the first level into their
// own work (one total per tile of vertices) and use this for the rest.
#include "sim/opencl/Device.h"

#include <cstddef>
#include <string>
#include <vector>

namespace vf::sim::opencl {

class Scan {
public:
    // `type` is the OpenCL C element type ("uint", "double" or "float"), `elementSize` its size.
    // `options` carries the build's common defines (VF_LOCAL, VF_FP64). Throws DeviceError.
    Scan(Device& device, const std::string& type, std::size_t elementSize, const std::string& options);

    // data[i] ← sum of data[0..i) for i < count, enqueued on the device's queue. The caller puts
    // a zero after the last entry it wants summed when it needs the total.
    void exclusive(const cl::Buffer& data, std::size_t count);

private:
    void exclusive(cl::Buffer data, std::size_t count, std::size_t level);

    Device& m_device;
    std::size_t m_elementSize;
    cl::Kernel m_scanBlocks, m_addBlockBase, m_scanOneGroup;
    std::vector<cl::Buffer> m_levels;  // block totals, one buffer per recursion level
    std::vector<std::size_t> m_levelSizes;
};

} // namespace vf::sim::opencl
