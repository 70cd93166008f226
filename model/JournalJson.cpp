// The journal in a project file (docs/project-format.md, "Journal"). An entry is an array rather
// than an object: a pen part is one per step while a stroke is drawn, so the form is kept short.
#include "model/JournalJson.h"

#include "model/SceneJson.h"

#include <stdexcept>

namespace vf::model {

using namespace Qt::StringLiterals;
using namespace json;

namespace {

inline constexpr qsizetype kMaxDrives = 1000;
// A drive is made when the file is read (its target rasterised and blurred on its grid): so that no
// file makes the reader work for minutes, its drives' grids hold four of the largest at most.
inline constexpr std::int64_t kMaxDriveCells = 4 * std::int64_t(limits::maxGrid) * limits::maxGrid;
inline constexpr qsizetype kMaxContours = 100'000;
inline constexpr qsizetype kMaxEntries = 100'000'000;

QJsonArray numbers(std::initializer_list<double> values)
{
    QJsonArray array;
    for (double v : values)
        array.append(v);
    return array;
}

QJsonArray polygonJson(const sim::Polygon& polygon)
{
    QJsonArray flat;
    for (const sim::Vec2& p : polygon) {
        flat.append(p.x);
        flat.append(p.y);
    }
    return flat;
}

QJsonArray contoursJson(const std::vector<sim::Polygon>& contours)
{
    QJsonArray array;
    for (const sim::Polygon& c : contours)
        array.append(polygonJson(c));
    return array;
}

// [step, kind] followed by `values`.
QJsonArray entryJson(std::int64_t step, const QString& kind, const QJsonArray& values)
{
    QJsonArray entry{qint64(step), kind};
    for (const QJsonValue& v : values)
        entry.append(v);
    return entry;
}

QJsonArray mapValues(const sim::ExactMap& map)
{
    return std::visit(
        [](const auto& m) -> QJsonArray {
            using Map = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<Map, sim::Comb>)
                return numbers({m.from.x, m.from.y, m.to.x, m.to.y, double(m.tines), m.spacing, m.sharpness, m.amplitude,
                                m.wavelength, m.phase});
            else if constexpr (std::is_same_v<Map, sim::CircularComb>)
                return numbers({m.centre.x, m.centre.y, m.radius, double(m.tines), m.spacing, m.sharpness, m.angle});
            else
                return numbers({m.centre.x, m.centre.y, m.radius, m.angle});
        },
        map);
}

QString mapKind(const sim::ExactMap& map)
{
    static const QString kinds[] = {u"comb"_s, u"circular_comb"_s, u"swirl"_s};
    return kinds[map.index()];
}

// ---- reading ----------------------------------------------------------------------------------

// The values of an entry array after its step and kind: exactly `count` of them.
class Values {
public:
    Values(const Field& entry, const QJsonArray& array, qsizetype count) : m_entry(entry), m_array(array)
    {
        if (array.size() != count + 2)
            entry.fail(u"a \"%1\" entry has %2 values after its step and kind, not %3"_s
                           .arg(array.at(1).toString()).arg(array.size() - 2).arg(count));
    }
    Field at(qsizetype i) const { return m_entry.element(m_array, i + 2); }
    double coordinate(qsizetype i) const { return at(i).number(-limits::maxCanvasSize, limits::maxCanvasSize); }
    double length(qsizetype i) const
    {
        const double value = at(i).positive(limits::maxCanvasSize);
        if (value < limits::minLength)
            at(i).fail(u"must be at least %1, is %2"_s.arg(limits::minLength).arg(value));
        return value;
    }
    double size(qsizetype i) const { return at(i).number(0.0, limits::maxCanvasSize); }
    double angle(qsizetype i) const { return at(i).number(-limits::maxCanvasSize, limits::maxCanvasSize); }
    int tines(qsizetype i) const { return int(at(i).integer(1, limits::maxTines)); }

private:
    const Field& m_entry;
    const QJsonArray& m_array;
};

sim::Polygon readPolygon(const Field& field)
{
    const QJsonArray flat = field.array(6, qsizetype(2 * limits::maxPolygonPoints));
    if (flat.size() % 2 != 0)
        field.fail(u"has %1 numbers: a contour is x, y pairs"_s.arg(flat.size()));
    sim::Polygon polygon(std::size_t(flat.size() / 2));
    for (qsizetype i = 0; i < flat.size(); ++i)
        polygon[std::size_t(i / 2)][int(i % 2)] = field.element(flat, i).number(-limits::maxCanvasSize, limits::maxCanvasSize);
    return polygon;
}

std::vector<sim::Polygon> readContours(const Field& field)
{
    return readList<sim::Polygon>(field, 1, kMaxContours, readPolygon);
}

struct DriveSpec {
    std::vector<std::vector<sim::Polygon>> target;
    sim::FluidSettings grid;
    sim::TargetDriveSettings settings;
};

const Key<DriveSpec> driveKeys[] = {
    {u"target"_s, true, [](const Field& f, DriveSpec& d) { d.target = readList<std::vector<sim::Polygon>>(f, 1, kMaxContours, readContours); }},
    {u"cells"_s, true, [](const Field& f, DriveSpec& d) {
         const QJsonArray cells = f.array(2, 2);
         d.grid.nx = int(f.element(cells, 0).integer(limits::minGrid, limits::maxGrid));
         d.grid.ny = int(f.element(cells, 1).integer(limits::minGrid, limits::maxGrid));
     }},
    {u"width"_s, true, [](const Field& f, DriveSpec& d) { d.grid.width = f.positive(limits::maxCanvasSize); }},
    {u"height"_s, true, [](const Field& f, DriveSpec& d) { d.grid.height = f.positive(limits::maxCanvasSize); }},
    {u"strength"_s, true, [](const Field& f, DriveSpec& d) { d.settings.strength = f.nonNegative(); }},
    {u"attenuation"_s, true, [](const Field& f, DriveSpec& d) { d.settings.attenuation = f.nonNegative(); }},
    {u"blur"_s, true, [](const Field& f, DriveSpec& d) { d.settings.blur = f.positive(limits::maxCanvasSize); }},
    {u"gathering"_s, true, [](const Field& f, DriveSpec& d) { d.settings.gathering = f.nonNegative(); }},
};

journal::Configure readSettings(const Field& field)
{
    struct Both {
        FlowSpec flow;
        TrackingSpec tracking;
    };
    static const Key<Both> keys[] = {
        {u"flow"_s, true, [](const Field& f, Both& b) { b.flow = readFlowObject(f); }},
        {u"tracking"_s, true, [](const Field& f, Both& b) { b.tracking = readTrackingObject(f); }},
    };
    const Both both = readAs(field, keys);
    auto settings = std::make_shared<EngineSettings>();
    settings->flow = both.flow;
    settings->tracking = both.tracking;
    return {std::move(settings)};
}

enum class Kind { Drop, Pen, Comb, CircularComb, Swirl, Add, Remove, Settings, Drive };

decltype(JournalEntry::action) readAction(const Field& entry, const QJsonArray& array, const std::vector<DrivePtr>& drives)
{
    switch (entry.element(array, 1).choice<Kind>({{u"drop"_s, Kind::Drop}, {u"pen"_s, Kind::Pen}, {u"comb"_s, Kind::Comb},
                                                   {u"circular_comb"_s, Kind::CircularComb}, {u"swirl"_s, Kind::Swirl},
                                                   {u"add"_s, Kind::Add}, {u"remove"_s, Kind::Remove},
                                                   {u"settings"_s, Kind::Settings}, {u"drive"_s, Kind::Drive}})) {
    case Kind::Drop: {
        const Values v(entry, array, 3);
        return journal::Drop{{v.coordinate(0), v.coordinate(1)}, v.length(2)};
    }
    case Kind::Pen: {
        const Values v(entry, array, 6);
        return journal::Pen{{{v.coordinate(0), v.coordinate(1)}, {v.coordinate(2), v.coordinate(3)}, v.size(4), v.size(5)}};
    }
    case Kind::Comb: {
        const Values v(entry, array, 10);
        const sim::Comb comb{{v.coordinate(0), v.coordinate(1)}, {v.coordinate(2), v.coordinate(3)}, v.tines(4), v.size(5),
                             v.length(6), v.size(7), v.length(8), v.angle(9)};
        return journal::Map{std::make_shared<const sim::ExactMap>(comb)};
    }
    case Kind::CircularComb: {
        const Values v(entry, array, 7);
        const sim::CircularComb comb{{v.coordinate(0), v.coordinate(1)}, v.size(2), v.tines(3), v.size(4), v.length(5), v.angle(6)};
        return journal::Map{std::make_shared<const sim::ExactMap>(comb)};
    }
    case Kind::Swirl: {
        const Values v(entry, array, 4);
        return journal::Map{std::make_shared<const sim::ExactMap>(sim::Swirl{{v.coordinate(0), v.coordinate(1)}, v.length(2), v.angle(3)})};
    }
    case Kind::Add:
        return journal::AddRegion{readContours(Values(entry, array, 1).at(0))};
    case Kind::Remove:
        return journal::RemoveRegion{int(Values(entry, array, 1).at(0).integer(0, qint64(limits::maxRegions) - 1))};
    case Kind::Settings:
        return readSettings(Values(entry, array, 1).at(0));
    case Kind::Drive:
        break;
    }
    const Field index = Values(entry, array, 1).at(0);
    if (drives.empty())
        index.fail(u"names a drive, but the project lists none in \"drives\""_s);
    return journal::Drive{drives[std::size_t(index.integer(0, qint64(drives.size()) - 1))]};
}

} // namespace

