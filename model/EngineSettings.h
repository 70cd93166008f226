#pragma once
// The simulation settings a user edits in the app (the Simulation dock): the flow and tracking of
// the scene format, and which backend runs them. Changing them is one undoable command.
#include "model/Scene.h"

#include <QString>

namespace vf::model {

// The two fluid modes of the paper: marbling (§5.1, low viscosity, motion persists) and shape
// design (§5.2, high viscosity, motion dies right after each stroke). Marbling is the
// sumi-nagashi demo's. Shape design must do two things at once: carry the ink under the pen
// along with it, and stop within about half a second of the pen (tst_shapedesign measures both).
// A viscosity high enough to stop the motion (ν = 0.1: the flow a broad pen leaves decays at about
// ν/r² = 20 per second) also spreads the pen's push over its neighbourhood within a step, so the
// pen sets the fluid under it to its own velocity (a response of 1 ms, against marbling's 20 ms
// of gentle drag), and a broad pen keeps the carried ink inside its reach.
enum class FluidMode { Marbling, ShapeDesign };

struct FluidPreset {
    double viscosity;
    double stylusResponse;
    double stylusRadius;
};
inline constexpr FluidPreset marblingPreset{5e-4, 0.02, 0.03};
inline constexpr FluidPreset shapeDesignPreset{0.1, 0.001, 0.07};

inline const FluidPreset& presetOf(FluidMode mode)
{
    return mode == FluidMode::Marbling ? marblingPreset : shapeDesignPreset;
}

inline void applyPreset(FlowSpec& flow, FluidMode mode)
{
    const FluidPreset& preset = presetOf(mode);
    flow.viscosity = preset.viscosity;
    flow.stylusResponse = preset.stylusResponse;
    flow.stylusRadius = preset.stylusRadius;
}

// Whether the flow is the mode's preset exactly; any other values are a custom fluid.
inline bool isPreset(const FlowSpec& flow, FluidMode mode)
{
    const FluidPreset& preset = presetOf(mode);
    return flow.viscosity == preset.viscosity && flow.stylusResponse == preset.stylusResponse
        && flow.stylusRadius == preset.stylusRadius;
}

struct EngineSettings {
    FlowSpec flow;
    TrackingSpec tracking;
    QString backend = QStringLiteral("opencl");  // "opencl" (falls back to "reference" without a device) or "reference"
    int device = -1;                             // OpenCL device index as `vectorfluid devices` lists; -1: automatic

    friend bool operator==(const EngineSettings&, const EngineSettings&) = default;
};

} // namespace vf::model
