// Reading *.vfscene files (docs/scene-format.md). Everything a file can get wrong is caught here
// and reported as one line "<file>: <key path or line:col>: <what is wrong>", so the rest of the
// program only ever sees a valid Scene.
#include "model/SceneFile.h"

#include "sim/AnalyticFlow.h"

#include <QFile>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <span>
#include <utility>

namespace vf::model {
namespace {

using namespace Qt::StringLiterals;

constexpr int kVersion = 1;

constexpr double kHuge = std::numeric_limits<double>::max();

// Thrown by any check; parseScene turns it into the error line. `where` is a key path or line:col.
struct ReadError {
    QString where;
    QString what;
};

// "regions[1].shape.circle.radius": where a value sits in the file, as the error line names it.
// A default-constructed path is the top level.
class KeyPath {
public:
    KeyPath() = default;
    KeyPath key(const QString& name) const { return KeyPath(m_text.isEmpty() ? name : m_text + u'.' + name); }
    KeyPath index(qsizetype i) const { return KeyPath(m_text + u'[' + QString::number(i) + u']'); }
    [[noreturn]] void fail(const QString& what) const { throw ReadError{m_text, what}; }

private:
    explicit KeyPath(QString text) : m_text(std::move(text)) {}
    QString m_text;
};

// Quotes text from the file for a message, short enough to keep the message one readable line.
QString quoted(const QString& text)
{
    constexpr qsizetype kMaxShown = 40;
    return u'"' + (text.size() > kMaxShown ? text.left(kMaxShown) + u"…"_s : text) + u'"';
}

QString describe(const QJsonValue& value)
{
    switch (value.type()) {
    case QJsonValue::Null: return u"null"_s;
    case QJsonValue::Bool: return value.toBool() ? u"true"_s : u"false"_s;
    case QJsonValue::Double: return u"the number %1"_s.arg(value.toDouble());
    case QJsonValue::String: return u"the string "_s + quoted(value.toString());
    case QJsonValue::Array: return u"an array"_s;
    case QJsonValue::Object: return u"an object"_s;
    case QJsonValue::Undefined: break;
    }
    return u"nothing"_s;
}

// A JSON value with its key path: every check can say where it failed. Absent keys are
// Undefined values, so optional and required keys are read the same way.
class Field {
public:
    Field(QJsonValue value, KeyPath path) : m_value(std::move(value)), m_path(std::move(path)) {}

    bool exists() const { return !m_value.isUndefined(); }
    [[noreturn]] void fail(const QString& what) const { m_path.fail(what); }

    Field member(const QString& key) const { return {object().value(key), m_path.key(key)}; }
    Field element(const QJsonArray& array, qsizetype i) const { return {array.at(i), m_path.index(i)}; }

