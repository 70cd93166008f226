// Reading *.vfscene files (docs/scene-format.md). Everything a file can get wrong is caught here
// and reported as one line "<file>: <key path or line:col>: <what is wrong>", so the rest of the
// program only ever sees a valid Scene. About 690 lines: one short reader per section, shape and
// stroke type of the format, all on the Field helpers of SceneJson.h; a new type adds its reader.
// The seam for a split is the checks across keys run once all are read (flow and tools, names,
// targets, patterns, the vertex budget), which could become a file of their own.
#include "model/Patterns.h"
#include "model/SceneFile.h"
#include "model/SceneJson.h"

#include "sim/AnalyticFlow.h"
#include "sim/Coverage.h"
#include "sim/Crossings.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QJsonDocument>

#include <limits>

namespace vf::model {
namespace {

using namespace Qt::StringLiterals;
using namespace json;

constexpr int kVersion = 1;

constexpr double kHuge = std::numeric_limits<double>::max();

// ---- primitive values -------------------------------------------------------------------------

// Shapes may lie outside the canvas, but coordinates this far out only come from mistakes.
double coordinate(const Field& field) { return field.number(-limits::maxCanvasSize, limits::maxCanvasSize); }
double length(const Field& field)
{
    const double value = field.positive(limits::maxCanvasSize);
    if (value < limits::minLength)
        field.fail(u"must be at least %1, is %2"_s.arg(limits::minLength).arg(value));
    return value;
}
double seconds(const Field& field) { return field.nonNegative(); }

sim::Vec2 point(const Field& field)
{
    const QJsonArray xy = field.array(2, 2);
    return {coordinate(field.element(xy, 0)), coordinate(field.element(xy, 1))};
}

sim::Vec2 lengths(const Field& field)
{
    const QJsonArray wh = field.array(2, 2);
    return {length(field.element(wh, 0)), length(field.element(wh, 1))};
}

QString expression(const Field& field)
{
    const QString text = field.string();
    const std::string error = sim::AnalyticFlow::check(text.toStdString());
    if (!error.empty())
        field.fail(QString::fromStdString(error));  // names the expression and what muparser found
    return text;
}

// ---- canvas, flow, time, tracking -------------------------------------------------------------

const Key<Canvas> canvasKeys[] = {
    {u"width"_s, false, [](const Field& f, Canvas& c) { c.width = length(f); }},
    {u"height"_s, false, [](const Field& f, Canvas& c) { c.height = length(f); }},
    {u"background"_s, false, [](const Field& f, Canvas& c) { c.background = color(f); }},
};

void readFlowType(const Field& field, FlowSpec& flow)
{
    flow.type = field.choice<FlowSpec::Type>({{u"fluid"_s, FlowSpec::Type::Fluid},
                                              {u"analytic"_s, FlowSpec::Type::Analytic}});
}

void readGrid(const Field& field, FlowSpec& flow)
{
    const QJsonArray grid = field.array(2, 2);
    flow.gridX = static_cast<int>(field.element(grid, 0).integer(limits::minGrid, limits::maxGrid));
    flow.gridY = static_cast<int>(field.element(grid, 1).integer(limits::minGrid, limits::maxGrid));
}

const Key<FlowSpec> fluidKeys[] = {
    {u"type"_s, false, readFlowType},
    {u"grid"_s, false, readGrid},
    {u"viscosity"_s, false, [](const Field& f, FlowSpec& flow) { flow.viscosity = f.nonNegative(); }},
    {u"stylus_response"_s, false, [](const Field& f, FlowSpec& flow) { flow.stylusResponse = f.nonNegative(); }},
    {u"stylus_radius"_s, false, [](const Field& f, FlowSpec& flow) { flow.stylusRadius = length(f); }},
    {u"advection"_s, false, [](const Field& f, FlowSpec& flow) {
         flow.maccormack = f.choice<bool>({{u"maccormack"_s, true}, {u"semi-lagrangian"_s, false}});
     }},
};

const Key<FlowSpec> analyticKeys[] = {
    {u"type"_s, true, readFlowType},
    {u"u"_s, true, [](const Field& f, FlowSpec& flow) { flow.u = expression(f); }},
    {u"v"_s, true, [](const Field& f, FlowSpec& flow) { flow.v = expression(f); }},
};

} // namespace

FlowSpec readFlowObject(const Field& field)
{
    FlowSpec flow;
    if (const Field type = field.member(u"type"_s); type.exists())
        readFlowType(type, flow);
    const bool fluid = flow.type == FlowSpec::Type::Fluid;
    const std::span<const Key<FlowSpec>> keys = fluid ? std::span<const Key<FlowSpec>>(fluidKeys) : analyticKeys;
    const std::span<const Key<FlowSpec>> otherKeys = fluid ? std::span<const Key<FlowSpec>>(analyticKeys) : fluidKeys;
    // A key of the other flow type is a likelier mistake than a typo: say so.
    for (const QString& key : field.object().keys()) {
        if (!hasKey(keys, key) && hasKey(otherKeys, key))
            field.member(key).fail(u"only allowed with \"type\": \"%1\""_s.arg(fluid ? u"analytic"_s : u"fluid"_s));
    }
    readObject(field, flow, keys);
    return flow;
}

namespace {

const Key<TimeSpec> timeKeys[] = {
    {u"dt"_s, false, [](const Field& f, TimeSpec& t) { t.dt = f.positive(kHuge); }},
    {u"steps"_s, false, [](const Field& f, TimeSpec& t) { t.steps = f.integer(0, limits::maxSteps); }},
};

const Key<TrackingSpec> trackingKeys[] = {
    {u"max_spacing"_s, false, [](const Field& f, TrackingSpec& t) { t.maxSpacing = length(f); }},
    {u"adaptive"_s, false, [](const Field& f, TrackingSpec& t) { t.adaptive = f.boolean(); }},
    {u"proximity"_s, false, [](const Field& f, TrackingSpec& t) { t.proximity = f.boolean(); }},
    {u"area_correction"_s, false, [](const Field& f, TrackingSpec& t) { t.areaCorrection = f.boolean(); }},
    {u"max_vertices"_s, false, [](const Field& f, TrackingSpec& t) { t.maxVertices = f.integer(3, limits::maxVertices); }},  // a contour has at least 3
};

} // namespace

TrackingSpec readTrackingObject(const Field& field)
{
    return readAs(field, trackingKeys);
}

namespace {

// ---- regions and their shapes -----------------------------------------------------------------

const Key<CircleShape> circleKeys[] = {
    {u"center"_s, true, [](const Field& f, CircleShape& c) { c.center = point(f); }},
    {u"radius"_s, true, [](const Field& f, CircleShape& c) { c.radius = length(f); }},
};

const Key<EllipseShape> ellipseKeys[] = {
    {u"center"_s, true, [](const Field& f, EllipseShape& e) { e.center = point(f); }},
    {u"radii"_s, true, [](const Field& f, EllipseShape& e) { e.radii = lengths(f); }},
};

const Key<RectShape> rectKeys[] = {
    {u"position"_s, true, [](const Field& f, RectShape& r) { r.topLeft = point(f); }},
    {u"size"_s, true, [](const Field& f, RectShape& r) { r.size = lengths(f); }},
};

// Polygons close themselves; a repeated point (often the first one written again at the end)
// would be a zero-length edge that the tracker cannot orient.
PolygonShape readPolygon(const Field& field)
{
    PolygonShape polygon{readList<sim::Vec2>(field, 3, static_cast<qsizetype>(limits::maxPolygonPoints), point)};
    const sim::Polygon& points = polygon.points;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const std::size_t previous = (i + points.size() - 1) % points.size();
        if (points[i] == points[previous])
            field.fail(u"point %1 repeats point %2 (a polygon closes itself: leave the last point out)"_s.arg(i).arg(previous));
    }
    if (!sim::isSimple(points))
        field.fail(u"the polygon crosses or touches itself"_s);
    const double scale = sim::perimeter(points);
    if (std::abs(sim::signedArea(points)) <= 1e-12 * scale * scale)
        field.fail(u"the polygon encloses no area"_s);
    return polygon;
}

// The file's shapes are imported once the whole scene is read (importSvgShapes): they depend on the
// canvas and the spacing. A project writes the object form, which carries the file's contents.
const Key<SvgShape> svgKeys[] = {
    {u"file"_s, true, [](const Field& f, SvgShape& svg) { svg.file = f.name(); }},
    {u"base64"_s, true, [](const Field& f, SvgShape& svg) {
         const auto decoded = QByteArray::fromBase64Encoding(f.string().toLatin1(), QByteArray::AbortOnBase64DecodingErrors);
         if (!decoded || decoded.decoded.isEmpty())
             f.fail(u"must be the SVG document in base64"_s);
         svg.text = *decoded;
     }},
};

SvgShape readSvg(const Field& field)
{
    if (field.isObject())
        return readAs(field, svgKeys);
    return SvgShape{field.name(), {}, {}};
}

// Each key is a kind of shape; the object must hold exactly one of them.
const Key<Shape> shapeKeys[] = {
    {u"circle"_s, false, [](const Field& f, Shape& s) { s = readAs(f, circleKeys); }},
    {u"ellipse"_s, false, [](const Field& f, Shape& s) { s = readAs(f, ellipseKeys); }},
    {u"rect"_s, false, [](const Field& f, Shape& s) { s = readAs(f, rectKeys); }},
    {u"polygon"_s, false, [](const Field& f, Shape& s) { s = readPolygon(f); }},
    {u"svg"_s, false, [](const Field& f, Shape& s) { s = readSvg(f); }},
};

void readShape(const Field& field, RegionSpec& region)
{
    const std::span<const Key<Shape>> keys(shapeKeys);
    if (const qsizetype count = field.object().size(); count != 1)
        field.fail(u"must have exactly one key, one of: %1 (has %2)"_s.arg(keyList(keys)).arg(count));
    readObject(field, region.shape, keys);
}

const Key<RegionSpec> regionKeys[] = {
    {u"name"_s, true, [](const Field& f, RegionSpec& r) { r.name = f.name(); }},
    {u"color"_s, false, [](const Field& f, RegionSpec& r) { r.color = color(f); }},
    {u"visible"_s, false, [](const Field& f, RegionSpec& r) { r.visible = f.boolean(); }},
    {u"shape"_s, true, readShape},
};

// Only an SVG shape may leave its colours to the file.
RegionSpec readRegion(const Field& field)
{
    RegionSpec region = readAs(field, regionKeys);
    if (!region.color.isValid() && !std::holds_alternative<SvgShape>(region.shape))
        field.member(u"color"_s).fail(u"missing (required unless the shape is an SVG file)"_s);
    return region;
}

// ---- strokes ----------------------------------------------------------------------------------

void readStylusPoints(const Field& field, StylusStroke& stroke)
{
    const QJsonArray points = field.array(2, static_cast<qsizetype>(limits::maxPolygonPoints));
    for (qsizetype i = 0; i < points.size(); ++i) {
        const Field pointField = field.element(points, i);
        const QJsonArray xyt = pointField.array(3, 3);
        const double t = seconds(pointField.element(xyt, 2));
        if (!stroke.times.empty() && t < stroke.times.back())
            pointField.fail(u"time %1 is before the previous point's %2 (times must not decrease)"_s.arg(t).arg(stroke.times.back()));
        stroke.points.emplace_back(coordinate(pointField.element(xyt, 0)), coordinate(pointField.element(xyt, 1)));
        stroke.times.push_back(t);
    }
}

const Key<StylusStroke> stylusKeys[] = {
    {u"tool"_s, true, readAlready<StylusStroke>},
    {u"radius"_s, false, [](const Field& f, StylusStroke& s) { s.radius = length(f); }},
    {u"points"_s, true, readStylusPoints},
};

const Key<DropStroke> dropKeys[] = {
    {u"tool"_s, true, readAlready<DropStroke>},
    {u"time"_s, true, [](const Field& f, DropStroke& d) { d.time = seconds(f); }},
    {u"center"_s, true, [](const Field& f, DropStroke& d) { d.center = point(f); }},
    {u"radius"_s, true, [](const Field& f, DropStroke& d) { d.radius = length(f); }},
    {u"color"_s, true, [](const Field& f, DropStroke& d) { d.color = color(f); }},
    {u"name"_s, false, [](const Field& f, DropStroke& d) { d.name = f.name(); }},
};

CombStroke::Mode combMode(const Field& f)
{
    return f.choice<CombStroke::Mode>({{u"water"_s, CombStroke::Mode::Water}, {u"exact"_s, CombStroke::Mode::Exact}});
}

const Key<CombStroke> combKeys[] = {
    {u"tool"_s, true, readAlready<CombStroke>},
    {u"mode"_s, false,
     [](const Field& f, CombStroke& c) { c.mode = combMode(f); }},
    {u"time"_s, true, [](const Field& f, CombStroke& c) { c.time = seconds(f); }},
    {u"from"_s, true, [](const Field& f, CombStroke& c) { c.from = point(f); }},
    {u"to"_s, true, [](const Field& f, CombStroke& c) { c.to = point(f); }},
    {u"tines"_s, false, [](const Field& f, CombStroke& c) { c.tines = int(f.integer(1, limits::maxTines)); }},
    {u"spacing"_s, false, [](const Field& f, CombStroke& c) { c.spacing = f.number(0.0, limits::maxCanvasSize); }},
    {u"sharpness"_s, false, [](const Field& f, CombStroke& c) { c.sharpness = length(f); }},
    {u"duration"_s, false, [](const Field& f, CombStroke& c) { c.duration = f.positive(kHuge); }},
    {u"radius"_s, false, [](const Field& f, CombStroke& c) { c.radius = length(f); }},
    {u"amplitude"_s, false, [](const Field& f, CombStroke& c) { c.amplitude = f.number(0.0, limits::maxCanvasSize); }},
    {u"wavelength"_s, false, [](const Field& f, CombStroke& c) { c.wavelength = length(f); }},
    {u"phase"_s, false, [](const Field& f, CombStroke& c) { c.phase = f.number(-360.0, 360.0); }},
};

// A turn of ten revolutions at most: more only winds the ink into rings finer than any spacing.
double turnDegrees(const Field& f) { return f.number(-3600.0, 3600.0); }

const Key<CircularCombStroke> circularCombKeys[] = {
    {u"tool"_s, true, readAlready<CircularCombStroke>},
    {u"mode"_s, false, [](const Field& f, CircularCombStroke& c) { c.mode = combMode(f); }},
    {u"time"_s, true, [](const Field& f, CircularCombStroke& c) { c.time = seconds(f); }},
    {u"center"_s, true, [](const Field& f, CircularCombStroke& c) { c.center = point(f); }},
    {u"inner_radius"_s, true, [](const Field& f, CircularCombStroke& c) { c.innerRadius = length(f); }},
    {u"tines"_s, false, [](const Field& f, CircularCombStroke& c) { c.tines = int(f.integer(1, limits::maxTines)); }},
    {u"spacing"_s, false, [](const Field& f, CircularCombStroke& c) { c.spacing = f.number(0.0, limits::maxCanvasSize); }},
    {u"angle"_s, true, [](const Field& f, CircularCombStroke& c) { c.angle = turnDegrees(f); }},
    {u"sharpness"_s, false, [](const Field& f, CircularCombStroke& c) { c.sharpness = length(f); }},
    {u"duration"_s, false, [](const Field& f, CircularCombStroke& c) { c.duration = f.positive(kHuge); }},
    {u"radius"_s, false, [](const Field& f, CircularCombStroke& c) { c.radius = length(f); }},
};

// [smallest, largest] drop radii.
void readRadii(const Field& f, SpatterStroke& s)
{
    const QJsonArray range = f.array(2, 2);
    s.smallest = length(f.element(range, 0));
    s.largest = length(f.element(range, 1));
    if (s.smallest > s.largest)
        f.fail(u"the smallest radius %1 is larger than the largest %2"_s.arg(s.smallest).arg(s.largest));
}

template <typename WithColors>
void readColors(const Field& f, WithColors& s)
{
    const QJsonArray list = f.array(1, limits::maxSpatterColors);
    s.colors.clear();
    for (qsizetype i = 0; i < list.size(); ++i)
        s.colors.push_back(color(f.element(list, i)));
}

// Seeds up to 2^53, which a JSON number holds exactly.
std::uint64_t seed(const Field& f) { return std::uint64_t(f.integer(0, std::int64_t(1) << 53)); }

const Key<SpatterStroke> spatterKeys[] = {
    {u"tool"_s, true, readAlready<SpatterStroke>},
    {u"time"_s, true, [](const Field& f, SpatterStroke& s) { s.time = seconds(f); }},
    {u"center"_s, true, [](const Field& f, SpatterStroke& s) { s.center = point(f); }},
    {u"spread"_s, false, [](const Field& f, SpatterStroke& s) { s.spread = f.number(0.0, limits::maxCanvasSize); }},
    {u"count"_s, false, [](const Field& f, SpatterStroke& s) { s.count = int(f.integer(1, limits::maxSpatterDrops)); }},
    {u"radius"_s, false, readRadii},
    {u"colors"_s, true, readColors<SpatterStroke>},
    {u"seed"_s, false, [](const Field& f, SpatterStroke& s) { s.seed = seed(f); }},
    {u"interval"_s, false, [](const Field& f, SpatterStroke& s) { s.interval = f.nonNegative(); }},
};

const Key<SwirlStroke> swirlKeys[] = {
    {u"tool"_s, true, readAlready<SwirlStroke>},
    {u"time"_s, true, [](const Field& f, SwirlStroke& s) { s.time = seconds(f); }},
    {u"center"_s, true, [](const Field& f, SwirlStroke& s) { s.center = point(f); }},
    {u"radius"_s, true, [](const Field& f, SwirlStroke& s) { s.radius = length(f); }},
    {u"angle"_s, true, [](const Field& f, SwirlStroke& s) { s.angle = turnDegrees(f); }},
    {u"mode"_s, false, [](const Field& f, SwirlStroke& s) { s.mode = combMode(f); }},
    {u"duration"_s, false, [](const Field& f, SwirlStroke& s) { s.duration = f.positive(kHuge); }},
    {u"rings"_s, false, [](const Field& f, SwirlStroke& s) { s.rings = int(f.integer(1, limits::maxTines)); }},
};

PatternStroke::Kind patternKind(const Field& f)
{
    using Kind = PatternStroke::Kind;
    return f.choice<Kind>({{patternName(Kind::Stone), Kind::Stone},
                           {patternName(Kind::GelGit), Kind::GelGit},
                           {patternName(Kind::Chevron), Kind::Chevron},
                           {patternName(Kind::Nonpareil), Kind::Nonpareil},
                           {patternName(Kind::Bouquet), Kind::Bouquet}});
}

const Key<PatternStroke> patternKeys[] = {
    {u"tool"_s, true, readAlready<PatternStroke>},
    {u"name"_s, true, [](const Field& f, PatternStroke& p) { p.kind = patternKind(f); }},
    {u"time"_s, true, [](const Field& f, PatternStroke& p) { p.time = seconds(f); }},
    {u"colors"_s, true, readColors<PatternStroke>},
    {u"mode"_s, false, [](const Field& f, PatternStroke& p) { p.mode = combMode(f); }},
    {u"seed"_s, false, [](const Field& f, PatternStroke& p) { p.seed = seed(f); }},
    {u"drop_radius"_s, false, [](const Field& f, PatternStroke& p) { p.dropRadius = length(f); }},
    {u"spacing"_s, false, [](const Field& f, PatternStroke& p) { p.spacing = length(f); }},
    {u"fine_spacing"_s, false, [](const Field& f, PatternStroke& p) { p.fineSpacing = length(f); }},
    {u"shift"_s, false, [](const Field& f, PatternStroke& p) { p.shift = length(f); }},
    {u"sharpness"_s, false, [](const Field& f, PatternStroke& p) { p.sharpness = length(f); }},
    {u"duration"_s, false, [](const Field& f, PatternStroke& p) { p.duration = f.positive(kHuge); }},
};

const Key<TextTarget> textKeys[] = {
    {u"string"_s, true, [](const Field& f, TextTarget& t) {
         t.text = f.string();
         if (t.text.trimmed().isEmpty())
             f.fail(u"must hold some text"_s);
     }},
    {u"font"_s, false, [](const Field& f, TextTarget& t) { t.font = f.string(); }},
    {u"bold"_s, false, [](const Field& f, TextTarget& t) { t.bold = f.boolean(); }},
    {u"baseline"_s, true, [](const Field& f, TextTarget& t) { t.baseline = point(f); }},
    {u"size"_s, true, [](const Field& f, TextTarget& t) { t.size = length(f); }},
};

// Each key is a kind of target; the object must hold exactly one of them. The region shapes but an
// SVG file, or text.
const Key<GatherStroke> targetKeys[] = {
    {u"circle"_s, false, [](const Field& f, GatherStroke& g) { g.target = Shape(readAs(f, circleKeys)); }},
    {u"ellipse"_s, false, [](const Field& f, GatherStroke& g) { g.target = Shape(readAs(f, ellipseKeys)); }},
    {u"rect"_s, false, [](const Field& f, GatherStroke& g) { g.target = Shape(readAs(f, rectKeys)); }},
    {u"polygon"_s, false, [](const Field& f, GatherStroke& g) { g.target = Shape(readPolygon(f)); }},
    {u"text"_s, false, [](const Field& f, GatherStroke& g) { g.target = readAs(f, textKeys); }},
};

void readTarget(const Field& field, GatherStroke& gather)
{
    const std::span<const Key<GatherStroke>> keys(targetKeys);
    if (const qsizetype count = field.object().size(); count != 1)
        field.fail(u"must have exactly one key, one of: %1 (has %2)"_s.arg(keyList(keys)).arg(count));
    readObject(field, gather, keys);
}

const Key<GatherStroke> gatherKeys[] = {
    {u"tool"_s, true, readAlready<GatherStroke>},
    {u"time"_s, true, [](const Field& f, GatherStroke& g) { g.time = seconds(f); }},
    {u"duration"_s, false, [](const Field& f, GatherStroke& g) { g.duration = f.positive(kHuge); }},
    {u"target"_s, true, readTarget},
    {u"strength"_s, false, [](const Field& f, GatherStroke& g) { g.drive.strength = f.nonNegative(); }},
    {u"attenuation"_s, false, [](const Field& f, GatherStroke& g) { g.drive.attenuation = f.nonNegative(); }},
    {u"gathering"_s, false, [](const Field& f, GatherStroke& g) { g.drive.gathering = f.nonNegative(); }},
    {u"blur"_s, false, [](const Field& f, GatherStroke& g) { g.drive.blur = length(f); }},
};

Stroke readStroke(const Field& field)
{
    enum class Tool { Stylus, Drop, Comb, CircularComb, Swirl, Spatter, Pattern, Gather };
    const Field tool = field.member(u"tool"_s);
    if (!tool.exists())
        tool.fail(u"missing (required)"_s);
    switch (tool.choice<Tool>({{u"stylus"_s, Tool::Stylus},
                               {u"drop"_s, Tool::Drop},
                               {u"comb"_s, Tool::Comb},
                               {u"circular-comb"_s, Tool::CircularComb},
                               {u"swirl"_s, Tool::Swirl},
                               {u"spatter"_s, Tool::Spatter},
                               {u"pattern"_s, Tool::Pattern},
                               {u"gather"_s, Tool::Gather}})) {
    case Tool::Stylus:
        return readAs(field, stylusKeys);
    case Tool::Drop:
        return readAs(field, dropKeys);
    case Tool::Comb:
        return readAs(field, combKeys);
    case Tool::CircularComb:
        return readAs(field, circularCombKeys);
    case Tool::Swirl:
        return readAs(field, swirlKeys);
    case Tool::Spatter:
        return readAs(field, spatterKeys);
    case Tool::Gather:
        return readAs(field, gatherKeys);
    case Tool::Pattern:
        break;
    }
    return readAs(field, patternKeys);
}

// ---- the whole scene --------------------------------------------------------------------------

void readVersion(const Field& field, Scene&)
{
    if (!field.exists())
        field.fail(u"missing: this is not a vectorfluid scene (expected \"vectorfluid\": %1)"_s.arg(kVersion));
    const double version = field.number();
    if (version != kVersion)
        field.fail(u"version %1 is not supported (this program reads version %2)"_s.arg(version).arg(kVersion));
}

const Key<Scene> sceneKeys[] = {
    {u"vectorfluid"_s, true, readVersion},
    {u"canvas"_s, false, [](const Field& f, Scene& s) { s.canvas = readAs(f, canvasKeys); }},
    {u"flow"_s, false, [](const Field& f, Scene& s) { s.flow = readFlowObject(f); }},
    {u"time"_s, false, [](const Field& f, Scene& s) { s.time = readAs(f, timeKeys); }},
    {u"tracking"_s, false, [](const Field& f, Scene& s) { s.tracking = readTrackingObject(f); }},
    {u"regions"_s, false, [](const Field& f, Scene& s) {
         s.regions = readList<RegionSpec>(f, 0, static_cast<qsizetype>(limits::maxRegions),
                                          readRegion);
     }},
    {u"strokes"_s, false, [](const Field& f, Scene& s) {
         s.strokes = readList<Stroke>(f, 0, static_cast<qsizetype>(limits::maxStrokes), readStroke);
     }},
};

// Whether a tool with a mode (the combs, the swirl) acts in the water.
bool inWater(const Stroke& stroke)
{
    return std::visit(
        [](const auto& tool) {
            if constexpr (requires { tool.mode; })
                return tool.mode == CombStroke::Mode::Water;
            else
                return false;
        },
        stroke);
}

// Checks that span several keys, run after every key has been read on its own. `root` is the path
// of the scene object (the top level of a scene file).
KeyPath itemPath(const KeyPath& root, const QString& list, qsizetype i) { return root.key(list).index(i); }

void checkStrokesFitFlow(const Scene& scene, const KeyPath& root)
{
    if (scene.flow.type != FlowSpec::Type::Analytic)
        return;
    for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
        if (std::holds_alternative<StylusStroke>(scene.strokes[i]))
            itemPath(root, u"strokes"_s, i).key(u"tool"_s).fail(
                u"a stylus needs \"flow\": {\"type\": \"fluid\"}: an analytic flow is prescribed and does not react to it"_s);
        if (std::holds_alternative<GatherStroke>(scene.strokes[i]))
            itemPath(root, u"strokes"_s, i).key(u"tool"_s).fail(
                u"gathering needs \"flow\": {\"type\": \"fluid\"}: it drives the fluid"_s);
        if (inWater(scene.strokes[i]))
            itemPath(root, u"strokes"_s, i).key(u"mode"_s).fail(
                u"a tool in the water needs \"flow\": {\"type\": \"fluid\"}; use \"mode\": \"exact\" with an analytic flow"_s);
    }
}

