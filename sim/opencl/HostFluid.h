#pragma once
// sim/FluidFlow on the host, in double, for the OpenCL contours (Fluid.h says when): after each
// step the stream functions of its start, middle and end go to the device as float32, laid out as
// DeviceFluid lays them out (flow_fluid.cl).
#include "sim/FluidFlow.h"
#include "sim/opencl/Fluid.h"

#include <vector>

namespace vf::sim::opencl {

class HostFluid final : public Fluid {
public:
    HostFluid(Device& device, const FluidSettings& settings);

    const FluidSettings& settings() const override { return m_flow.solver().settings(); }
    void addStylus(Vec2 from, Vec2 to, double radius, double duration) override;
    void addForce(const BodyForce& force) override { m_flow.solver().addForce(force); }
    void step(double dt) override;
    FlowBinding binding(double t0, double t1) const override;
    MacVelocity readVelocity() const override { return m_flow.solver().velocity(); }
    void writeVelocity(const MacVelocity& velocity) override;
    std::vector<double> readPressure() const override { return m_flow.solver().pressure(); }
    void writePressure(const std::vector<double>& pressure) override;
    double maxDivergence() const override { return m_flow.solver().maxDivergence(); }

private:
    void upload();

    Device& m_device;
    FluidFlow m_flow;
    cl::Buffer m_stream;           // start, middle, end
    std::vector<float> m_staging;  // the three lattices as float32
};

} // namespace vf::sim::opencl