    QJsonObject object() const
    {
        expectType(QJsonValue::Object, u"an object"_s);
        return m_value.toObject();
    }
    QJsonArray array(qsizetype minSize, qsizetype maxSize) const
    {
        expectType(QJsonValue::Array, u"an array"_s);
        const QJsonArray array = m_value.toArray();
        if (minSize == maxSize && array.size() != minSize)
            fail(u"must have exactly %1 elements, has %2"_s.arg(minSize).arg(array.size()));
        if (array.size() < minSize)
            fail(u"must have at least %1 elements, has %2"_s.arg(minSize).arg(array.size()));
        if (array.size() > maxSize)
            fail(u"must have at most %1 elements, has %2"_s.arg(maxSize).arg(array.size()));
        return array;
    }
    QString string() const
    {
        expectType(QJsonValue::String, u"a string"_s);
        return m_value.toString();
    }
    QString name() const
    {
        const QString text = string();
        if (text.trimmed().isEmpty())
            fail(u"must not be empty"_s);
        return text;
    }
    bool boolean() const
    {
        expectType(QJsonValue::Bool, u"true or false"_s);
        return m_value.toBool();
    }
    // JSON has no NaN or infinity literal and Qt refuses numbers that overflow ("NaN" as a string
    // fails the type check), so the finiteness check guards against a future parser, not the file.
    double number() const
    {
        expectType(QJsonValue::Double, u"a number"_s);
        const double value = m_value.toDouble();
        if (!std::isfinite(value))
            fail(u"must be a finite number"_s);
        return value;
    }
    double number(double min, double max) const
    {
        const double value = number();
        if (value < min || value > max)
            fail(u"must be in [%1, %2], is %3"_s.arg(min).arg(max).arg(value));
        return value;
    }
    double nonNegative() const
    {
        const double value = number();
        if (value < 0.0)
            fail(u"must not be negative, is %1"_s.arg(value));
        return value;
    }
    double positive(double max) const
    {
        const double value = number();
        if (value <= 0.0)
            fail(u"must be positive, is %1"_s.arg(value));
        if (value > max)
            fail(u"must be at most %1, is %2"_s.arg(max).arg(value));
        return value;
    }
    std::int64_t integer(std::int64_t min, std::int64_t max) const
    {
        const double value = number();
        if (std::floor(value) != value)
            fail(u"must be a whole number, is %1"_s.arg(value));
        if (value < static_cast<double>(min) || value > static_cast<double>(max))
            fail(u"must be in [%1, %2], is %3"_s.arg(min).arg(max).arg(value));
        return static_cast<std::int64_t>(value);
    }
    template <typename T>
    T choice(std::initializer_list<std::pair<QString, T>> choices) const
    {
        const QString text = string();
        QStringList names;
        for (const auto& [name, value] : choices) {
            if (name == text)
                return value;
            names << u'"' + name + u'"';
        }
        fail(u"must be one of %1, not %2"_s.arg(names.join(u", "_s), quoted(text)));
    }

private:
    void expectType(QJsonValue::Type type, const QString& wanted) const
    {
        if (m_value.type() != type)
            fail(u"must be %1, not %2"_s.arg(wanted, describe(m_value)));
    }

    QJsonValue m_value;
    KeyPath m_path;
};

// ---- primitive values -------------------------------------------------------------------------

// Shapes may lie outside the canvas, but coordinates this far out only come from mistakes.
double coordinate(const Field& field) { return field.number(-limits::maxCanvasSize, limits::maxCanvasSize); }
double length(const Field& field) { return field.positive(limits::maxCanvasSize); }
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

int hexDigit(QChar c)
{
    if (c >= u'0' && c <= u'9') return c.unicode() - u'0';
    if (c >= u'a' && c <= u'f') return c.unicode() - u'a' + 10;
    if (c >= u'A' && c <= u'F') return c.unicode() - u'A' + 10;
    return -1;
}

// Only #rrggbb and #rrggbbaa: QColor's own parser also takes names and #aarrggbb, which would make
// "#rrggbbaa" from CSS or SVG silently mean something else.
QColor color(const Field& field)
{
    const QString text = field.string();
    const bool shapeOk = (text.size() == 7 || text.size() == 9) && text.startsWith(u'#');
    int channels[4] = {0, 0, 0, 255};
    for (qsizetype i = 1; shapeOk && i < text.size(); i += 2) {
        const int high = hexDigit(text[i]);
        const int low = hexDigit(text[i + 1]);
        if (high < 0 || low < 0)
            field.fail(u"must be \"#rrggbb\" or \"#rrggbbaa\" in hexadecimal, not %1"_s.arg(quoted(text)));
        channels[i / 2] = high * 16 + low;
    }
    if (!shapeOk)
        field.fail(u"must be \"#rrggbb\" or \"#rrggbbaa\", not %1"_s.arg(quoted(text)));
    return QColor(channels[0], channels[1], channels[2], channels[3]);
}

QString expression(const Field& field)
{
    const QString text = field.string();
    const std::string error = sim::AnalyticFlow::check(text.toStdString());
    if (!error.empty())
        field.fail(QString::fromStdString(error));  // names the expression and what muparser found
    return text;
}

// ---- objects: a table per object says which keys exist, which are required, how each is read --

template <typename Target>
struct Key {
    QString name;
    bool required;
    void (*read)(const Field&, Target&);
};

template <typename Target>
bool hasKey(std::span<const Key<Target>> keys, const QString& name)
{
    return std::any_of(keys.begin(), keys.end(), [&name](const Key<Target>& key) { return key.name == name; });
}

template <typename Target>
QString keyList(std::span<const Key<Target>> keys)
{
    QStringList names;
    for (const Key<Target>& key : keys)
        names << key.name;
    return names.join(u", "_s);
}

// Keys are read in table order, absent optional keys keep the defaults of model/Scene.h.
template <typename Target>
void readObject(const Field& field, Target& target, std::span<const Key<Target>> keys)
{
    const QJsonObject object = field.object();
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!hasKey(keys, it.key()))
            field.member(it.key()).fail(u"unknown key (expected one of: %1)"_s.arg(keyList(keys)));
    }
    for (const Key<Target>& key : keys) {
        const Field child = field.member(key.name);
        if (child.exists())
            key.read(child, target);
        else if (key.required)
            child.fail(u"missing (required)"_s);
    }
}

