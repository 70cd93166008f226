#pragma once
// What the document needs from the live simulation. The app implements it with a worker thread
// (app/SimulationController); every call only queues a request and returns at once, and the
// requests run in the order they were made, between steps, never racing one.
#include "model/EngineSettings.h"
#include "model/Scene.h"
#include "model/StateSlot.h"
#include "sim/Stylus.h"
#include "sim/TargetDrive.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace vf::model {

class SimulationPort {
public:
    virtual ~SimulationPort() = default;

    // A new simulation with these settings, for this scene (its canvas and timed strokes): with
    // `start` filled, it continues from that state, else it starts from the scene's regions and
    // its drops at t = 0.
    virtual void load(const Scene& scene, const EngineSettings& settings, const StateSlotPtr& start) = 0;
    // The same state carried on under other settings (another backend, grid, spacing...).
    virtual void configure(const EngineSettings& settings) = 0;

    virtual void snapshot(const StateSlotPtr& into) = 0;
    virtual void restore(const StateSlotPtr& from) = 0;

    virtual void addRegion(const std::vector<sim::Polygon>& contours) = 0;
    // Region `region` and its ink gone; the regions above it move down one index
    // (model::withoutRegion).
    virtual void removeRegion(int region) = 0;
    virtual void drop(sim::Vec2 center, double radius) = 0;
    // A tool's exact map (a comb's, a swirl's) applied to all the ink at once.
    virtual void applyMap(const sim::ExactMap& map) = 0;
    // Pens moving together (a stylus, or a comb's tines in the water), each from `from` to `to` in
    // `duration` seconds of wall time; they act together, during the next steps.
    virtual void stylus(const std::vector<sim::StylusSegment>& pens) = 0;
    // Target-driven design: the fluid is driven into the drive's target for `duration` seconds of
    // simulated time from now, in the steps to come; a gather under way, a restore or a load ends it.
    virtual void gather(const std::shared_ptr<const sim::TargetDrive>& drive, double duration) = 0;

    // How many requests have been made so far; a frame says how many it has seen (Frame::serial).
    virtual std::uint64_t requestCount() const = 0;
};

} // namespace vf::model
