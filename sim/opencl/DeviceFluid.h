#pragma once
// The stable-fluids solver of sim/FluidSolver, on an OpenCL device in float32: the same grid,
// walls, advection, viscosity, stylus and projection, with the velocity staying on the device.
#include "sim/opencl/Fluid.h"

#include <memory>
#include <vector>

namespace vf::sim::opencl {

class DeviceFluid final : public Fluid {
public:
    // Builds fluid.cl and allocates the grid. Throws DeviceError, std::invalid_argument for
    // settings FluidSolver refuses too.
    DeviceFluid(Device& device, const FluidSettings& settings);
    ~DeviceFluid() override;

    const FluidSettings& settings() const override;
    void addStylus(Vec2 from, Vec2 to, double radius, double duration) override;
    void addForce(const BodyForce& force) override;
    void step(double dt) override;
    FlowBinding binding(double t0, double t1) const override;
    MacVelocity readVelocity() const override;
    void writeVelocity(const MacVelocity& velocity) override;
    std::vector<double> readPressure() const override;
    void writePressure(const std::vector<double>& pressure) override;
    double maxDivergence() const override;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace vf::sim::opencl
