#pragma once
// What a render will hold in memory at its largest, estimated from the scene and the options
// before anything is allocated, against the memory this machine has available: a scene value or a
// flag that could not fit is refused at once, in one line, instead of ending in std::bad_alloc or
// swapping after hours of steps.
#include "app/RenderOptions.h"
#include "model/Scene.h"
#include "render/Exporter.h"

#include <QString>

#include <cstdint>

namespace vf::app {

// Bytes of memory available now (Linux: MemAvailable), or 0 when unknown (then nothing is refused).
double availableMemory();

// An empty string, or one line naming each part of the estimate, its limit and the total.
[[nodiscard]] QString checkMemory(const model::Scene& scene, const RenderOptions& options, double available);

// The parts of the estimate, for the app to hold its settings and exports to the same limits.
double vertexBytes(std::int64_t maxVertices);
double gridBytes(const model::FlowSpec& flow);  // 0 for an analytic flow, which has no grid
double pngBytes(const render::RasterSize& pixels);
// The largest tracking.max_vertices whose estimate fits in `available` beside `flow`'s grid (may
// be below any usable count); INT64_MAX when `available` is unknown (0).
std::int64_t maxVerticesFitting(const model::FlowSpec& flow, double available);
// "200 GB", "1180 GB", "614 MB", "0.6 MB": three digits at most, in the larger unit that has one.
QString bytesText(double bytes);

} // namespace vf::app
