#include "sim/Simulation.h"

#include "sim/ReferenceSimulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vf::sim {

namespace {

void require(bool condition, const char* message)
{
    if (!condition)
        throw std::invalid_argument(message);
}

} // namespace

// Shared by every backend so they refuse exactly the same settings.
void validateSettings(const SimulationSettings& s)
{
    const TrackingSettings& t = s.tracking;
    require(std::isfinite(t.maxSpacing) && t.maxSpacing > 0.0, "tracking max_spacing must be a positive number");
    require(t.maxVertices >= 3, "tracking max_vertices must be at least 3");
    require(t.maxSubsteps >= 1, "tracking max_substeps must be at least 1");
    require(std::isfinite(s.fluid.width) && s.fluid.width > 0.0 && std::isfinite(s.fluid.height) && s.fluid.height > 0.0,
            "canvas width and height must be positive numbers");
}

int substepCount(double strain, const TrackingSettings& tracking)
{
    if (!(strain >= 0.0))  // NaN: let the step run once and the finiteness checks speak
        return 1;
    return int(std::clamp(std::ceil(strain / tracking.substepStrain), 1.0, double(tracking.maxSubsteps)));
}

DropReport Simulation::drop(Vec2 center, double radius)
{
    // A contour around the centre ends up enclosing the new drop too: π r² more, counted as the
    // drop's own polygon so that the ring it leaves keeps exactly the area it had.
    const Polygon dropped = circle(center, radius, settings().tracking.maxSpacing);
    growTargetAreasAround(center, signedArea(dropped));
    const bool refined = pushOutward(center, radius);
    DropReport report;
    report.region = addRegion({dropped});
    report.vertexLimitReached = !refined || vertexCount() > settings().tracking.maxVertices;
    return report;
}

std::vector<std::vector<Polygon>> Simulation::regions() const
{
    std::vector<std::vector<Polygon>> out(regionCount());
    for (Contour& c : contours())
        out[c.region].push_back(std::move(c.positions));
    return out;
}

std::unique_ptr<Simulation> makeReferenceSimulation(const SimulationSettings& settings)
{
    return std::make_unique<ReferenceSimulation>(settings);
}

} // namespace vf::sim
