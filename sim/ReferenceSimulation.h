#pragma once
// The reference backend: scalar double-precision C++, deterministic, single-threaded.
#include "sim/ContourTracker.h"
#include "sim/Simulation.h"
#include "sim/Stylus.h"

#include <memory>

namespace vf::sim {

class FluidFlow;

class ReferenceSimulation final : public Simulation {
public:
    explicit ReferenceSimulation(const SimulationSettings& settings);
    ~ReferenceSimulation() override;

    std::string backendName() const override { return "reference"; }
    const SimulationSettings& settings() const override { return m_settings; }
    int addRegion(const std::vector<Polygon>& contours) override;
    void stylus(Vec2 from, Vec2 to, double radius, double duration) override;
    StepReport step(double dt) override;
    double time() const override { return m_flow->time(); }
    std::size_t vertexCount() const override { return m_tracker.vertexCount(); }
    int regionCount() const override { return m_regionCount; }
    std::vector<Contour> contours() const override { return m_tracker.contours(); }
    std::uint64_t requestRegions() override;
    std::optional<RegionsCopy> takeRegions(bool wait) override;
    std::optional<MacVelocity> velocity() const override;
    SimulationState snapshot() const override;
    void restore(const SimulationState& state) override;
    void enablePhaseTiming() override;

    // The flow the contours move through (the benchmarks' naive loop samples it too).
    const Flow& flow() const { return *m_flow; }

protected:
    void growTargetAreasAround(Vec2 p, double area) override { m_tracker.growTargetAreasAround(p, area); }
    bool pushOutward(Vec2 center, double radius) override;
    bool mapContours(const ExactMap& map) override;
    void separateLayers(std::optional<Window> within = std::nullopt) override;

private:
    SimulationSettings m_settings;
    FluidFlow* m_fluid = nullptr;  // m_flow when the flow is a fluid: set while m_flow is made, so declared first
    std::unique_ptr<Flow> m_flow;
    ContourTracker m_tracker;
    std::vector<StylusSegment> m_pendingStylus;
    int m_regionCount = 0;
    std::uint64_t m_regionsRequests = 0;
    std::optional<RegionsCopy> m_regionsCopy;  // requested, not yet taken
};

} // namespace vf::sim
