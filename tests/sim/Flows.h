#pragma once
// Analytic flows used by the accuracy tests, as SimulationSettings.
#include "sim/Simulation.h"

#include <string>

namespace vf::test {

inline sim::SimulationSettings analyticSettings(std::string u, std::string v, double maxSpacing, bool adaptive)
{
    sim::SimulationSettings s;
    s.flow = sim::SimulationSettings::FlowType::Analytic;
    s.u = std::move(u);
    s.v = std::move(v);
    s.tracking.maxSpacing = maxSpacing;
    s.tracking.adaptive = adaptive;
    s.tracking.proximity = adaptive;
    return s;
}

// LeVeque's single vortex, reversed at t = T/2 so that at t = T every point is back where it began.
inline sim::SimulationSettings singleVortex(double period, double maxSpacing, bool adaptive)
{
    const std::string time = "cos(pi*t/" + std::to_string(period) + ")";
    return analyticSettings("-sin(pi*x)^2*sin(2*pi*y)*" + time, "sin(pi*y)^2*sin(2*pi*x)*" + time, maxSpacing,
                            adaptive);
}

// Solid-body rotation about the canvas centre, one turn per `period` seconds.
inline sim::SimulationSettings rotation(double period, double maxSpacing, bool adaptive)
{
    const std::string omega = "(2*pi/" + std::to_string(period) + ")";
    return analyticSettings("-" + omega + "*(y-0.5)", omega + "*(x-0.5)", maxSpacing, adaptive);
}

} // namespace vf::test
