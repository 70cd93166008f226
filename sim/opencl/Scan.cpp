#include "sim/opencl/Scan.h"

#include "sim/opencl/KernelSources.h"
#include "sim/opencl/Launch.h"

namespace vf::sim::opencl {

namespace {
constexpr std::size_t itemsPerWorkItem = 8;  // VF_SCAN_ITEMS in scan.cl
constexpr std::size_t blockSize = localSize * itemsPerWorkItem;
// Arrays up to this long are scanned by one work-group in one launch (scanOneGroup); a work-item's
// run is then at most one block.
constexpr std::size_t oneGroupLimit = localSize * blockSize;
} // namespace

Scan::Scan(Device& device, const std::string& type, std::size_t elementSize, const std::string& options)
    : m_device(device)
    , m_elementSize(elementSize)
{
    const cl::Program program = device.build(joinedKernelSources({"workgroup.cl", "scan.cl"}), "scan.cl (" + type + ")",
                                             options + " -DVF_SCAN_T=" + type);
    m_scanBlocks = cl::Kernel(program, "scanBlocks");
    m_addBlockBase = cl::Kernel(program, "addBlockBase");
    m_scanOneGroup = cl::Kernel(program, "scanOneGroup");
}

void Scan::exclusive(const cl::Buffer& data, std::size_t count)
{
    if (count <= oneGroupLimit)
        launch(m_device.queue(), m_scanOneGroup, localSize, data, cl_uint(count));
    else
        exclusive(data, count, 0);
}

void Scan::exclusive(cl::Buffer data, std::size_t count, std::size_t level)
{
    const std::size_t blocks = (count + blockSize - 1) / blockSize;
    if (level == m_levels.size()) {
        m_levels.emplace_back();
        m_levelSizes.push_back(0);
    }
    if (m_levelSizes[level] < blocks) {
        m_levelSizes[level] = blocks * 2;  // geometric: the arrays scanned grow with the contours
        m_levels[level] = cl::Buffer(m_device.context(), CL_MEM_READ_WRITE, m_levelSizes[level] * m_elementSize);
    }
    const cl::Buffer totals = m_levels[level];  // a handle: m_levels may grow below
    cl::CommandQueue& queue = m_device.queue();
    launch(queue, m_scanBlocks, blocks * localSize, data, cl_uint(count), totals);
    if (blocks > 1) {
        exclusive(totals, blocks, level + 1);
        launch(queue, m_addBlockBase, count, data, cl_uint(count), totals);
    }
}

} // namespace vf::sim::opencl
