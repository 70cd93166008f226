#pragma once
// The timed part of a scene: its drops, combs and stylus strokes, played into a simulation as its time
// passes. Stateless: what happens over (from, to] depends only on the interval, so the same script
// plays on unchanged after a simulation is restored to an earlier state (the app's undo).
#include "model/Regions.h"
#include "model/Scene.h"
#include "sim/Simulation.h"
#include "sim/TargetDrive.h"

#include <memory>
#include <span>

namespace vf::model {

// What the app adds to a step: a drive (its gather, which takes over from the script's) and the
// pens' parts for this step, fed after the script's strokes.
struct LiveInputs {
    const sim::TargetDrive* drive = nullptr;
    std::span<const sim::StylusSegment> pens;
};

class SceneScript {
public:
    explicit SceneScript(const Scene& scene);

    // The looks of the scene's starting regions (an SVG shape gives several, model/Scene.h
    // startingLooks) and then of its drops, in the order they become simulation regions (drops by
    // time, stable for equal times). Names are unique: unnamed drops are called
    // "drop N", skipping names already taken.
    const RegionTable& looks() const { return m_looks; }
    int startingRegionCount() const { return m_startingRegions; }
    int dropCount() const { return int(m_drops.size()); }
    // When the last drop lands (seconds of simulated time); -infinity without drops.
    double lastDropTime() const;

    // The tools due in (from, to], as a step takes them: the drops in landing order, then the exact
    // maps (combs, circular combs, swirls) in file order (a tool in the water is stylus strokes).
    // Returns whether one took the vertex count to tracking.max_vertices.
    bool applyTools(sim::Simulation& simulation, double from, double to) const;

    // One step of `dt` from the time `from`, in the order every player keeps (the app, the command
    // line, a replayed history): the tools due in (from, from + dt], the stylus strokes' share, the
    // drive, the pens, then the simulation's step. The report also says whether a tool took the
    // vertex count to tracking.max_vertices.
    sim::StepReport step(sim::Simulation& simulation, double from, double dt, const LiveInputs& live = {}) const;

private:
    // The stylus strokes' share of (from, to]: every piece of a pen path overlapping the interval
    // acts with the part of it inside the interval.
    void applyStylus(sim::Simulation& simulation, double from, double to) const;
    // The gather (target-driven design) whose span [time, time + duration) holds `from`, driving
    // the next step from the ink as it is (the one latest in the file where spans overlap).
    void applyGather(sim::Simulation& simulation, double from) const;
    bool applyDrops(sim::Simulation& simulation, double from, double to) const;
    bool applyMaps(sim::Simulation& simulation, double from, double to) const;
    // One of the scene's tools (a pattern: each of its tools in turn).
    void add(const Stroke& stroke, const Canvas& canvas);
    // A comb straight or circular: its map when exact, else a stylus stroke per tine.
    template <typename AnyComb>
    void addComb(const AnyComb& comb);

    std::vector<DropStroke> m_drops;  // in landing order
    std::vector<StylusStroke> m_strokes;  // with a comb in the water's tines
    struct TimedMap {
        double time;
        sim::ExactMap map;
    };
    std::vector<TimedMap> m_maps;  // the exact tools'
    struct TimedDrive {
        double start, end;
        std::shared_ptr<const sim::TargetDrive> drive;  // shared: the script is copied with its scene
    };
    std::vector<TimedDrive> m_drives;  // the gathers'
    RegionTable m_looks;
    int m_startingRegions = 0;
};

} // namespace vf::model
