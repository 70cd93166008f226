#pragma once
// The scene file (*.vfscene) as data: what docs/scene-format.md describes, already validated.
// SceneReader fills it from JSON, SceneWriter writes it back, SceneRunner plays it.
#include "model/SvgImport.h"
#include "sim/ExactMap.h"
#include "sim/TargetDrive.h"
#include "sim/Geometry.h"

#include <QByteArray>
#include <QColor>
#include <QString>

#include <cstdint>
#include <variant>
#include <vector>

namespace vf::model {

struct Canvas {
    double width = 1.0;
    double height = 1.0;
    QColor background = QColor(255, 255, 255);

    friend bool operator==(const Canvas&, const Canvas&) = default;
};

struct FlowSpec {
    enum class Type { Fluid, Analytic };
    Type type = Type::Fluid;
    // fluid
    int gridX = 64;
    int gridY = 64;
    double viscosity = 5e-4;
    bool maccormack = true;  // "advection": "maccormack" | "semi-lagrangian"
    // analytic: muparser expressions in x, y, t (canvas units, seconds)
    QString u;
    QString v;
    // fluid: how a stylus stirs it
    double stylusResponse = 0.02;  // s; sim::FluidSettings::stylusResponse
    double stylusRadius = 0.03;    // canvas units: the radius of the strokes drawn in the app

    friend bool operator==(const FlowSpec&, const FlowSpec&) = default;
};

struct TimeSpec {
    double dt = 0.002;
    std::int64_t steps = 500;

    friend bool operator==(const TimeSpec&, const TimeSpec&) = default;
};

struct TrackingSpec {
    double maxSpacing = 0.004;
    bool adaptive = true;
    bool proximity = true;
    bool areaCorrection = false;
    std::int64_t maxVertices = 4'000'000;

    friend bool operator==(const TrackingSpec&, const TrackingSpec&) = default;
};

// Equality is exact (a read of a written scene must give back the same numbers).
struct CircleShape {
    sim::Vec2 center;
    double radius = 0.0;
    friend bool operator==(const CircleShape&, const CircleShape&) = default;
};
struct EllipseShape {
    sim::Vec2 center;
    sim::Vec2 radii;
    friend bool operator==(const EllipseShape&, const EllipseShape&) = default;
};
struct RectShape {
    sim::Vec2 topLeft;
    sim::Vec2 size;
    friend bool operator==(const RectShape&, const RectShape&) = default;
};
struct PolygonShape {
    sim::Polygon points;
    friend bool operator==(const PolygonShape&, const PolygonShape&) = default;
};
// The filled shapes of an SVG file, imported as File > Import SVG does (model/SvgImport.h): the
// drawing fitted to the canvas, curves flattened at tracking.max_spacing. The reader fills every
// field; equal file and text import to equal shapes on the same canvas and spacing.
struct SvgShape {
    QString file;     // as the scene gives it: relative to the scene file's folder, or absolute
    QByteArray text;  // the SVG document (a project carries it, so that it opens without the file)
    std::vector<ImportedShape> shapes;  // bottom to top, at least one
    double spacing = 0.0;               // the tracking.max_spacing they were imported at
    friend bool operator==(const SvgShape& a, const SvgShape& b) { return a.file == b.file && a.text == b.text; }
};
using Shape = std::variant<CircleShape, EllipseShape, RectShape, PolygonShape, SvgShape>;

// The closed contours of a shape, edges no longer than maxSpacing, each with positive
// sim::signedArea like every contour the engine creates (clockwise as seen on screen, y down).
// An SVG shape gives the contours of all its shapes; startingRegions keeps them apart.
std::vector<sim::Polygon> shapeContours(const Shape& shape, double maxSpacing);
// An upper bound on the vertices shapeContours(shape, maxSpacing) creates, computed without
// creating them; a double so that absurd inputs cannot overflow. The reader uses it to refuse
// scenes whose starting shapes alone exceed tracking.max_vertices.
double shapeVertexBound(const Shape& shape, double maxSpacing);

struct RegionSpec {
    QString name;
    QColor color;  // invalid: an SVG shape's own colours
    bool visible = true;
    Shape shape;

