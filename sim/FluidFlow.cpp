#include "sim/FluidFlow.h"

#include <algorithm>
#include <cmath>

namespace vf::sim {

FluidFlow::FluidFlow(const FluidSettings& settings)
    : m_solver(settings)
    , m_previous(m_solver.velocity())
    , m_middle(m_previous)
{
}

namespace {

// The field halfway between two fields. Sampling is linear in the field, so sampling this equals
// blending two samples at s = ½ (to rounding) at half the cost.
MacVelocity average(const MacVelocity& a, const MacVelocity& b)
{
    MacVelocity mean = a;
    for (std::size_t i = 0; i < mean.u.size(); ++i)
        mean.u[i] = 0.5 * (a.u[i] + b.u[i]);
    for (std::size_t i = 0; i < mean.v.size(); ++i)
        mean.v[i] = 0.5 * (a.v[i] + b.v[i]);
    return mean;
}

} // namespace

void FluidFlow::advance(double dt)
{
    m_previous = m_solver.velocity();
    m_solver.step(dt);
    m_middle = average(m_previous, m_solver.velocity());
    m_stepStart = m_time;
    m_time += dt;
}

// Between steps only the solver's field is sampled (the span's end, see blend()): the fields of
// the last step's start and middle matter no more and become the current one.
void FluidFlow::setTime(double t)
{
    m_previous = m_middle = m_solver.velocity();
    m_stepStart = m_time = t;
}

void FluidFlow::setState(const FluidState* state)
{
    m_solver.setVelocity(state ? state->velocity : FluidSolver::atRest(m_solver.settings()));
    if (state)
        m_solver.setPressure(state->pressure);
    m_previous = m_middle = m_solver.velocity();
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
        return sample(m_solver.velocity());
    if (std::abs(s - 0.5) < near)
        return sample(m_middle);
    const auto start = sample(m_previous);
    if (s < near)
        return start;
    return start + s * (sample(m_solver.velocity()) - start);
}

Vec2 FluidFlow::velocity(Vec2 p, double t) const
{
    return interpolate(blend(t), [p](const MacVelocity& f) { return f.sample(p); });
}

double FluidFlow::vorticity(Vec2 p, double t) const
{
    return interpolate(blend(t), [p](const MacVelocity& f) { return f.vorticity(p); });
}

} // namespace vf::sim
