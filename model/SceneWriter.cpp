// Writing *.vfscene files. Every key is written, defaults included, so a file says everything the
// run depends on; doubles go out in Qt's shortest round-trip form, so reading a written scene
// gives back exactly the same numbers.
#include "model/AtomicFile.h"
#include "model/Patterns.h"
#include "model/SceneFile.h"
#include "model/SceneJson.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <type_traits>

namespace vf::model {
namespace {

using namespace Qt::StringLiterals;
using json::colorText;

QJsonArray pair(sim::Vec2 p) { return {p.x, p.y}; }

QString modeText(CombStroke::Mode mode) { return mode == CombStroke::Mode::Exact ? u"exact"_s : u"water"_s; }

template <typename T, typename ToJson>
QJsonArray listJson(const std::vector<T>& items, ToJson toJson)
{
    QJsonArray array;
    for (const T& item : items)
        array.append(toJson(item));
    return array;
}

} // namespace

QJsonObject flowToJson(const FlowSpec& flow)
{
    if (flow.type == FlowSpec::Type::Analytic)
        return {{u"type"_s, u"analytic"_s}, {u"u"_s, flow.u}, {u"v"_s, flow.v}};
    return {{u"type"_s, u"fluid"_s},
            {u"grid"_s, QJsonArray{flow.gridX, flow.gridY}},
            {u"viscosity"_s, flow.viscosity},
            {u"stylus_response"_s, flow.stylusResponse},
            {u"stylus_radius"_s, flow.stylusRadius},
            {u"advection"_s, flow.maccormack ? u"maccormack"_s : u"semi-lagrangian"_s}};
}

QJsonObject trackingToJson(const TrackingSpec& tracking)
{
    return {{u"max_spacing"_s, tracking.maxSpacing},
            {u"adaptive"_s, tracking.adaptive},
            {u"proximity"_s, tracking.proximity},
            {u"area_correction"_s, tracking.areaCorrection},
            {u"max_vertices"_s, qint64(tracking.maxVertices)}};
}

namespace {

QJsonObject toJson(const CircleShape& c)
{
    return {{u"circle"_s, QJsonObject{{u"center"_s, pair(c.center)}, {u"radius"_s, c.radius}}}};
}

QJsonObject toJson(const EllipseShape& e)
{
    return {{u"ellipse"_s, QJsonObject{{u"center"_s, pair(e.center)}, {u"radii"_s, pair(e.radii)}}}};
}

QJsonObject toJson(const RectShape& r)
{
    return {{u"rect"_s, QJsonObject{{u"position"_s, pair(r.topLeft)}, {u"size"_s, pair(r.size)}}}};
}

QJsonObject toJson(const PolygonShape& p)
{
    return {{u"polygon"_s, listJson(p.points, pair)}};
}

QJsonObject toJson(const SvgShape& svg, SvgShapes how)
{
    if (how == SvgShapes::Reference)
        return {{u"svg"_s, svg.file}};
    return {{u"svg"_s, QJsonObject{{u"file"_s, svg.file}, {u"base64"_s, QString::fromLatin1(svg.text.toBase64())}}}};
}

QJsonObject toJson(const Shape& shape, SvgShapes how)
{
    return std::visit([how](const auto& s) {
        if constexpr (std::is_same_v<std::decay_t<decltype(s)>, SvgShape>)
            return toJson(s, how);
        else
            return toJson(s);
    }, shape);
}

QJsonObject toJson(const StylusStroke& s)
{
    QJsonArray points;
    for (std::size_t i = 0; i < s.points.size(); ++i)
        points.append(QJsonArray{s.points[i].x, s.points[i].y, s.times[i]});
    return {{u"tool"_s, u"stylus"_s}, {u"radius"_s, s.radius}, {u"points"_s, points}};
}

QJsonObject toJson(const DropStroke& d)
{
    QJsonObject drop{{u"tool"_s, u"drop"_s},
                     {u"time"_s, d.time},
                     {u"center"_s, pair(d.center)},
                     {u"radius"_s, d.radius},
                     {u"color"_s, colorText(d.color)}};
    // An unnamed drop stays unnamed: the reader refuses an empty name.
    if (!d.name.isEmpty())
        drop.insert(u"name"_s, d.name);
    return drop;
}

// A comb's keys that depend on how it acts: its sharpness when exact, its tines' duration and
// stylus radius in the water.
template <typename AnyComb>
void insertActionKeys(QJsonObject& comb, const AnyComb& c)
{
    comb.insert(u"mode"_s, modeText(c.mode));
    if (c.mode == CombStroke::Mode::Exact) {
        comb.insert(u"sharpness"_s, c.sharpness);
    } else {
        comb.insert(u"duration"_s, c.duration);
        comb.insert(u"radius"_s, c.radius);
    }
}

// Every key, defaults included: a program reading it needs no table of defaults.
QJsonObject toJson(const CombStroke& c)
{
    QJsonObject comb{{u"tool"_s, u"comb"_s},      {u"time"_s, c.time},   {u"from"_s, pair(c.from)},
                     {u"to"_s, pair(c.to)},       {u"tines"_s, c.tines}, {u"spacing"_s, c.spacing}};
    insertActionKeys(comb, c);
    if (c.amplitude > 0.0) {
        comb.insert(u"amplitude"_s, c.amplitude);
        comb.insert(u"wavelength"_s, c.wavelength);
        comb.insert(u"phase"_s, c.phase);
    }
    return comb;
}

QJsonObject toJson(const CircularCombStroke& c)
{
    QJsonObject comb{{u"tool"_s, u"circular-comb"_s}, {u"time"_s, c.time},   {u"center"_s, pair(c.center)},
                     {u"inner_radius"_s, c.innerRadius}, {u"tines"_s, c.tines}, {u"spacing"_s, c.spacing},
                     {u"angle"_s, c.angle}};
    insertActionKeys(comb, c);
    return comb;
}

QJsonObject toJson(const SpatterStroke& s)
{
    QJsonArray colors;
    for (const QColor& c : s.colors)
        colors.append(colorText(c));
    return {{u"tool"_s, u"spatter"_s},
            {u"time"_s, s.time},
            {u"center"_s, pair(s.center)},
            {u"spread"_s, s.spread},
            {u"count"_s, s.count},
            {u"radius"_s, QJsonArray{s.smallest, s.largest}},
            {u"colors"_s, colors},
            {u"seed"_s, double(s.seed)},
            {u"interval"_s, s.interval}};
}

QJsonObject toJson(const PatternStroke& p)
{
    QJsonArray colors;
    for (const QColor& c : p.colors)
        colors.append(colorText(c));
    return {{u"tool"_s, u"pattern"_s},        {u"name"_s, patternName(p.kind)},
            {u"time"_s, p.time},              {u"colors"_s, colors},
            {u"mode"_s, modeText(p.mode)},    {u"seed"_s, double(p.seed)},
            {u"drop_radius"_s, p.dropRadius}, {u"spacing"_s, p.spacing},
            {u"fine_spacing"_s, p.fineSpacing}, {u"shift"_s, p.shift},
            {u"sharpness"_s, p.sharpness},    {u"duration"_s, p.duration}};
}

QJsonObject toJson(const SwirlStroke& s)
{
    QJsonObject swirl{{u"tool"_s, u"swirl"_s}, {u"time"_s, s.time}, {u"center"_s, pair(s.center)},
                      {u"radius"_s, s.radius}, {u"angle"_s, s.angle}};
    swirl.insert(u"mode"_s, modeText(s.mode));
    if (s.mode == CombStroke::Mode::Water) {
        swirl.insert(u"duration"_s, s.duration);
        swirl.insert(u"rings"_s, s.rings);
    }
    return swirl;
}

QJsonObject toJson(const TextTarget& t)
{
    return {{u"text"_s, QJsonObject{{u"string"_s, t.text}, {u"font"_s, t.font}, {u"bold"_s, t.bold},
                                    {u"baseline"_s, pair(t.baseline)}, {u"size"_s, t.size}}}};
}

QJsonObject toJson(const GatherStroke& g)
{
    const QJsonObject target = std::holds_alternative<TextTarget>(g.target)
                                   ? toJson(std::get<TextTarget>(g.target))
                                   : toJson(std::get<Shape>(g.target), SvgShapes::Reference);
    return {{u"tool"_s, u"gather"_s},          {u"time"_s, g.time},
            {u"duration"_s, g.duration},       {u"target"_s, target},
            {u"strength"_s, g.drive.strength}, {u"attenuation"_s, g.drive.attenuation},
            {u"gathering"_s, g.drive.gathering}, {u"blur"_s, g.drive.blur}};
}

template <typename... Ts>
QJsonObject toJson(const std::variant<Ts...>& value)
{
    return std::visit([](const auto& alternative) { return toJson(alternative); }, value);
}

QJsonObject toJson(const RegionSpec& region, SvgShapes how)
{
    QJsonObject object{{u"name"_s, region.name}, {u"visible"_s, region.visible}, {u"shape"_s, toJson(region.shape, how)}};
    // Without a colour, an SVG shape keeps the file's colours.
    if (region.color.isValid())
        object.insert(u"color"_s, colorText(region.color));
    return object;
}

} // namespace

QJsonObject sceneToJsonObject(const Scene& scene, SvgShapes svg)
{
    return {
        {u"vectorfluid"_s, 1},
        {u"canvas"_s, QJsonObject{{u"width"_s, scene.canvas.width},
                                  {u"height"_s, scene.canvas.height},
                                  {u"background"_s, colorText(scene.canvas.background)}}},
        {u"flow"_s, flowToJson(scene.flow)},
        {u"time"_s, QJsonObject{{u"dt"_s, scene.time.dt}, {u"steps"_s, qint64(scene.time.steps)}}},
        {u"tracking"_s, trackingToJson(scene.tracking)},
        {u"regions"_s, listJson(scene.regions, [svg](const RegionSpec& r) { return toJson(r, svg); })},
        {u"strokes"_s, listJson(scene.strokes, [](const Stroke& s) { return toJson(s); })},
    };
}

QByteArray sceneToJson(const Scene& scene)
{
    return QJsonDocument(sceneToJsonObject(scene, SvgShapes::Reference)).toJson(QJsonDocument::Indented);
}

QString writeSceneFile(const Scene& scene, const QString& path)
{
    const QByteArray json = sceneToJson(scene);
    return saveAtomically(path, [&json](QIODevice& file) { return writeAll(file, json); });
}

} // namespace vf::model
