#pragma once
// Analytic flows and shapes used by the accuracy tests.
#include "sim/Simulation.h"

#include <cmath>
#include <numbers>
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

// Zalesak's slotted disk: radius 0.15 at (0.5, 0.75), a slot 0.05 wide cut 0.25 deep from the
// side facing +y. Positive area, like every shape the engine makes.
inline sim::Polygon slottedDisk(double spacing)
{
    const sim::Vec2 centre(0.5, 0.75);
    const double radius = 0.15, halfWidth = 0.025, slotTop = 0.9 - 0.25;
    const double side = std::asin(halfWidth / radius);
    const double from = std::numbers::pi / 2 + side, to = 2.5 * std::numbers::pi - side;
    const int arcSteps = int(std::ceil((to - from) * radius / spacing));
    sim::Polygon disk;
    for (int i = 0; i <= arcSteps; ++i) {
        const double a = from + (to - from) * i / arcSteps;
        disk.push_back(centre + radius * sim::Vec2(std::cos(a), std::sin(a)));
    }
    disk.push_back({0.5 + halfWidth, slotTop});
    disk.push_back({0.5 - halfWidth, slotTop});
    return sim::resample(disk, spacing);
}

} // namespace vf::test