    friend bool operator==(const RegionSpec&, const RegionSpec&) = default;
};

// What a scene region starts as in the simulation: itself, or for an SVG shape one region per
// shape of the file, named "<region name>/<shape name>" and in the region's colour if it has one,
// else the file's (docs/scene-format.md, "Shapes from SVG files").
struct StartingRegion {
    QString name;
    QColor color;
    bool visible = true;
    std::vector<sim::Polygon> contours;  // empty from startingLooks
};
std::vector<StartingRegion> startingLooks(const RegionSpec& region);
std::vector<StartingRegion> startingRegions(const RegionSpec& region, double maxSpacing);

struct StylusStroke {
    double radius = 0.03;
    std::vector<sim::Vec2> points;  // positions
    std::vector<double> times;      // one per point, non-decreasing, seconds of simulated time

    friend bool operator==(const StylusStroke&, const StylusStroke&) = default;
};

struct DropStroke {
    double time = 0.0;
    sim::Vec2 center;
    double radius = 0.0;
    QColor color;
    QString name;  // empty: "drop N"

    friend bool operator==(const DropStroke&, const DropStroke&) = default;
};

// A comb (rake) drawn across the tray at `time`: exactly, as the map of sim/Comb.h applied to the
// ink at once, or in the water, as one stylus per tine moving together for `duration` seconds.
// With an amplitude its tines are waves (sim/Comb.h), which in the water they trace.
struct CombStroke {
    enum class Mode { Water, Exact };
    Mode mode = Mode::Water;
    double time = 0.0;
    sim::Vec2 from, to;
    int tines = 1;
    double spacing = 0.1;     // between tines, canvas units
    double sharpness = 0.02;  // exact: u of the map, canvas units
    double duration = 0.5;    // water: seconds the tines take from `from` to `to`
    double radius = 0.03;     // water: each tine's stylus radius
    double amplitude = 0.0;   // of the tines' wave across the stroke, canvas units; 0: straight
    double wavelength = 0.2;  // of the wave, canvas units along the stroke
    double phase = 0.0;       // of the wave at the stroke's middle, degrees

    sim::Comb map() const;
    // Water: the path of tine k, as a stylus stroke (along its wave: 16 points a wavelength, at
    // most pathPoints).
    StylusStroke tineStroke(int k) const;
    friend bool operator==(const CombStroke&, const CombStroke&) = default;
};

// The most points of a tine's path in the water (a wavy or circular comb's).
inline constexpr int pathPoints = 256;

// A circular comb turned at `time` about `center`: tines on circles of radii inner_radius + k·spacing,
// exactly (sim/Whirl.h) or in the water, each tine's stylus tracing its arc for `duration` seconds
// from the ray toward +x.
struct CircularCombStroke {
    CombStroke::Mode mode = CombStroke::Mode::Water;
    double time = 0.0;
    sim::Vec2 center;
    double innerRadius = 0.1;  // the first tine's circle, canvas units
    int tines = 1;
    double spacing = 0.1;     // between the tines' circles
    double angle = 90.0;      // degrees, counter-clockwise
    double sharpness = 0.02;  // exact: u of the map
    double duration = 0.5;    // water
    double radius = 0.03;     // water: each tine's stylus radius

    sim::CircularComb map() const;
    // Water: the arc of tine k, as a stylus stroke (64 points a turn, at most pathPoints).
    StylusStroke tineStroke(int k) const;
    friend bool operator==(const CircularCombStroke&, const CircularCombStroke&) = default;
};

// A swirl (vortex) at `time`: the ink about `center` turned by `angle` degrees there, fading out
// past `radius`. Exactly, as the map of sim/Whirl.h; or in the water, as `rings` rings of styluses
// about the centre, ring k at (k + ½)·radius/rings, its styluses as wide as the rings' spacing and
// spread evenly around it (as many as cover it), each turning as far as the map turns its circle,
// all together for `duration` seconds: a wheel of fluid turning faster towards its middle.
struct SwirlStroke {
    double time = 0.0;
    sim::Vec2 center;
    double radius = 0.1;
    double angle = 180.0;
    CombStroke::Mode mode = CombStroke::Mode::Exact;
    double duration = 0.5;  // water
    int rings = 4;          // water

    sim::Swirl map() const;
    std::vector<StylusStroke> ringStrokes(int k) const;
    friend bool operator==(const SwirlStroke&, const SwirlStroke&) = default;
};

// A brush spattering ink from `time` on: `count` drops, one every `interval` seconds, landing
// uniformly within `spread` of `center`, of radii uniform in [smallest, largest] and colours drawn
// from `colors`, all drawn from `seed` (SplitMix64, so the same seed gives the same drops anywhere).
struct SpatterStroke {
    double time = 0.0;
    sim::Vec2 center;
    double spread = 0.2;
    int count = 20;
    double smallest = 0.005, largest = 0.02;
    std::vector<QColor> colors;
    std::uint64_t seed = 1;
    double interval = 0.002;

