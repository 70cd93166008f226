#include "model/ProjectFormat.h"

#include "model/ProjectFile.h"
#include "model/SceneJson.h"
#include "model/StateBlob.h"

#include <QHash>

#include <algorithm>
#include <unordered_set>

namespace vf::model {
namespace projectformat {

using namespace Qt::StringLiterals;
using json::KeyPath;

namespace {

void checkRegionTable(const RegionTable& table, int regionCount, const KeyPath& where)
{
    QHash<QString, qsizetype> firstUse;
    for (std::size_t i = 0; i < table.size(); ++i) {
        const RegionLook& look = table[i];
        const KeyPath at = where.index(qsizetype(i));
        if (look.name.trimmed().isEmpty())
            at.key(u"name"_s).fail(u"must not be empty"_s);
        if (const auto it = firstUse.constFind(look.name); it != firstUse.constEnd())
            at.key(u"name"_s).fail(u"the name %1 is already used by entry %2 (names must be unique)"_s.arg(json::quoted(look.name)).arg(*it));
        firstUse.insert(look.name, qsizetype(i));
        if (look.simIndex < 0 || look.simIndex >= regionCount)
            at.key(u"sim_index"_s).fail(u"%1 is outside the simulation's %2 regions"_s.arg(look.simIndex).arg(regionCount));
    }
}

// What a table of a history entry that carries no state is checked against: the entry left the
// simulation alone, so its regions are among those of some state of the project.
int largestRegionCount(const Project& project)
{
    int largest = project.state.regionCount;
    for (const HistoryEntry& entry : project.history) {
        for (const auto& state : {entry.before, entry.after}) {
            if (state)
                largest = std::max(largest, state->regionCount);
        }
    }
    return largest;
}

} // namespace

void checkRegionTables(const Project& project)
{
    const KeyPath top;
    checkRegionTable(project.regions, project.state.regionCount, top.key(u"regions"_s));
    const int anyRegionCount = largestRegionCount(project);
    for (std::size_t i = 0; i < project.history.size(); ++i) {
        const HistoryEntry& entry = project.history[i];
        const KeyPath at = top.key(u"history"_s).index(qsizetype(i));
        checkRegionTable(entry.regionsBefore, entry.before ? entry.before->regionCount : anyRegionCount, at.key(u"regions_before"_s));
        checkRegionTable(entry.regionsAfter, entry.after ? entry.after->regionCount : anyRegionCount, at.key(u"regions_after"_s));
    }
}

void checkCommandEnds(const Project& project)
{
    const KeyPath top;
    for (std::size_t i = 0; i < project.history.size(); ++i) {
        const HistoryEntry& entry = project.history[i];
        if (bool(entry.before) != bool(entry.after))
            top.key(u"history"_s).index(qsizetype(i)).key(entry.before ? u"after"_s : u"before"_s)
                .fail(u"null while %1 is a state: a command has states at both ends or at neither"_s
                          .arg(entry.before ? u"before"_s : u"after"_s));
    }
}

} // namespace projectformat

QString checkProject(const Project& project)
{
    using namespace projectformat;
    using namespace Qt::StringLiterals;
    const KeyPath top;
    try {
        // The scene goes through its own reader, so a scene that would not read back is refused.
        readSceneObject(json::Field(sceneToJsonObject(project.scene, SvgShapes::Embedded), top.key(u"scene"_s)), {});
        checkState(project.state, top.key(u"state"_s));
        std::unordered_set<const sim::SimulationState*> checked;
        for (std::size_t i = 0; i < project.history.size(); ++i) {
            const HistoryEntry& entry = project.history[i];
            const KeyPath at = top.key(u"history"_s).index(qsizetype(i));
            for (const auto& [state, key] : {std::pair(entry.before.get(), u"before"_s), std::pair(entry.after.get(), u"after"_s)}) {
                if (state && checked.insert(state).second)
                    checkState(*state, at.key(key));
            }
        }
        checkRegionTables(project);
        checkCommandEnds(project);
        if (project.steps < 0 || project.steps > kMaxJsonInteger)
            top.key(u"steps"_s).fail(u"%1 is outside [0, %2]"_s.arg(project.steps).arg(kMaxJsonInteger));
        if (std::int64_t(project.history.size()) > kMaxHistory)
            top.key(u"history"_s).fail(u"%1 entries, at most %2"_s.arg(project.history.size()).arg(kMaxHistory));
        if (project.historyIndex < 0 || std::size_t(project.historyIndex) > project.history.size())
            top.key(u"history_index"_s).fail(u"%1 is outside [0, %2]"_s.arg(project.historyIndex).arg(project.history.size()));
    } catch (const json::ReadError& error) {
        return json::oneLine(u"%1: %2"_s.arg(error.where, error.what));
    }
    return {};
}

} // namespace vf::model
