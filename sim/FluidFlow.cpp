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

Vec2 FluidFlow::velocity(Vec2 p, double t) const
{
    const double s = blend(t);
    const Vec2 now = m_solver.velocity().sample(p);
    if (s == 1.0)
        return now;
    const Vec2 before = m_previous.sample(p);
    return before + s * (now - before);
}

double FluidFlow::vorticity(Vec2 p, double t) const
{
    const double s = blend(t);
    const double now = m_solver.velocity().vorticity(p);
    if (s == 1.0)
        return now;
    const double before = m_previous.vorticity(p);
    return before + s * (now - before);
}

} // namespace vf::sim
