#pragma once
// The contour tracker of sim/ContourTracker on an OpenCL device, float32 positions: RK4 advection
// (eq. 1), adaptive spacing (eqs. 3–7) with a counting-sort proximity grid and Gaussian smoothing
// along contours, refinement by the time-rewinding split (eq. 2) and collapse, kept contiguous
// and ordered by stream compaction, the optional area correction, and ink drops.
#include "sim/ExactMap.h"
#include "sim/Simulation.h"
#include "sim/Tracking.h"
#include "sim/opencl/Device.h"
#include "sim/opencl/FlowBinding.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vf::sim::opencl {

class DeviceContours {
public:
    // `flowSource` is the OpenCL C that defines flowVelocity, flowVelocityLanes and flowVorticity
    // (FlowBinding.h); flow.h.cl comes before it. `canvas` is the canvas size, where the ink mostly
    // lies: the proximity grid's cells are never so small that the canvas has more of them than
    // the grid has buckets. Throws DeviceError.
    // `sweepOverflow`: the length of the collapse's sweep grid overflow list (opencl-backend.md,
    // "Refinement by stream compaction"); any length gives the same result, a shorter one by
    // building the grid more often.
    DeviceContours(Device& device, const TrackingSettings& settings, Vec2 canvas, const std::string& flowSource,
                   std::size_t sweepOverflow = sweepOverflowCapacity);
    ~DeviceContours();

    // As ContourTracker::addContour for each polygon (resampled so no edge exceeds d_max; area
    // targets set), all or none: when the device cannot hold them, nothing is added.
    void addRegion(int region, const std::vector<Polygon>& polygons);
    void growTargetAreasAround(Vec2 p, double area);

    // As ContourTracker::strainInSpacings for a step of dt, with the flow at the end of `flow`'s
    // span, for the substep count: one scalar comes back.
    double strainInSpacings(const FlowBinding& flow, double dt);

    // RK4 from flow.t0 to flow.t1 through `flow`, then spacing, refinement, area correction.
    // `startSampled`: the caller's word that the flow at flow.t0 is the flow the last
    // strainInSpacings() sampled (a step's first substep: the fluid's start field is a copy of the
    // field the strain check saw). RK4's first stage then takes the strain check's samples, the
    // same values, instead of sampling again, unless the contours changed since.
    // False when refinement stopped at max_vertices (or at what the device's memory holds); the
    // contours are then valid but may have edges longer than d_i. Throws std::runtime_error when
    // the flow moved a vertex to a non-finite position, DeviceError on a device failure.
    bool advect(const FlowBinding& flow, bool startSampled);

    // The drop's push P → C + (P−C)·sqrt(1 + r²/|P−C|²) as the motion, then refinement (split
    // vertices land on the pushed curve). `flow` at the end of its span feeds the spacing's
    // vorticity term.
    bool drop(Vec2 center, double radius, const FlowBinding& flow);

    // Contour surgery (sim/Pinches.h) on the host: the contours are read back, and written again
    // when a cut was made. Returns how many cuts were made.
    std::size_t cutPinches();
    // Layers between two contours widened to the pinch width (sim/Pinches.h), searched on the host
    // too, everywhere or within a window: the moved vertices are written. Returns how many moved.
    std::size_t separateLayers(std::optional<Window> within);

    // A tool's exact map (sim/ExactMap.h) as the motion, then refinement, as drop().
    bool applyMap(const ExactMap& map, const FlowBinding& flow);

    std::size_t vertexCount() const;  // known on the host after every step (one scalar read)

    // Reads the geometry back (blocking). Positions widen to double; spacing as used last step.
    std::vector<Contour> read() const;

    // Replaces every contour with `contours` (snapshot restore), laid out one after the other in
    // order, as steps leave them, so the steps after it match those after the snapshot bit for bit.
    // The caller validates them (Simulation::restore); at most deviceVertexLimit() vertices.
    // Readbacks requested before are dropped. Throws DeviceError.
    void write(const std::vector<Contour>& contours);
    // The most vertices the device's memory holds (max_vertices aside: a state to restore may
    // have reached past it with its last drop), or VF_OPENCL_MAX_VERTICES when that is smaller
    // (a test and diagnostic knob; a value that is not a positive count is a DeviceError).
    std::size_t deviceVertexLimit() const;

    // The app's readback (Simulation::requestRegions), asynchronous and double-buffered:
    // requestRead() packs the positions as they are now into the scratch vertex set and enqueues
    // a non-blocking copy of them (8 bytes a vertex) into one of two host staging buffers, and
    // returns the request's number at once (steps may be enqueued right behind it: the queue is
    // in order); takeRead() returns the newest requested copy that has completed, grouped into
    // `regionCount` regions, each at most once, or nothing when none is ready yet (with `wait`,
    // it waits for the newest one instead). A request whose buffer is still being filled from two
    // requests ago waits for that copy first.
    std::uint64_t requestRead(int regionCount);
    std::optional<RegionsCopy> takeRead(bool wait = false);

    // Charges the phases of every later motion to `clock` (Simulation::enablePhaseTiming).
    void setPhaseClock(PhaseClock* clock);

    // Bytes of device memory per vertex of capacity, all buffers that scale with vertices.
    static std::size_t bytesPerVertex();
    static constexpr std::size_t sweepOverflowCapacity = 1024;

private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

} // namespace vf::sim::opencl
