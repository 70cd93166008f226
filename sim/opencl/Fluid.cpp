#include "sim/opencl/Fluid.h"

#include "sim/opencl/DeviceFluid.h"
#include "sim/opencl/HostFluid.h"

namespace vf::sim::opencl {

std::unique_ptr<Fluid> makeFluid(Device& device, const FluidSettings& settings, FluidPlacement placement)
{
    const bool cpu = device.device().getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU;
    if (placement == FluidPlacement::Host || (placement == FluidPlacement::ByDevice && cpu))
        return std::make_unique<HostFluid>(device, settings);
    return std::make_unique<DeviceFluid>(device, settings);
}

} // namespace vf::sim::opencl