// Names become SVG ids and layer labels, so region and drop names share one namespace.
void checkNamesUnique(const Scene& scene, const KeyPath& root)
{
    QHash<QString, QString> owners;  // name -> where it was first used
    auto claim = [&owners, &root](const QString& name, const QString& list, qsizetype i) {
        if (name.isEmpty())
            return;
        if (const auto it = owners.constFind(name); it != owners.constEnd())
            itemPath(root, list, i).key(u"name"_s).fail(u"the name %1 is already used by %2"_s.arg(quoted(name), it.value()));
        owners.insert(name, u"%1[%2]"_s.arg(list).arg(i));
    };
    for (std::size_t i = 0; i < scene.regions.size(); ++i)
        for (const StartingRegion& look : startingLooks(scene.regions[i]))
            claim(look.name, u"regions"_s, i);
    for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
        if (const auto* drop = std::get_if<DropStroke>(&scene.strokes[i]))
            claim(drop->name, u"strokes"_s, i);
    }
}

// Imports the SVG files of the regions' shapes as File > Import SVG does, with the canvas and
// spacing just read; the importer's one-line error goes out under the shape's key path. Files are
// found relative to `folder`; without one (a project) every SVG shape must carry its contents.
void importSvgShapes(Scene& scene, const KeyPath& root, const QString& folder)
{
    std::size_t regionCount = 0;
    for (std::size_t i = 0; i < scene.regions.size(); ++i) {
        auto* svg = std::get_if<SvgShape>(&scene.regions[i].shape);
        if (!svg) {
            ++regionCount;
            continue;
        }
        const KeyPath path = itemPath(root, u"regions"_s, i).key(u"shape"_s).key(u"svg"_s);
        SvgImport imported;
        if (!svg->text.isEmpty()) {
            imported = importSvg(svg->text, QFileInfo(svg->file).fileName(), scene.canvas.width, scene.canvas.height,
                                 scene.tracking.maxSpacing);
        } else {
            if (folder.isEmpty())
                path.fail(u"the SVG's contents are missing: here it must be {\"file\": …, \"base64\": …}"_s);
            const QString file = QDir(folder).filePath(svg->file);
            imported = importSvgFile(file, scene.canvas.width, scene.canvas.height, scene.tracking.maxSpacing);
            if (imported.ok()) {
                // Kept for a project, which carries it. The importer has checked the file's size.
                QFile contents(file);
                if (!contents.open(QIODevice::ReadOnly))
                    path.fail(u"%1: %2"_s.arg(svg->file, contents.errorString()));
                svg->text = contents.readAll();
            }
        }
        if (!imported.ok())
            path.fail(imported.error);
        svg->shapes = std::move(imported.shapes);
        svg->spacing = scene.tracking.maxSpacing;
        regionCount += svg->shapes.size();
        if (regionCount > limits::maxRegions)
            path.fail(u"its shapes take the starting regions to %1, over the limit of %2"_s.arg(regionCount).arg(limits::maxRegions));
    }
}

