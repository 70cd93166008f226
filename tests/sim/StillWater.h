#pragma once
// Ink at rest for the exact-map tests: a grid of drops in an analytic flow that never moves, so
// only the maps move contours, and what to check them with.
#include "Backends.h"
#include "sim/Crossings.h"

#include <memory>
#include <vector>

namespace vf::test {

// Rows of touching-free drops, as a marbler starts: `rows` × `rows` circles in the unit square.
inline std::vector<sim::Polygon> dropGrid(int rows, double spacing)
{
    std::vector<sim::Polygon> drops;
    const double pitch = 1.0 / rows, radius = 0.4 * pitch;
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < rows; ++j)
            drops.push_back(sim::circle({(i + 0.5) * pitch, (j + 0.5) * pitch}, radius, spacing));
    return drops;
}

inline std::unique_ptr<sim::Simulation> stillWater(const QString& backend, bool areaCorrection = false)
{
    sim::SimulationSettings settings;
    settings.tracking.areaCorrection = areaCorrection;
    settings.flow = sim::SimulationSettings::FlowType::Analytic;  // at rest: only the combs move ink
    return makeBackend(backend, settings);
}

inline std::vector<sim::Polygon> outlines(const sim::Simulation& simulation)
{
    std::vector<sim::Polygon> out;
    for (sim::Contour& c : simulation.contours())
        out.push_back(std::move(c.positions));
    return out;
}

inline std::size_t crossings(const std::vector<sim::Polygon>& polygons)
{
    std::vector<const sim::Polygon*> pointers;
    for (const sim::Polygon& p : polygons)
        pointers.push_back(&p);
    return sim::countCrossings(pointers);
}

} // namespace vf::test
