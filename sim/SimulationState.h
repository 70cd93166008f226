#pragma once
// Everything a Simulation needs to go on exactly where it was: what Simulation::snapshot() takes
// and Simulation::restore() gives back. Plain data in double precision and backend-neutral, so a
// state taken from one backend restores into the other (the app switches backends this way, and
// keeps states in its undo history and project files).
#include "sim/FluidSolver.h"
#include "sim/Stylus.h"
#include "sim/Tracking.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace vf::sim {

// The fluid between two steps. The velocity is the whole physical state; the pressure only warm-
// starts the next projection, but it is kept so that stepping on from a restored state gives the
// same numbers as stepping on from the original.
struct FluidState {
    MacVelocity velocity;
    std::vector<double> pressure;  // nx * ny, cell centres

    friend bool operator==(const FluidState&, const FluidState&) = default;
};

struct SimulationState {
    double time = 0.0;
    int regionCount = 0;
    std::vector<Contour> contours;            // every field (`previous` as Simulation::snapshot takes it)
    std::optional<FluidState> fluid;          // absent for an analytic flow
    std::vector<StylusSegment> pendingStylus; // given but not yet stepped

    // Heap bytes held, for the undo history's memory budget.
    std::size_t bytes() const
    {
        std::size_t n = sizeof(*this) + pendingStylus.capacity() * sizeof(StylusSegment);
        for (const Contour& c : contours)
            n += sizeof(Contour) + c.positions.capacity() * sizeof(Vec2) + c.previous.capacity() * sizeof(Vec2)
                 + c.spacing.capacity() * sizeof(double);
        if (fluid)
            n += (fluid->velocity.u.capacity() + fluid->velocity.v.capacity() + fluid->pressure.capacity()) * sizeof(double);
        return n;
    }

    friend bool operator==(const SimulationState&, const SimulationState&) = default;
};

} // namespace vf::sim
