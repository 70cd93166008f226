#pragma once
// The OpenCL backend: the whole step on the device (the fluid, Fluid.h, or an analytic flow compiled
// to OpenCL C, and DeviceContours), with geometry read back only when asked for.
#include "sim/Simulation.h"
#include "sim/Stylus.h"
#include "sim/opencl/Device.h"
#include "sim/opencl/DeviceContours.h"
#include "sim/opencl/Fluid.h"

#include <memory>
#include <optional>

namespace vf::sim::opencl {

class OpenClSimulation final : public Simulation {
public:
    // Throws DeviceError when no device can run it (no device, a failed kernel build, an
    // expression the translator refuses), std::invalid_argument for invalid settings.
    OpenClSimulation(const SimulationSettings& settings, std::optional<int> deviceIndex,
                     FluidPlacement fluidPlacement = FluidPlacement::ByDevice);
    ~OpenClSimulation() override;

    std::string backendName() const override { return "opencl"; }
    std::string description() const override { return "opencl (" + m_device.name() + ")"; }
    // The most vertices the device holds (DeviceContours::deviceVertexLimit).
    std::size_t hardwareVertexLimit() const override { return m_contours->deviceVertexLimit(); }
    const SimulationSettings& settings() const override { return m_settings; }
    int addRegion(const std::vector<Polygon>& contours) override;
    void stylus(Vec2 from, Vec2 to, double radius, double duration) override;
    StepReport step(double dt) override;
    double time() const override { return m_time; }
    std::size_t vertexCount() const override { return m_contours->vertexCount(); }
    int regionCount() const override { return m_regionCount; }
    std::vector<Contour> contours() const override { return m_contours->read(); }
    std::uint64_t requestRegions() override { return m_contours->requestRead(m_regionCount); }
    std::optional<RegionsCopy> takeRegions(bool wait) override { return m_contours->takeRead(wait); }
    std::optional<MacVelocity> velocity() const override;
    SimulationState snapshot() const override;
    void restore(const SimulationState& state) override;
    void enablePhaseTiming() override;

protected:
    void growTargetAreasAround(Vec2 p, double area) override { m_contours->growTargetAreasAround(p, area); }
    bool pushOutward(Vec2 center, double radius) override;
    bool mapContours(const ExactMap& map) override;
    void separateLayers(std::optional<Window> within = std::nullopt) override;

private:
    // The flow over [t0, t1]: the fluid's fields at the last step's ends, or the analytic flow.
    FlowBinding binding(double t0, double t1) const;

    SimulationSettings m_settings;
    Device m_device;
    std::unique_ptr<Fluid> m_fluid;         // null for an analytic flow
    FlowBinding m_placeholders;            // the buffers an analytic flow ignores
    std::unique_ptr<DeviceContours> m_contours;
    std::vector<StylusSegment> m_pendingStylus;
    int m_regionCount = 0;
    double m_time = 0.0;
};

// The backend by name, "reference" or "opencl" (with an optional device index). Throws as the
// backends' constructors do.
std::unique_ptr<Simulation> makeSimulation(const SimulationSettings& settings, const std::string& backend,
                                           std::optional<int> deviceIndex = std::nullopt);

} // namespace vf::sim::opencl