qint64 DriveTable::add(const DrivePtr& drive)
{
    const auto [it, added] = m_index.try_emplace(drive.get(), qint64(m_drives.size()));
    if (added)
        m_drives.push_back(drive);
    return it->second;
}

QJsonArray DriveTable::toJson() const
{
    QJsonArray array;
    for (const DrivePtr& drive : m_drives) {
        QJsonArray target;
        for (const std::vector<sim::Polygon>& shape : drive->target())
            target.append(contoursJson(shape));
        const sim::FluidSettings grid = drive->grid();
        const sim::TargetDriveSettings& s = drive->settings();
        array.append(QJsonObject{{u"target"_s, target},
                                 {u"cells"_s, QJsonArray{grid.nx, grid.ny}},
                                 {u"width"_s, grid.width},
                                 {u"height"_s, grid.height},
                                 {u"strength"_s, s.strength},
                                 {u"attenuation"_s, s.attenuation},
                                 {u"blur"_s, s.blur},
                                 {u"gathering"_s, s.gathering}});
    }
    return array;
}

QJsonArray journalToJson(const std::vector<JournalEntry>& entries, DriveTable& drives)
{
    QJsonArray array;
    for (const JournalEntry& entry : entries) {
        const std::int64_t step = entry.step;
        std::visit(
            [&](const auto& action) {
                using Action = std::decay_t<decltype(action)>;
                if constexpr (std::is_same_v<Action, journal::Drop>)
                    array.append(entryJson(step, u"drop"_s, numbers({action.center.x, action.center.y, action.radius})));
                else if constexpr (std::is_same_v<Action, journal::Pen>) {
                    const sim::StylusSegment& p = action.part;
                    array.append(entryJson(step, u"pen"_s, numbers({p.from.x, p.from.y, p.to.x, p.to.y, p.radius, p.duration})));
                } else if constexpr (std::is_same_v<Action, journal::Map>)
                    array.append(entryJson(step, mapKind(*action.map), mapValues(*action.map)));
                else if constexpr (std::is_same_v<Action, journal::AddRegion>)
                    array.append(entryJson(step, u"add"_s, QJsonArray{contoursJson(action.contours)}));
                else if constexpr (std::is_same_v<Action, journal::RemoveRegion>)
                    array.append(entryJson(step, u"remove"_s, QJsonArray{action.region}));
                else if constexpr (std::is_same_v<Action, journal::Configure>)
                    array.append(entryJson(step, u"settings"_s,
                                           QJsonArray{QJsonObject{{u"flow"_s, flowToJson(action.settings->flow)},
                                                                  {u"tracking"_s, trackingToJson(action.settings->tracking)}}}));
                else
                    array.append(entryJson(step, u"drive"_s, QJsonArray{drives.add(action.drive)}));
            },
            entry.action);
    }
    return array;
}

