#pragma once
// Generated workloads of the kinds designers make, as scenes: the yardstick of the engine's
// benchmarks (benchmarks/vf_session) and of its topology and agreement tests. Each generator takes
// a seed that varies its layout, timing and strength within what such a session looks like, so
// that measurements can be made on variations nobody tuned to.
#include "model/Scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vf::sessions {

// A marbling session (paper §5.1): a grid of ink drops falling one after another, then comb passes
// across the tray (a comb is several tines moving together) and comb passes across those.
struct MarblingOptions {
    int dropsPerSide = 5;        // a dropsPerSide² grid of drops
    double dropRadius = 0.07;
    int combPasses = 4;          // along x, alternating direction
    int crossPasses = 2;         // along y, after them
    int tines = 10;
    double tineRadius = 0.012;
    double passSeconds = 0.5;    // to cross the tray once
    double maxSpacing = 0.002;
    double dt = 0.005;
    std::int64_t steps = 900;
};
model::Scene marbling(const MarblingOptions& options, std::uint32_t seed);

// Fine detail: hundreds of small circles tracked at a very fine uniform spacing, and one fast
// stroke through them.
struct FineDetailOptions {
    int circlesPerSide = 15;
    double radius = 0.025;
    double spacing = 6e-5;       // uniform (tracking.adaptive off)
    double strokeSeconds = 0.25; // one diagonal stroke across the canvas
    double dt = 0.005;
    std::int64_t steps = 80;
};
model::Scene fineDetail(const FineDetailOptions& options, std::uint32_t seed);

// Shape design (paper §5.2): letter-like shapes in a viscous fluid, bent by short strokes with
// pauses between them, the motion dying out after each.
struct ShapeDesignOptions {
    double viscosity = 0.3;
    int strokes = 5;
    double maxSpacing = 0.0002;  // a logo's outlines, finely
    double dt = 0.005;
    std::int64_t steps = 600;
};
// Letters are polygons given by the caller (glyph outlines: model/TextOutlines needs a
// QGuiApplication, which this library does not assume), each becoming a region.
model::Scene shapeDesign(const ShapeDesignOptions& options, const std::vector<sim::Polygon>& letters,
                         std::uint32_t seed);

// The letters shapeDesign() is measured on: the outlines of a few capitals without counters, set in
// DejaVu Sans Bold across the canvas. Needs a QGuiApplication.
std::vector<sim::Polygon> designLetters(double maxSpacing);

// Target-driven design (paper §5.3, Figure 9): small ovals scattered over the canvas, their areas
// adding up to the target word's, gathered into the word. The word, the ovals' count, places and
// turns vary with the seed. Needs a QGuiApplication (the word's outline).
struct GatherOptions {
    int ovals = 60;              // about as many; the seed varies it by up to half
    double seconds = 6.0;        // the gather's duration; the scene runs 0.5 s longer
    double maxSpacing = 0.004;
    double dt = 0.01;
};
model::Scene gather(const GatherOptions& options, std::uint32_t seed);

// The names of the sessions, and the session of a name with its default options (nothing for an
// unknown name). shape-design and gather need a QGuiApplication (their letters).
const std::vector<std::string>& names();
std::optional<model::Scene> byName(const std::string& name, std::uint32_t seed);

} // namespace vf::sessions