// A pattern's drops and tines are counted on the canvas, before any is made.
void checkPatternsFit(const Scene& scene, const KeyPath& root)
{
    for (std::size_t i = 0; i < scene.strokes.size(); ++i)
        if (const auto* pattern = std::get_if<PatternStroke>(&scene.strokes[i]))
            if (const auto problem = patternProblem(*pattern, scene.canvas))
                itemPath(root, u"strokes"_s, i).key(problem->key).fail(problem->message);
}

// Each gather's target outlined at the scene's spacing, which must cover some of the fluid grid.
void outlineTargets(Scene& scene, const KeyPath& root)
{
    const sim::CellLattice grid{scene.flow.gridX, scene.flow.gridY, scene.canvas.width, scene.canvas.height};
    for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
        auto* gather = std::get_if<GatherStroke>(&scene.strokes[i]);
        if (!gather)
            continue;
        gather->contours = targetContours(gather->target, scene.tracking.maxSpacing);
        const KeyPath target = itemPath(root, u"strokes"_s, i).key(u"target"_s);
        if (gather->contours.empty())
            target.fail(u"the text gives no outline: no glyphs, or no fonts (text needs the app or `vectorfluid render`)"_s);
        const std::vector<double> covered = sim::coverage({gather->contours}, grid, 4);
        if (std::all_of(covered.begin(), covered.end(), [](double c) { return c == 0.0; }))
            target.fail(u"lies outside the canvas"_s);
    }
}

