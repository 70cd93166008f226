#pragma once
// One picture of the live simulation, made on the worker thread and handed to the GUI by value
// (std::shared_ptr<const Frame>): immutable once made, so the GUI draws it without locks while the
// simulation steps on.
#include "sim/FluidSolver.h"
#include "sim/Geometry.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vf::model {

struct Frame {
    std::uint64_t serial = 0;    // how many requests the worker had handled when it made this
    double time = 0.0;           // simulated seconds
    std::int64_t steps = 0;      // steps taken since the document started
    std::size_t vertexCount = 0;
    double width = 1.0;          // canvas size, canvas units
    double height = 1.0;
    std::vector<std::vector<sim::Polygon>> regions;  // indexed by simulation region
    std::optional<sim::MacVelocity> velocity;        // fluid flows, for the velocity overlay
    double stepsPerSecond = 0.0; // measured by the worker over the last second of playing
    std::string backend;         // "reference", or "opencl" with its device
    bool playing = false;
};

} // namespace vf::model
