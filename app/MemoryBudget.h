#pragma once
// What a render will hold in memory at its largest, estimated from the scene and the options
// before anything is allocated, against the memory this machine has available: a scene value or a
// flag that could not fit is refused at once, in one line, instead of ending in std::bad_alloc or
// swapping after hours of steps.
#include "app/RenderOptions.h"
#include "model/Scene.h"

#include <QString>

namespace vf::app {

// Bytes of memory available now (Linux: MemAvailable), or 0 when unknown (then nothing is refused).
double availableMemory();

// An empty string, or one line naming each part of the estimate, its limit and the total.
[[nodiscard]] QString checkMemory(const model::Scene& scene, const RenderOptions& options, double available);

} // namespace vf::app
