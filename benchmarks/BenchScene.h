#pragma once
// What the benchmarks share: the backends, and docs/BENCHMARKS.md's "The stirred scene" (a 64×64 fluid
// stirred by a circling pen, with a lattice of small ink circles of about N vertices in all).
#include "sim/Simulation.h"
#include "sim/opencl/OpenClSimulation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace vf::bench {

// ---- Backends: each one becomes a family of the benchmarks that take one -----------------------

struct Backend {
    const char* name;
    std::unique_ptr<sim::Simulation> (*make)(const sim::SimulationSettings&);
};

inline const std::vector<Backend>& backends()
{
    static const std::vector<Backend> list{
        {"reference", &sim::makeReferenceSimulation},
        // The device VF_OPENCL_DEVICE names, else the first GPU, else the first CPU (PoCL).
        {"opencl", [](const sim::SimulationSettings& s) -> std::unique_ptr<sim::Simulation> {
             return std::make_unique<sim::opencl::OpenClSimulation>(s, std::nullopt);
         }}};
    return list;
}

// ---- The scene -----------------------------------------------------------------------------------

constexpr double kDt = 1.0 / 60.0;  // one display frame per step, as an interactive session steps
constexpr int kStirSteps = 30;      // fluid-only steps before the ink goes in (0.5 s of stirring)
constexpr int kWarmupSteps = 3;     // with ink, untimed: refinement settles the fresh circles
constexpr double kPenOrbit = 0.3;   // the pen circles (0.5, 0.5) at this distance...
constexpr double kPenSpeed = 0.3;   // ...at this speed (canvas units / s)...
constexpr double kPenRadius = 0.05; // ...with this reach
// Circles of about this many vertices once refinement has settled them (measured, see
// layoutFor): small enough to tile the canvas with N vertices, large enough that per-contour
// overhead does not swamp per-vertex work.
constexpr double kVerticesPerCircle = 128.0;
// d_max relative to the circle radius. The adaptive spacing then settles each circle at about
// kVerticesPerCircle vertices in this flow (curvature, vorticity and proximity all shrink d_i).
constexpr double kSpacingOverRadius = 0.1;

struct Layout {
    int grid = 0;        // grid × grid circles
    double radius = 0;   // of each circle
    double maxSpacing = 0;
};

inline Layout layoutFor(std::int64_t targetVertices)
{
    Layout l;
    l.grid = std::max(1, int(std::lround(std::sqrt(double(targetVertices) / kVerticesPerCircle))));
    l.radius = 0.3 / l.grid;  // gaps of 0.4 / grid between neighbours: no proximity at the start
    l.maxSpacing = kSpacingOverRadius * l.radius;
    return l;
}

inline sim::SimulationSettings settingsFor(const Layout& layout)
{
    sim::SimulationSettings s;  // fluid flow, 64 × 64 cells, unit canvas, adaptive + proximity on
    s.tracking.maxSpacing = layout.maxSpacing;
    return s;
}

inline sim::Vec2 penAt(int step)
{
    const double angle = step * kPenSpeed * kDt / kPenOrbit;
    return sim::Vec2(0.5) + kPenOrbit * sim::Vec2(std::cos(angle), std::sin(angle));
}

inline std::vector<sim::Vec2> circleCentres(const Layout& layout)
{
    std::vector<sim::Vec2> centres;
    for (int j = 0; j < layout.grid; ++j)
        for (int i = 0; i < layout.grid; ++i)
            centres.emplace_back((i + 0.5) / layout.grid, (j + 0.5) / layout.grid);
    return centres;
}

} // namespace vf::bench
