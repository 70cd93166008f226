#pragma once
// The stable-fluids solver of sim/FluidSolver, on an OpenCL device in float32: the same grid,
// walls, advection, viscosity, stylus and projection, with the velocity staying on the device.
#include "sim/FluidSolver.h"
#include "sim/opencl/Device.h"
#include "sim/opencl/FlowBinding.h"

#include <memory>
#include <vector>

namespace vf::sim::opencl {

class DeviceFluid {
public:
    // Builds fluid.cl and allocates the grid. Throws DeviceError, std::invalid_argument for
    // settings FluidSolver refuses too.
    DeviceFluid(Device& device, const FluidSettings& settings);
    ~DeviceFluid();

    const FluidSettings& settings() const;

    // As FluidSolver::addStylus: applied during the next step().
    void addStylus(Vec2 from, Vec2 to, double radius, double duration);

    // One step. Keeps the stream functions of the step's start, middle and end, so binding() can
    // blend across the step.
    void step(double dt);

    // The stream functions at the start, halfway and end of the last step (FlowBinding.h), with t0,
    // t1 set from `t0` and `t1` (the caller's clock). Before the first step all are the current
    // field's.
    FlowBinding binding(double t0, double t1) const;

    // Blocking readbacks, for tests and snapshots: never on the per-step path.
    MacVelocity readVelocity() const;
    void writeVelocity(const MacVelocity& velocity);  // clears the pressure warm start
    // The pressure warm start, as FluidSolver::pressure(): write it after writeVelocity().
    std::vector<double> readPressure() const;
    void writePressure(const std::vector<double>& pressure);
    double maxDivergence() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace vf::sim::opencl
