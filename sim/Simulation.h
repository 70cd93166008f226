#pragma once
// The backend interface: one live simulation of contours in a flow. The reference backend (plain
// double-precision C++) is always built; an OpenCL backend implements the same interface.
#include "sim/ExactMap.h"
#include "sim/FluidSolver.h"
#include "sim/Geometry.h"
#include "sim/PhaseClock.h"
#include "sim/SimulationState.h"
#include "sim/Tracking.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vf::sim {

struct SimulationSettings {
    enum class FlowType { Fluid, Analytic };
    FlowType flow = FlowType::Fluid;
    FluidSettings fluid;        // its width and height are the canvas size
    std::string u = "0", v = "0";  // analytic flow: muparser expressions in x, y, t
    TrackingSettings tracking;
};

struct StepReport {
    bool vertexLimitReached = false;  // refinement stopped at tracking.maxVertices
    int substeps = 1;
    std::size_t pinchesCut = 0;  // contour surgery at the end of the step (sim/Pinches.h)
};

// Every region's contours at one moment, for a display (Simulation::requestRegions).
struct RegionsCopy {
    std::uint64_t request = 0;                   // requestRegions()'s number for it
    std::vector<std::vector<Polygon>> regions;   // indexed by region, as regions()
};

struct DropReport {
    int region = 0;                   // the new region's index
    bool vertexLimitReached = false;  // the drop took the vertex count to tracking.maxVertices
};

class Simulation {
public:
    virtual ~Simulation() = default;

    virtual std::string backendName() const = 0;
    // The backend and where it runs, for people: "reference", "opencl (device name)".
    virtual std::string description() const { return backendName(); }
    // The most vertices the hardware holds, whatever the settings allow (unbounded on the host).
    virtual std::size_t hardwareVertexLimit() const { return std::numeric_limits<std::size_t>::max(); }
    virtual const SimulationSettings& settings() const = 0;

    // Adds a region made of closed contours (filled together, even-odd); returns its index.
    virtual int addRegion(const std::vector<Polygon>& contours) = 0;
    // A marbling ink drop: every existing contour point P moves to C + (P−C)·sqrt(1 + r²/|P−C|²),
    // which pushes old ink outward and keeps its area, then a circle of radius r at C becomes a new
    // region, whose index is returned. Regions are painted in order, so ink the drop lands in
    // shows as a ring around it: its contour then encloses the drop too (area + π r²).
    DropReport drop(Vec2 center, double radius);
    // A tool's exact map (sim/ExactMap.h: a comb, a circular comb, a swirl) applied to every
    // contour at once and depicted within tracking.chordTolerance; the fluid is untouched. False
    // when refinement stopped at max_vertices.
    bool applyMap(const ExactMap& map);
    // The stylus moved from `from` to `to` during `duration` seconds; acts during the next step.
    // Only a fluid flow responds.
    virtual void stylus(Vec2 from, Vec2 to, double radius, double duration) = 0;

    // A force over the fluid grid for the next step, in every substep (target-driven design:
    // sim/TargetDrive.h); the caller computes it from the ink before each step. Only a fluid flow
    // responds. It is not part of a snapshot: a state restored drops it. Throws
    // std::invalid_argument (one line) for a force FluidSolver::addForce refuses.
    void drive(const BodyForce& force);

    // Advances by dt, split into substeps when vertices would move too far for their spacing.
    // Throws std::runtime_error when the flow turns non-finite.
    virtual StepReport step(double dt) = 0;

    virtual double time() const = 0;
    virtual std::size_t vertexCount() const = 0;
    virtual int regionCount() const = 0;
    // Every contour with its region and spacing, read back from the backend.
    virtual std::vector<Contour> contours() const = 0;

    // Every region's contours, indexed by region.
    std::vector<std::vector<Polygon>> regions() const;
    // The same for a display, without waiting on the step: requestRegions() starts a copy of every
    // region's contours as they are now and returns its number (1, 2, ...); takeRegions() returns
    // the newest requested copy that is complete, each at most once, or nothing yet (with `wait`,
    // it waits for the newest request's copy). The OpenCL backend reads positions only, enqueued
    // behind the work already queued and double-buffered, so the caller can go on to the next
    // step without waiting for it; the reference backend copies at once. restore() drops the
    // copies requested before it.
    virtual std::uint64_t requestRegions() = 0;
    virtual std::optional<RegionsCopy> takeRegions(bool wait = false) = 0;
    // The fluid's velocity now (for the app's velocity overlay); none for an analytic flow.
    // Blocking on OpenCL (a readback of the grid).
    virtual std::optional<MacVelocity> velocity() const = 0;

