#include "sim/FluidFlow.h"

#include <algorithm>

namespace vf::sim {

FluidFlow::FluidFlow(const FluidSettings& settings)
    : m_solver(settings)
    , m_previous(m_solver.velocity())
{
}

void FluidFlow::advance(double dt)
{
    m_previous = m_solver.velocity();
    m_solver.step(dt);
    m_stepStart = m_time;
    m_time += dt;
}

double FluidFlow::blend(double t) const
{
    const double span = m_time - m_stepStart;
    return span > 0.0 ? std::clamp((t - m_stepStart) / span, 0.0, 1.0) : 1.0;
}

namespace {

// The field `s` of the way from `before` to `now`; `sample` reads one value out of a field.
template <typename Sample>
auto interpolate(double s, const MacVelocity& before, const MacVelocity& now, Sample sample)
{
    const auto end = sample(now);
    if (s == 1.0)
        return end;
    const auto start = sample(before);
    return start + s * (end - start);
}

} // namespace

Vec2 FluidFlow::velocity(Vec2 p, double t) const
{
    return interpolate(blend(t), m_previous, m_solver.velocity(), [p](const MacVelocity& f) { return f.sample(p); });
}

double FluidFlow::vorticity(Vec2 p, double t) const
{
    return interpolate(blend(t), m_previous, m_solver.velocity(), [p](const MacVelocity& f) { return f.vorticity(p); });
}

} // namespace vf::sim
