#include "sim/opencl/WarmUp.h"

#include "sim/opencl/Device.h"
#include "sim/opencl/KernelSources.h"
#include "sim/opencl/OpenClSimulation.h"

#include <functional>
#include <vector>

namespace vf::sim::opencl {

std::string kernelIdentity(std::optional<int> device)
{
    const cl::Device found = Device::find(device);
    return std::string(kernelSourcesDigest()) + ' ' + Device::text(found, CL_DEVICE_NAME) + ' ' +
           Device::text(found, CL_DRIVER_VERSION);
}

void warmUpKernels(std::optional<int> device, const std::atomic<bool>& stop)
{
    if (stop)
        return;
    SimulationSettings settings;  // the fluid, as a session's: only its grid is smaller
    settings.fluid.nx = settings.fluid.ny = 32;
    settings.tracking.maxSpacing = 0.01;
    settings.tracking.areaCorrection = true;
    OpenClSimulation simulation(settings, device);
    const double dt = 0.02;
    const std::vector<std::function<void()>> parts{
        [&] {
            simulation.addRegion({circle({0.35, 0.5}, 0.12, settings.tracking.maxSpacing)});
            simulation.addRegion({circle({0.62, 0.5}, 0.12, settings.tracking.maxSpacing)});
            // Finely sampled, which the first step coarsens: past the most vertices one work-group
            // scans (sim/opencl/Scan.cpp), so the scans of several groups are launched too.
            simulation.addRegion({circle({0.5, 0.8}, 0.1, 1e-5)});
            // An hourglass whose waist is thinner than the pinch width: the pinch check cuts it.
            const double h = 1e-7;
            simulation.addRegion({{{0.05, 0.05}, {0.25, 0.05}, {0.15 + h, 0.15}, {0.25, 0.25}, {0.05, 0.25}, {0.15 - h, 0.15}}});
        },
        [&] {
            for (int k = 0; k < 6; ++k) {  // past a pinch check (every 0.1 s)
                simulation.stylus({0.1 + 0.1 * k, 0.45}, {0.2 + 0.1 * k, 0.5}, 0.05, dt);
                simulation.step(dt);
            }
        },
        [&] { simulation.drop({0.5, 0.3}, 0.08); },
        [&] {
            Comb comb;
            comb.from = {0.1, 0.5};
            comb.to = {0.9, 0.5};
            comb.tines = 3;
            comb.spacing = 0.1;
            comb.sharpness = 0.02;
            simulation.applyMap(comb);
        },
        [&] { simulation.restore(simulation.snapshot()); },
        [&] {
            simulation.requestRegions();
            simulation.takeRegions(true);
        },
    };
    for (const std::function<void()>& part : parts) {
        if (stop)
            return;
        part();
    }
}

} // namespace vf::sim::opencl
