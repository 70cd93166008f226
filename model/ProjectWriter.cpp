// Writing *.vfproj files (docs/project-format.md). The states are encoded and compressed one at a
// time, so only the compressed blobs are held together; the manifest needs their offsets and so
// is written last in memory but first in the file.
#include "model/AtomicFile.h"
#include "model/JournalJson.h"
#include "model/ProjectFile.h"
#include "model/ProjectFormat.h"
#include "model/SceneJson.h"
#include "model/StateBlob.h"

#include <QJsonDocument>
#include <QtEndian>

#include <optional>
#include <unordered_map>

namespace vf::model {
namespace {

using namespace Qt::StringLiterals;
using namespace projectformat;

// Each distinct state once, numbered in order of first use, with the journal's mark of where it
// was taken; shared pointers to one state share its number.
class StateTable {
public:
    QJsonValue add(const sim::SimulationState* state, const JournalMark& mark)
    {
        if (!state)
            return QJsonValue::Null;
        const auto [it, added] = m_index.try_emplace(state, m_states.size());
        if (added) {
            m_states.push_back(state);
            m_marks.push_back(mark);
        }
        return qint64(it->second);
    }
    const std::vector<const sim::SimulationState*>& states() const { return m_states; }
    const std::vector<JournalMark>& marks() const { return m_marks; }

private:
    std::unordered_map<const sim::SimulationState*, std::size_t> m_index;
    std::vector<const sim::SimulationState*> m_states;
    std::vector<JournalMark> m_marks;
};

// For each state, how it was reached from the nearest earlier state of its line of work that is
// stored too (docs/project-format.md, "Journal"): {"from", "steps", "entries"}, or nothing for the
// first of a line. A state's nearest is found by walking its segments back to the first one that
// is another state's head; on its own head, only a state taken earlier (fewer steps, or as many
// and numbered before it) counts, so that no two states reach each other.
std::vector<QJsonValue> reachedJson(const std::vector<JournalMark>& marks, DriveTable& drives)
{
    std::unordered_map<const JournalSegment*, std::vector<std::size_t>> statesAt;
    for (std::size_t i = 0; i < marks.size(); ++i)
        if (marks[i].head)
            statesAt[marks[i].head.get()].push_back(i);
    std::vector<QJsonValue> reached(marks.size(), QJsonValue(QJsonValue::Undefined));
    for (std::size_t i = 0; i < marks.size(); ++i) {
        const JournalMark& to = marks[i];
        std::optional<std::size_t> from;
        for (const JournalSegment* segment = to.head.get(); segment && !from; segment = segment->previous.get()) {
            const auto found = statesAt.find(segment);
            if (found == statesAt.end())
                continue;
            for (std::size_t j : found->second) {
                const bool earlier = marks[j].step < to.step || (marks[j].step == to.step && j < i);
                if (j != i && earlier && (!from || marks[j].step > marks[*from].step))
                    from = j;
            }
        }
        if (!from)
            continue;
        const std::optional<std::vector<JournalEntry>> entries = entriesBetween(marks[*from], to);
        if (!entries)
            continue;
        reached[i] = QJsonObject{{u"from"_s, qint64(*from)},
                                 {u"steps"_s, qint64(to.step - marks[*from].step)},
                                 {u"entries"_s, journalToJson(*entries, drives)}};
    }
    return reached;
}

QJsonArray tableJson(const RegionTable& table)
{
    QJsonArray array;
    for (const RegionLook& look : table)
        array.append(QJsonObject{{u"name"_s, look.name},
                                 {u"color"_s, json::colorText(look.color)},
                                 {u"visible"_s, look.visible},
                                 {u"sim_index"_s, look.simIndex}});
    return array;
}

struct EncodedProject {
    QByteArray head;  // header line, manifest length, manifest
    std::vector<QByteArray> blobs;
    QString error;
};

EncodedProject encodeProject(const Project& project)
{
    EncodedProject encoded;
    if (encoded.error = checkProject(project); !encoded.error.isEmpty())
        return encoded;

    StateTable table;
    QJsonArray history;
    for (const HistoryEntry& entry : project.history)
        history.append(QJsonObject{{u"text"_s, entry.text},
                                   {u"regions_before"_s, tableJson(entry.regionsBefore)},
                                   {u"regions_after"_s, tableJson(entry.regionsAfter)},
                                   {u"flow_before"_s, flowToJson(entry.flowBefore)},
                                   {u"flow_after"_s, flowToJson(entry.flowAfter)},
                                   {u"tracking_before"_s, trackingToJson(entry.trackingBefore)},
                                   {u"tracking_after"_s, trackingToJson(entry.trackingAfter)},
                                   {u"before"_s, table.add(entry.before.get(), entry.beforeMark)},
                                   {u"after"_s, table.add(entry.after.get(), entry.afterMark)}});
    const QJsonValue origin = table.add(project.origin.get(), project.originMark);

    // The current state is usually the end of the last command: stored once if it is that state
    // bit for bit (operator== would also take -0.0 for 0.0).
    const QByteArray current = encodeState(project.state, stateEncoding(kVersion));
    std::optional<qint64> currentIndex;
    // How each state was reached, the current one counted as stored on its own (last, so that no
    // other state is reached from it: it was taken after all of them).
    std::vector<JournalMark> marks = table.marks();
    marks.push_back(project.stateMark);
    DriveTable drives;
    const std::vector<QJsonValue> reached = reachedJson(marks, drives);
    QJsonArray states;
    qint64 offset = 0;
    auto addBlob = [&](const QByteArray& raw) {
        if (raw.size() > kMaxRawBlob) {
            encoded.error = u"state %1 is %2 bytes, over the format's limit of %3"_s.arg(states.size()).arg(raw.size()).arg(kMaxRawBlob);
            return;
        }
        // The fastest level: packed, a state's byte planes are mostly runs, which every level
        // finds (docs/project-format.md, "Compression").
        encoded.blobs.push_back(qCompress(raw, 1));
        const qint64 length = encoded.blobs.back().size();
        QJsonObject blob{{u"offset"_s, offset}, {u"length"_s, length}, {u"raw_length"_s, qint64(raw.size())}};
        if (const QJsonValue& how = reached[std::size_t(states.size())]; !how.isUndefined())
            blob.insert(u"reached"_s, how);
        states.append(blob);
        offset += length;
    };
    for (const sim::SimulationState* state : table.states()) {
        const QByteArray raw = encodeState(*state, stateEncoding(kVersion));
        if (!currentIndex && *state == project.state && raw == current)
            currentIndex = qint64(states.size());
        addBlob(raw);
    }
    if (!currentIndex) {
        currentIndex = qint64(states.size());
        addBlob(current);
    }
    if (!encoded.error.isEmpty())
        return encoded;

    const QJsonObject manifest{{u"scene"_s, sceneToJsonObject(project.scene, SvgShapes::Embedded)},
                               {u"regions"_s, tableJson(project.regions)},
                               {u"steps"_s, qint64(project.steps)},
                               {u"state"_s, *currentIndex},
                               {u"history"_s, history},
                               {u"history_index"_s, project.historyIndex},
                               {u"origin"_s, origin},
                               {u"drives"_s, drives.toJson()},
                               {u"states"_s, states}};
    // Compact: the journal is mostly short arrays of numbers, which indenting would triple.
    const QByteArray json = QJsonDocument(manifest).toJson(QJsonDocument::Compact);
    encoded.head = kMagic.toByteArray() + QByteArray::number(kVersion) + '\n';
    const quint64 length = qToLittleEndian(quint64(json.size()));
    encoded.head.append(reinterpret_cast<const char*>(&length), sizeof length);
    encoded.head.append(json);
    return encoded;
}

} // namespace

QByteArray projectToBytes(const Project& project)
{
    const EncodedProject encoded = encodeProject(project);
    if (!encoded.error.isEmpty())
        return {};
    QByteArray bytes = encoded.head;
    for (const QByteArray& blob : encoded.blobs)
        bytes.append(blob);
    return bytes;
}

QString writeProjectFile(const Project& project, const QString& path)
{
    const EncodedProject encoded = encodeProject(project);
    if (!encoded.error.isEmpty())
        return json::oneLine(u"%1: cannot save: %2"_s.arg(path, encoded.error));
    return saveAtomically(path, [&encoded](QIODevice& file) {
        QString error = writeAll(file, encoded.head);
        for (auto blob = encoded.blobs.begin(); error.isEmpty() && blob != encoded.blobs.end(); ++blob)
            error = writeAll(file, *blob);
        return error;
    });
}

} // namespace vf::model