// The starting shapes (and the circles drops add) must fit the vertex budget; without this check a
// tiny max_spacing would make the program try to allocate billions of vertices before any step.
void checkVertexBudget(const Scene& scene, const KeyPath& root)
{
    const double maxSpacing = scene.tracking.maxSpacing;
    const auto budget = static_cast<double>(scene.tracking.maxVertices);
    double needed = 0.0;
    auto add = [&](const Shape& shape, const KeyPath& path) {
        needed += shapeVertexBound(shape, maxSpacing);
        if (needed > budget)
            path.fail(u"the shapes up to here need about %1 vertices at tracking.max_spacing %2, over tracking.max_vertices %3"_s
                          .arg(needed, 0, 'g', 3).arg(maxSpacing).arg(scene.tracking.maxVertices));
    };
    for (std::size_t i = 0; i < scene.regions.size(); ++i)
        add(scene.regions[i].shape, itemPath(root, u"regions"_s, i).key(u"shape"_s));
    for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
        if (const auto* drop = std::get_if<DropStroke>(&scene.strokes[i]))
            add(CircleShape{drop->center, drop->radius}, itemPath(root, u"strokes"_s, i).key(u"radius"_s));
        if (const auto* spatter = std::get_if<SpatterStroke>(&scene.strokes[i]))
            for (const DropStroke& drop : spatter->drops())
                add(CircleShape{drop.center, drop.radius}, itemPath(root, u"strokes"_s, i).key(u"count"_s));
        if (const auto* pattern = std::get_if<PatternStroke>(&scene.strokes[i]))
            for (const Stroke& tool : patternStrokes(*pattern, scene.canvas))
                if (const auto* drop = std::get_if<DropStroke>(&tool))
                    add(CircleShape{drop->center, drop->radius}, itemPath(root, u"strokes"_s, i).key(u"drop_radius"_s));
    }
}