    std::vector<DropStroke> drops() const;
    friend bool operator==(const SpatterStroke&, const SpatterStroke&) = default;
};

// A traditional marbling pattern from `time` on, as a sequence of the tools above (model/Patterns.h):
// stone (drops of `colors` over the whole tray), then for the others lines drawn back and forth
// across it `spacing` apart (gel-git), and after those a comb across them: tines 2·spacing apart
// (chevron), tines `fineSpacing` apart (nonpareil), or the nonpareil's comb and a wavy comb drawn
// back (bouquet). Every pass is exact or in the water, as `mode` says.
struct PatternStroke {
    enum class Kind { Stone, GelGit, Chevron, Nonpareil, Bouquet };
    Kind kind = Kind::Stone;
    double time = 0.0;
    CombStroke::Mode mode = CombStroke::Mode::Exact;
    std::vector<QColor> colors;
    std::uint64_t seed = 1;
    double dropRadius = 0.05;   // the stone's drops: radii within a quarter of it
    double spacing = 0.1;       // the gel-git's lines
    double fineSpacing = 0.025; // the nonpareil's tines
    double shift = 0.1;         // exact: how far a pass drags the ink at its tines
    double sharpness = 0.02;    // exact: u of every pass's map
    double duration = 0.5;      // water: seconds a pass takes to cross the tray

    friend bool operator==(const PatternStroke&, const PatternStroke&) = default;
};

// Text for a target: the glyph outlines of `text` set in `font` (bold or not), the baseline
// starting at `baseline`, an em square `size` canvas units tall (model/TextOutlines.h).
struct TextTarget {
    QString text;
    QString font = QStringLiteral("DejaVu Sans");
    bool bold = true;
    sim::Vec2 baseline;
    double size = 0.2;
    friend bool operator==(const TextTarget&, const TextTarget&) = default;
};

// Target-driven design (sim/TargetDrive.h) from `time` for `duration` seconds: the fluid draws
// the ink into `target`, a shape (not an SVG file) or text.
struct GatherStroke {
    double time = 0.0;
    double duration = 3.0;
    std::variant<Shape, TextTarget> target;
    sim::TargetDriveSettings drive;
    // The target's outline (even-odd), filled by the reader: text is set with the fonts installed.
    std::vector<sim::Polygon> contours;

    // The outline follows from the rest.
    friend bool operator==(const GatherStroke& a, const GatherStroke& b)
    {
        return a.time == b.time && a.duration == b.duration && a.target == b.target && a.drive == b.drive;
    }
};

// The outline of a gather's target at `spacing`: a shape's contours, or the text's glyphs. Text
// needs a QGuiApplication (the font database); without one it gives no contours.
std::vector<sim::Polygon> targetContours(const std::variant<Shape, TextTarget>& target, double spacing);

using Stroke = std::variant<StylusStroke, DropStroke, CombStroke, CircularCombStroke, SwirlStroke, SpatterStroke,
                            PatternStroke, GatherStroke>;

struct Scene {
    Canvas canvas;
    FlowSpec flow;
    TimeSpec time;
    TrackingSpec tracking;
    std::vector<RegionSpec> regions;
    std::vector<Stroke> strokes;

    friend bool operator==(const Scene&, const Scene&) = default;
};

// Documented limits (docs/scene-format.md); the reader rejects anything beyond them.
namespace limits {
inline constexpr int maxGrid = 1024;
inline constexpr int minGrid = 4;
inline constexpr std::int64_t maxSteps = 100'000'000;
inline constexpr std::int64_t maxVertices = 1'000'000'000;
inline constexpr std::size_t maxRegions = 100'000;
inline constexpr std::size_t maxPolygonPoints = 10'000'000;
inline constexpr std::size_t maxStrokes = 1'000'000;
inline constexpr int maxTines = 1000;
inline constexpr int maxSpatterDrops = 10'000;
inline constexpr int maxSpatterColors = 256;
inline constexpr double maxCanvasSize = 1e6;
// Shorter lengths vanish next to coordinates of up to 1e6 (a double holds about 16 digits): a circle
// that small would have all its vertices on one point, a canvas that narrow an infinite scale.
inline constexpr double minLength = 1e-9;
} // namespace limits

} // namespace vf::model