// For a key that was read before its table was chosen ("tool" picks the stroke's table).
template <typename Target>
void readAlready(const Field&, Target&) {}

template <typename T, std::size_t N>
T readAs(const Field& field, const Key<T> (&keys)[N])
{
    T value;
    readObject(field, value, std::span<const Key<T>>(keys));
    return value;
}

template <typename T, typename ReadItem>
std::vector<T> readList(const Field& field, qsizetype minSize, qsizetype maxSize, ReadItem readItem)
{
    const QJsonArray array = field.array(minSize, maxSize);
    std::vector<T> items;
    items.reserve(static_cast<std::size_t>(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i)
        items.push_back(readItem(field.element(array, i)));
    return items;
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
    {u"advection"_s, false, [](const Field& f, FlowSpec& flow) {
         flow.maccormack = f.choice<bool>({{u"maccormack"_s, true}, {u"semi-lagrangian"_s, false}});
     }},
};

const Key<FlowSpec> analyticKeys[] = {
    {u"type"_s, true, readFlowType},
    {u"u"_s, true, [](const Field& f, FlowSpec& flow) { flow.u = expression(f); }},
    {u"v"_s, true, [](const Field& f, FlowSpec& flow) { flow.v = expression(f); }},
};

void readFlow(const Field& field, Scene& scene)
{
    FlowSpec& flow = scene.flow;
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
}

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

// Each key is a kind of shape; the object must hold exactly one of them.
const Key<Shape> shapeKeys[] = {
    {u"circle"_s, false, [](const Field& f, Shape& s) { s = readAs(f, circleKeys); }},
    {u"ellipse"_s, false, [](const Field& f, Shape& s) { s = readAs(f, ellipseKeys); }},
    {u"rect"_s, false, [](const Field& f, Shape& s) { s = readAs(f, rectKeys); }},
    {u"polygon"_s, false, [](const Field& f, Shape& s) { s = readPolygon(f); }},
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
    {u"color"_s, true, [](const Field& f, RegionSpec& r) { r.color = color(f); }},
    {u"visible"_s, false, [](const Field& f, RegionSpec& r) { r.visible = f.boolean(); }},
    {u"shape"_s, true, readShape},
};

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

Stroke readStroke(const Field& field)
{
    enum class Tool { Stylus, Drop };
    const Field tool = field.member(u"tool"_s);
    if (!tool.exists())
        tool.fail(u"missing (required)"_s);
    if (tool.choice<Tool>({{u"stylus"_s, Tool::Stylus}, {u"drop"_s, Tool::Drop}}) == Tool::Stylus)
        return readAs(field, stylusKeys);
    return readAs(field, dropKeys);
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
    {u"flow"_s, false, readFlow},
    {u"time"_s, false, [](const Field& f, Scene& s) { s.time = readAs(f, timeKeys); }},
    {u"tracking"_s, false, [](const Field& f, Scene& s) { s.tracking = readAs(f, trackingKeys); }},
    {u"regions"_s, false, [](const Field& f, Scene& s) {
         s.regions = readList<RegionSpec>(f, 0, static_cast<qsizetype>(limits::maxRegions),
                                          [](const Field& item) { return readAs(item, regionKeys); });
     }},
    {u"strokes"_s, false, [](const Field& f, Scene& s) {
         s.strokes = readList<Stroke>(f, 0, static_cast<qsizetype>(limits::maxStrokes), readStroke);
     }},
};

// Checks that span several keys, run after every key has been read on its own.

KeyPath itemPath(const QString& list, qsizetype i) { return KeyPath().key(list).index(i); }

void checkStrokesFitFlow(const Scene& scene)
{
    if (scene.flow.type != FlowSpec::Type::Analytic)
        return;
    for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
        if (std::holds_alternative<StylusStroke>(scene.strokes[i]))
            itemPath(u"strokes"_s, i).key(u"tool"_s).fail(
                u"a stylus needs \"flow\": {\"type\": \"fluid\"}: an analytic flow is prescribed and does not react to it"_s);
    }
}