// ---- bytes to JSON ----------------------------------------------------------------------------

QJsonDocument parseJson(const QByteArray& json)
{
    if (json.trimmed().isEmpty())
        throw ReadError{u"1:1"_s, u"the file is empty"_s};
    // JSON allows no raw control characters anywhere, so one means binary data: say that rather
    // than whatever the JSON parser makes of it.
    for (qsizetype i = 0; i < json.size(); ++i) {
        const auto byte = static_cast<unsigned char>(json[i]);
        if ((byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r') || byte == 0x7f)
            throw ReadError{location(json, i), u"binary data (byte 0x%1), not a scene file"_s.arg(int(byte), 2, 16, QChar(u'0'))};
    }
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(json, &error);
    // Qt reports the offset just after the offending character.
    if (error.error != QJsonParseError::NoError)
        throw ReadError{location(json, error.offset - 1), u"broken JSON: %1"_s.arg(error.errorString())};
    return document;
}

} // namespace

Scene readSceneObject(const Field& root, const QString& folder)
{
    Scene scene;
    // The version first: a newer file should say so rather than complain about its new keys.
    readVersion(root.member(u"vectorfluid"_s), scene);
    readObject(root, scene, std::span<const Key<Scene>>(sceneKeys));
    importSvgShapes(scene, root.path(), folder);
    checkStrokesFitFlow(scene, root.path());
    outlineTargets(scene, root.path());
    checkNamesUnique(scene, root.path());
    checkPatternsFit(scene, root.path());
    checkVertexBudget(scene, root.path());
    return scene;
}

SceneReadResult parseScene(const QByteArray& json, const QString& sourceName, const QString& folder)
{
    SceneReadResult result;
    try {
        const QJsonDocument document = parseJson(json);
        if (!document.isObject())
            throw ReadError{u"top level"_s, u"must be a JSON object {…}, not an array"_s};
        result.scene = readSceneObject(Field(document.object(), KeyPath()), folder);
    } catch (const ReadError& error) {
        result.scene = Scene();
        result.error = oneLine(u"%1: %2: %3"_s.arg(sourceName, error.where, error.what));
    }
    return result;
}

SceneReadResult readSceneFile(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {Scene(), oneLine(u"%1: cannot open: %2"_s.arg(path, file.errorString()))};
    const QByteArray json = file.readAll();
    if (file.error() != QFileDevice::NoError)
        return {Scene(), oneLine(u"%1: cannot read: %2"_s.arg(path, file.errorString()))};
    return parseScene(json, path, QFileInfo(path).absolutePath());
}

} // namespace vf::model
