#pragma once
// The fluid the OpenCL contours move through: it steps, takes the pen, and keeps the stream
// functions of the last step's start, middle and end in a device buffer (FlowBinding.h) for the
// contour kernels to sample. Two places to solve it:
// - DeviceFluid: the solver on the device, in float32. A GPU runs its many small kernels well.
// - HostFluid: sim/FluidSolver on the host, in double, uploading the stream functions (three
//   small lattices) after each step. On a CPU device the solver's launches and barriers over a
//   grid of a few thousand cells cost more than the host's single-threaded solve (the session
//   benchmarks in docs/BENCHMARKS.md, "Sessions", measure both).
#include "sim/FluidSolver.h"
#include "sim/opencl/Device.h"
#include "sim/opencl/FlowBinding.h"

#include <memory>
#include <vector>

namespace vf::sim::opencl {

class Fluid {
public:
    virtual ~Fluid() = default;

    virtual const FluidSettings& settings() const = 0;

    // As FluidSolver::addStylus: applied during the next step().
    virtual void addStylus(Vec2 from, Vec2 to, double radius, double duration) = 0;

    // As FluidSolver::addForce (validated there): applied during the next step().
    virtual void addForce(const BodyForce& force) = 0;

    // One step; afterwards binding() blends across it.
    virtual void step(double dt) = 0;

    // The stream functions at the start, halfway and end of the last step, with t0, t1 set from
    // `t0` and `t1` (the caller's clock). Before the first step all are the current field's.
    virtual FlowBinding binding(double t0, double t1) const = 0;

    // Blocking, for tests and snapshots: never on the per-step path.
    virtual MacVelocity readVelocity() const = 0;
    virtual void writeVelocity(const MacVelocity& velocity) = 0;  // clears the pressure warm start
    // The pressure warm start, as FluidSolver::pressure(): write it after writeVelocity().
    virtual std::vector<double> readPressure() const = 0;
    virtual void writePressure(const std::vector<double>& pressure) = 0;
    virtual double maxDivergence() const = 0;
};

enum class FluidPlacement {
    ByDevice,  // on the host for a CPU device, on the device otherwise
    Device,
    Host,
};

// Throws DeviceError, std::invalid_argument for settings FluidSolver refuses.
std::unique_ptr<Fluid> makeFluid(Device& device, const FluidSettings& settings,
                                 FluidPlacement placement = FluidPlacement::ByDevice);

} // namespace vf::sim::opencl