std::vector<DrivePtr> readDrives(const Field& field)
{
    const std::vector<DriveSpec> specs =
        readList<DriveSpec>(field, 0, kMaxDrives, [](const Field& item) { return readAs(item, driveKeys); });
    std::int64_t cells = 0;
    for (const DriveSpec& spec : specs)
        cells += std::int64_t(spec.grid.nx) * spec.grid.ny;
    if (cells > kMaxDriveCells)
        field.fail(u"the drives' grids hold %1 cells in all, more than %2"_s.arg(cells).arg(kMaxDriveCells));
    std::vector<DrivePtr> drives;
    for (std::size_t i = 0; i < specs.size(); ++i) {
        try {
            drives.push_back(std::make_shared<const sim::TargetDrive>(specs[i].target, specs[i].grid, specs[i].settings));
        } catch (const std::invalid_argument& e) {
            field.element(field.array(0, kMaxDrives), qsizetype(i)).fail(QString::fromUtf8(e.what()));
        }
    }
    return drives;
}

std::vector<JournalEntry> readJournal(const Field& field, std::int64_t steps, const std::vector<DrivePtr>& drives)
{
    std::int64_t last = 0;
    return readList<JournalEntry>(field, 0, kMaxEntries, [&](const Field& entry) {
        const QJsonArray array = entry.array(2, 12);
        const std::int64_t step = entry.element(array, 0).integer(last, steps);
        last = step;
        return JournalEntry{step, readAction(entry, array, drives)};
    });
}

} // namespace vf::model
