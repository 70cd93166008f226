#include "sim/FluidFlow.h"

#include <algorithm>
#include <cmath>

namespace vf::sim {

FluidFlow::FluidFlow(const FluidSettings& settings)
    : m_solver(settings)
{
    keepOnlyTheSolversField();
}

void FluidFlow::keepOnlyTheSolversField()
{
    m_start = m_middle = m_end = StreamField::of(m_solver.velocity());
}

void FluidFlow::advance(double dt)
{
    m_start = std::move(m_end);
    m_solver.step(dt);
    m_end = StreamField::of(m_solver.velocity());
    m_middle = StreamField::average(m_start, m_end);
    m_stepStart = m_time;
    m_time += dt;
}

// Between steps only the solver's field is sampled (the span's end, see blend()): the fields of
// the last step's start and middle matter no more and become the current one.
void FluidFlow::setTime(double t)
{
    keepOnlyTheSolversField();
    m_stepStart = m_time = t;
}

void FluidFlow::setState(const FluidState* state)
{
    m_solver.setVelocity(state ? state->velocity : FluidSolver::atRest(m_solver.settings()));
    if (state)
        m_solver.setPressure(state->pressure);
    keepOnlyTheSolversField();
}

double FluidFlow::blend(double t) const
{
    const double span = m_time - m_stepStart;
    return span > 0.0 ? std::clamp((t - m_stepStart) / span, 0.0, 1.0) : 1.0;
}

// The flow `s` of the way through the step; `sample` reads one value out of a field. RK4 asks at
// s = 0, ½, ½, 1 (up to rounding in computing s), each answered by one field: the fields differ
// from the blend there by rounding of the same order.
template <typename Sample>
auto FluidFlow::interpolate(double s, Sample sample) const
{
    constexpr double near = 1e-9;
    if (s > 1.0 - near)
        return sample(m_end);
    if (std::abs(s - 0.5) < near)
        return sample(m_middle);
    const auto start = sample(m_start);
    if (s < near)
        return start;
    return start + s * (sample(m_end) - start);
}

Vec2 FluidFlow::velocity(Vec2 p, double t) const
{
    return interpolate(blend(t), [p](const StreamField& f) { return f.velocity(p); });
}

double FluidFlow::vorticity(Vec2 p, double t) const
{
    return interpolate(blend(t), [p](const StreamField& f) { return f.vorticity(p); });
}

} // namespace vf::sim
