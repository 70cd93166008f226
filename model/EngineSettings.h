#pragma once
// The simulation settings a user edits in the app (the Simulation dock): the flow and tracking of
// the scene format, and which backend runs them. Changing them is one undoable command.
#include "model/Scene.h"

#include <QString>

namespace vf::model {

// The two fluid modes of the paper: marbling (§5.1, low viscosity, motion persists) and shape
// design (§5.2, high viscosity, motion dies right after each stroke). Marbling is the
// sumi-nagashi demo's. For shape design, the slowest mode of a unit canvas (k² = 2π²) decays at
// ν·2π² per second: at ν = 1 that is e^-4 within 0.2 s, so the ink stops once the pen does (the
// stylus force acts after the diffusion, so the stroke itself still carries the ink).
enum class FluidMode { Marbling, ShapeDesign };
inline constexpr double marblingViscosity = 5e-4;
inline constexpr double shapeDesignViscosity = 1.0;

inline double viscosityOf(FluidMode mode)
{
    return mode == FluidMode::Marbling ? marblingViscosity : shapeDesignViscosity;
}

struct EngineSettings {
    FlowSpec flow;
    TrackingSpec tracking;
    QString backend = QStringLiteral("opencl");  // "opencl" (falls back to "reference" without a device) or "reference"
    int device = -1;                             // OpenCL device index as `vectorfluid devices` lists; -1: automatic

    friend bool operator==(const EngineSettings&, const EngineSettings&) = default;
};

} // namespace vf::model