// Names become SVG ids and layer labels, so region and drop names share one namespace.
void checkNamesUnique(const Scene& scene)
{
    QHash<QString, QString> owners;  // name -> where it was first used
    auto claim = [&owners](const QString& name, const QString& list, qsizetype i) {
        if (name.isEmpty())
            return;
        if (const auto it = owners.constFind(name); it != owners.constEnd())
            itemPath(list, i).key(u"name"_s).fail(u"the name %1 is already used by %2"_s.arg(quoted(name), it.value()));
        owners.insert(name, u"%1[%2]"_s.arg(list).arg(i));
    };
    for (std::size_t i = 0; i < scene.regions.size(); ++i)
        claim(scene.regions[i].name, u"regions"_s, i);
    for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
        if (const auto* drop = std::get_if<DropStroke>(&scene.strokes[i]))
            claim(drop->name, u"strokes"_s, i);
    }
}

// The starting shapes (and the circles drops add) must fit the vertex budget; without this check a
// tiny max_spacing would make the program try to allocate billions of vertices before any step.
void checkVertexBudget(const Scene& scene)
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
        add(scene.regions[i].shape, itemPath(u"regions"_s, i).key(u"shape"_s));
    for (std::size_t i = 0; i < scene.strokes.size(); ++i) {
        if (const auto* drop = std::get_if<DropStroke>(&scene.strokes[i]))
            add(CircleShape{drop->center, drop->radius}, itemPath(u"strokes"_s, i).key(u"radius"_s));
    }
}

Scene readScene(const Field& root)
{
    Scene scene;
    // The version first: a newer file should say so rather than complain about its new keys.
    readVersion(root.member(u"vectorfluid"_s), scene);
    readObject(root, scene, std::span<const Key<Scene>>(sceneKeys));
    checkStrokesFitFlow(scene);
    checkNamesUnique(scene);
    checkVertexBudget(scene);
    return scene;
}

// ---- bytes to JSON ----------------------------------------------------------------------------

// "line:col" of a byte offset, both 1-based, the column counted in characters.
QString location(const QByteArray& json, qsizetype offset)
{
    const QByteArray before = json.left(std::clamp<qsizetype>(offset, 0, json.size()));
    const qsizetype lineStart = before.lastIndexOf('\n') + 1;
    const qsizetype column = QString::fromUtf8(before.sliced(lineStart)).size() + 1;
    return u"%1:%2"_s.arg(before.count('\n') + 1).arg(column);
}

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

// Messages may quote the file's own text (keys, expressions): keep the result on one line.
QString oneLine(QString text)
{
    for (QChar& c : text) {
        if (c.category() == QChar::Other_Control || c == QChar::LineSeparator || c == QChar::ParagraphSeparator)
            c = u' ';
    }
    return text;
}

} // namespace

SceneReadResult parseScene(const QByteArray& json, const QString& sourceName)
{
    SceneReadResult result;
    try {
        const QJsonDocument document = parseJson(json);
        if (!document.isObject())
            throw ReadError{u"top level"_s, u"must be a JSON object {…}, not an array"_s};
        result.scene = readScene(Field(document.object(), KeyPath()));
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
    return parseScene(json, path);
}

} // namespace vf::model