    // Snapshots, for the app's undo history, backend switching and project files.
    //
    // snapshot() takes everything that determines the steps to come: the time, the region count,
    // every contour with all its fields, the fluid's velocity and pressure warm start (fluid flows
    // only), and stylus input given but not yet stepped. Blocking on OpenCL (a readback). A
    // contour's `previous` is taken as its positions (settledContours): every motion overwrites it
    // at its start, so between steps it decides nothing, and equal to the positions it packs to
    // nothing in a project file.
    //
    // restore() replaces the whole live state with `state`. After b.restore(a.snapshot()) on the
    // same backend and settings (OpenCL: the same device), b.snapshot() == a.snapshot() and both
    // step on bit for bit alike. The OpenCL backend keeps positions in float32: a state taken from
    // it restores exactly, one from the reference backend is rounded to float.
    //
    // The state may come from other settings, as when the app changes settings by building a new
    // simulation and restoring the old state into it. Contours are taken as they are (the next
    // step refines them to this simulation's spacing). When the state has no fluid (it came from
    // an analytic flow) or one on a grid of another size, the fluid starts at rest; a fluid in the
    // state of an analytic simulation is ignored, and so is its pending stylus input.
    //
    // A state that cannot be run is refused with std::invalid_argument (one line) before anything
    // changes: a contour of fewer than 3 vertices, parallel arrays of unequal lengths, a non-finite
    // number or a spacing that is not positive, a region outside [0, regionCount), regionCount < 0,
    // a malformed fluid, or (OpenCL) more vertices than the device holds. tracking.maxVertices is
    // not applied: it stops growth, and a state to restore may have gone past it with the drop
    // or region that reached it (the app's undo history holds such states).
    virtual SimulationState snapshot() const = 0;
    virtual void restore(const SimulationState& state) = 0;

    // Where the steps' time goes, phase by phase, for the session benchmarks (sim/PhaseClock.h). Off
    // until enabled; on a device, each phase then waits for its work, which costs a little.
    virtual void enablePhaseTiming() = 0;
    const PhaseClock::Seconds& phaseSeconds() const { return m_phases.seconds(); }

protected:
    PhaseClock m_phases;
    std::optional<BodyForce> m_pendingForce;  // drive(), for the next step's substeps
    // The least fraction of its thickness a layer may have kept under the drops since all the ink
    // was last widened (drop()); 0 after a restore, whose layers are unknown.
    double m_layersPressed = 0.0;

    // The two backend parts of drop(): raise the area-correction target of every contour winding
    // around `p` by `area`, and move every contour by the drop's push, refining under it (false
    // when refinement stopped at max_vertices).
    virtual void growTargetAreasAround(Vec2 p, double area) = 0;
    virtual bool pushOutward(Vec2 center, double radius) = 0;
    // The backend part of applyMap(): every contour moved by the map, refined under it.
    virtual bool mapContours(const ExactMap& map) = 0;
    // Layers between two contours widened to the pinch width (sim/Separation.h), everywhere or
    // within a window: around every exact map and every drop, before and after it. A map or a
    // drop presses layers (a map anywhere, a drop near it), and a drop leaves ink a hair from its
    // centre a hair outside its rim; a layer pressed under two float spacings is one a device's
    // next refinement can cross. Not in the steps: there the moves cost marbling a third of its
    // time (the refinement works the little bumps they leave), and flow presses layers gradually.
    virtual void separateLayers(std::optional<Window> within = std::nullopt) = 0;
};

// Throws std::invalid_argument with a one-line message for settings no backend can run.
void validateSettings(const SimulationSettings& settings);

// `contours` with each one's `previous` set to its positions, as snapshot() takes them.
std::vector<Contour> settledContours(std::vector<Contour> contours);

// Throws std::invalid_argument with a one-line message for a state restore() must refuse (see
// Simulation::restore), `vertexLimit` being the most vertices the simulation can hold.
void validateState(const SimulationState& state, std::size_t vertexLimit);

// The state's fluid when it lies on a grid of the size `fluid` sets, else null: the fluid then
// starts at rest.
const FluidState* fluidOnGrid(const SimulationState& state, const FluidSettings& fluid);

// How many substeps a step of the given strain (the largest relative motion of an edge's ends in
// local spacings, ContourTracker::strainInSpacings) takes: enough to keep each under
// tracking.substepStrain, at most tracking.maxSubsteps.
int substepCount(double strain, const TrackingSettings& tracking);

// Throws std::invalid_argument with a one-line message for invalid settings.
std::unique_ptr<Simulation> makeReferenceSimulation(const SimulationSettings& settings);

} // namespace vf::sim
