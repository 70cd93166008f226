#pragma once
// The simulation backend a user asked for: OpenCL wherever a device can run the settings, else
// the reference backend with a notice saying why. Shared by the command line and the app.
#include "sim/Simulation.h"

#include <QString>

#include <memory>
#include <optional>

namespace vf::app {

// `backend` is "reference" or "opencl" (anything else counts as "opencl"). On a fallback,
// `notice` gets one line (and a failed kernel build's log on the lines below it).
// Throws std::invalid_argument for settings no backend can run.
std::unique_ptr<sim::Simulation> makeBackend(const sim::SimulationSettings& settings, const QString& backend,
                                             std::optional<int> device, QString& notice);

// "reference", or "opencl (device name)".
QString backendLabel(const sim::Simulation& simulation);

// Which limit stops refinement: "max_vertices (N)", or the OpenCL device's vertex limit where that
// is smaller (its memory, or VF_OPENCL_MAX_VERTICES).
QString vertexLimitLabel(const sim::Simulation& simulation);

} // namespace vf::app
