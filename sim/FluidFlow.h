#pragma once
// The fluid solver seen as a Flow: velocity between two solver steps is interpolated linearly in
// time, so RK4's mid-step samples (eq. 1) see the flow of that moment rather than a frozen field.
// The contours move through the curl of the fields' stream functions (sim/StreamFunction.h): C¹
// and divergence-free, where the MAC field's own bilinear interpolation is neither.
#include "sim/Flow.h"
#include "sim/FluidSolver.h"
#include "sim/SimulationState.h"
#include "sim/StreamFunction.h"

#include <array>

namespace vf::sim {

class FluidFlow final : public Flow {
public:
    explicit FluidFlow(const FluidSettings& settings);

    FluidSolver& solver() { return m_solver; }
    const FluidSolver& solver() const { return m_solver; }

    void advance(double dt) override;
    double time() const override { return m_time; }
    void setTime(double t) override;

    // The fluid between two steps (snapshots). setState() takes a state on this grid, or null for
    // the fluid at rest.
    FluidState state() const { return {m_solver.velocity(), m_solver.pressure()}; }
    void setState(const FluidState* state);
    // The stream functions of the last step's start, middle and end (between steps, after
    // setTime or setState, all three are the solver's).
    std::array<const StreamField*, 3> streams() const { return {&m_start, &m_middle, &m_end}; }
    Vec2 velocity(Vec2 p, double t) const override;
    double vorticity(Vec2 p, double t) const override;

private:
    double blend(double t) const;  // 0 at the step's start, 1 at its end
    template <typename Sample>
    auto interpolate(double s, Sample sample) const;
    void keepOnlyTheSolversField();  // no step in progress: start, middle and end are the same

    FluidSolver m_solver;
    StreamField m_start;   // the field at the step's start
    StreamField m_middle;  // halfway through the step
    StreamField m_end;     // the solver's
    double m_stepStart = 0.0;
    double m_time = 0.0;
};

} // namespace vf::sim
