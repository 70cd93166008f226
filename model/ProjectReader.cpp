// Reading *.vfproj files (docs/project-format.md). Everything a file can get wrong is reported as
// one line "<file>: <where>: <what is wrong>", where is "header", "manifest line:col" or a key
// path of the manifest ("states[2]" for what is wrong inside a state's blob). Lengths from the
// file are checked against the file's size before anything is allocated for them.
#include "model/JournalJson.h"
#include "model/ProjectFile.h"
#include "model/ProjectFormat.h"
#include "model/SceneJson.h"
#include "model/StateBlob.h"

#include <QFile>
#include <QJsonDocument>
#include <QtEndian>

#include <zlib.h>

#include <atomic>
#include <exception>
#include <thread>

namespace vf::model {
namespace {

using namespace Qt::StringLiterals;
using namespace json;
using namespace projectformat;

constexpr qint64 kNoState = -1;

struct BlobRef {
    qint64 offset = 0;
    qint64 length = 0;
    qint64 rawLength = 0;
    std::optional<Field> reached;  // read once the drives it may name are (readJournals)
};

// How a state was reached from another (docs/project-format.md, "Journal").
struct Reached {
    qint64 from = kNoState;
    std::int64_t steps = 0;
    std::vector<JournalEntry> entries;  // steps counted from `from`
};

struct HistoryRef {
    HistoryEntry entry;
    qint64 before = kNoState;
    qint64 after = kNoState;
};

// The manifest as read, states still as numbers.
struct Manifest {
    Project project;  // everything but the states
    qint64 state = 0;
    std::vector<HistoryRef> history;
    std::vector<BlobRef> states;
    qint64 origin = kNoState;
    std::vector<DrivePtr> drives;
    std::vector<std::optional<Reached>> reached;  // per state
};

// ---- the manifest -----------------------------------------------------------------------------

qint64 jsonInteger(const Field& f) { return f.integer(0, kMaxJsonInteger); }
qint64 stateIndex(const Field& f) { return f.isNull() ? kNoState : jsonInteger(f); }

const Key<RegionLook> regionKeys[] = {
    {u"name"_s, true, [](const Field& f, RegionLook& r) { r.name = f.name(); }},
    {u"color"_s, true, [](const Field& f, RegionLook& r) { r.color = color(f); }},
    {u"visible"_s, true, [](const Field& f, RegionLook& r) { r.visible = f.boolean(); }},
    {u"sim_index"_s, true, [](const Field& f, RegionLook& r) { r.simIndex = int(f.integer(0, qint64(limits::maxRegions) - 1)); }},
};

RegionTable regionTable(const Field& f)
{
    return readList<RegionLook>(f, 0, qsizetype(limits::maxRegions), [](const Field& item) { return readAs(item, regionKeys); });
}

const Key<HistoryRef> historyKeys[] = {
    {u"text"_s, true, [](const Field& f, HistoryRef& h) { h.entry.text = f.string(); }},
    {u"regions_before"_s, true, [](const Field& f, HistoryRef& h) { h.entry.regionsBefore = regionTable(f); }},
    {u"regions_after"_s, true, [](const Field& f, HistoryRef& h) { h.entry.regionsAfter = regionTable(f); }},
    {u"flow_before"_s, true, [](const Field& f, HistoryRef& h) { h.entry.flowBefore = readFlowObject(f); }},
    {u"flow_after"_s, true, [](const Field& f, HistoryRef& h) { h.entry.flowAfter = readFlowObject(f); }},
    {u"tracking_before"_s, true, [](const Field& f, HistoryRef& h) { h.entry.trackingBefore = readTrackingObject(f); }},
    {u"tracking_after"_s, true, [](const Field& f, HistoryRef& h) { h.entry.trackingAfter = readTrackingObject(f); }},
    {u"before"_s, true, [](const Field& f, HistoryRef& h) { h.before = stateIndex(f); }},
    {u"after"_s, true, [](const Field& f, HistoryRef& h) { h.after = stateIndex(f); }},
};

const Key<BlobRef> blobKeys[] = {
    {u"offset"_s, true, [](const Field& f, BlobRef& b) { b.offset = jsonInteger(f); }},
    {u"length"_s, true, [](const Field& f, BlobRef& b) { b.length = jsonInteger(f); }},
    {u"raw_length"_s, true, [](const Field& f, BlobRef& b) { b.rawLength = f.integer(1, kMaxRawBlob); }},
    {u"reached"_s, false, [](const Field& f, BlobRef& b) { b.reached = f; }},
};

const Key<Reached> reachedKeys[] = {
    {u"from"_s, true, [](const Field& f, Reached& r) { r.from = jsonInteger(f); }},
    {u"steps"_s, true, [](const Field& f, Reached& r) { r.steps = jsonInteger(f); }},
    {u"entries"_s, true, readAlready<Reached>},  // once the steps are known
};

void readJournals(Manifest& m)
{
    for (const BlobRef& blob : m.states) {
        std::optional<Reached>& reached = m.reached.emplace_back();
        if (!blob.reached)
            continue;
        reached = readAs(*blob.reached, reachedKeys);
        reached->entries = readJournal(blob.reached->member(u"entries"_s), reached->steps, m.drives);
    }
}

const Key<Manifest> manifestKeys[] = {
    {u"scene"_s, true, [](const Field& f, Manifest& m) { m.project.scene = readSceneObject(f, {}); }},
    {u"regions"_s, true, [](const Field& f, Manifest& m) { m.project.regions = regionTable(f); }},
    {u"steps"_s, true, [](const Field& f, Manifest& m) { m.project.steps = jsonInteger(f); }},
    {u"state"_s, true, [](const Field& f, Manifest& m) { m.state = jsonInteger(f); }},
    {u"history"_s, true, [](const Field& f, Manifest& m) {
         m.history = readList<HistoryRef>(f, 0, qsizetype(kMaxHistory), [](const Field& item) { return readAs(item, historyKeys); });
     }},
    {u"history_index"_s, true, [](const Field& f, Manifest& m) { m.project.historyIndex = int(f.integer(0, kMaxHistory)); }},
    {u"origin"_s, false, [](const Field& f, Manifest& m) { m.origin = stateIndex(f); }},
    {u"drives"_s, false, [](const Field& f, Manifest& m) { m.drives = readDrives(f); }},
    {u"states"_s, true, [](const Field& f, Manifest& m) {
         // Two per history entry and the current one at most: each is stored once.
         m.states = readList<BlobRef>(f, 1, qsizetype(2 * kMaxHistory + 1), [](const Field& item) { return readAs(item, blobKeys); });
     }},
};

// Indices that span keys: each must name a listed state, and each listed state must be used.
void checkReferences(const Manifest& m)
{
    const KeyPath top;
    const auto stateCount = qint64(m.states.size());
    std::vector<bool> used(m.states.size(), false);
    auto use = [&](qint64 index, const KeyPath& where) {
        if (index == kNoState)
            return;
        if (index >= stateCount)
            where.fail(u"state %1 does not exist (\"states\" lists %2)"_s.arg(index).arg(stateCount));
        used[std::size_t(index)] = true;
    };
    use(m.state, top.key(u"state"_s));
    use(m.origin, top.key(u"origin"_s));
    for (std::size_t i = 0; i < m.reached.size(); ++i) {
        if (!m.reached[i])
            continue;
        const KeyPath where = top.key(u"states"_s).index(qsizetype(i)).key(u"reached"_s).key(u"from"_s);
        if (m.reached[i]->from >= stateCount)
            where.fail(u"state %1 does not exist (\"states\" lists %2)"_s.arg(m.reached[i]->from).arg(stateCount));
        if (m.reached[i]->from == qint64(i))
            where.fail(u"a state cannot be reached from itself"_s);
    }
    for (std::size_t i = 0; i < m.history.size(); ++i) {
        use(m.history[i].before, top.key(u"history"_s).index(qsizetype(i)).key(u"before"_s));
        use(m.history[i].after, top.key(u"history"_s).index(qsizetype(i)).key(u"after"_s));
    }
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (!used[i])
            top.key(u"states"_s).index(qsizetype(i)).fail(u"no history entry, not the current state and not the origin refers to it"_s);
    }
    if (std::size_t(m.project.historyIndex) > m.history.size())
        top.key(u"history_index"_s).fail(u"%1 is past the %2 history entries"_s.arg(m.project.historyIndex).arg(m.history.size()));
}

// ---- the blobs --------------------------------------------------------------------------------

sim::SimulationState readState(const BlobRef& ref, QByteArrayView data, StateEncoding encoding, const KeyPath& where)
{
    const auto dataSize = qint64(data.size());
    if (ref.offset > dataSize || ref.length > dataSize - ref.offset)
        where.fail(u"its bytes [%1, %2) lie beyond the end of the state data (%3 bytes): the file is truncated"_s
                       .arg(ref.offset).arg(ref.offset + ref.length).arg(dataSize));
    const QByteArrayView blob = data.sliced(ref.offset, ref.length);
    // qCompress's format: the raw length, 32-bit big-endian, then a zlib stream.
    if (blob.size() < 4 || qFromBigEndian<quint32>(blob.data()) != quint64(ref.rawLength))
        where.fail(u"corrupt compressed data (it does not start with raw_length %1)"_s.arg(ref.rawLength));
    if (ref.rawLength > (ref.length - 4) * kMaxInflation)
        where.fail(u"raw_length %1 is more than %2 compressed bytes can hold"_s.arg(ref.rawLength).arg(ref.length));
    // zlib itself rather than qUncompress, which prints "qUncompress: Input data is corrupted" to
    // stderr: the one line of the error must be all a bad file shows.
    QByteArray raw(qsizetype(ref.rawLength), Qt::Uninitialized);
    uLongf inflated = uLongf(ref.rawLength);
    const int status = uncompress(reinterpret_cast<Bytef*>(raw.data()), &inflated,
                                  reinterpret_cast<const Bytef*>(blob.data() + 4), uLong(blob.size() - 4));
    if (status == Z_BUF_ERROR && inflated == uLongf(ref.rawLength))
        where.fail(u"corrupt compressed data (it inflates to more than raw_length %1)"_s.arg(ref.rawLength));
    if (status != Z_OK)
        where.fail(u"corrupt compressed data (zlib: %1)"_s.arg(QString::fromLatin1(zError(status))));
    if (inflated != uLongf(ref.rawLength))
        where.fail(u"corrupt compressed data (it inflates to %1 bytes, not raw_length %2)"_s.arg(inflated).arg(ref.rawLength));
    return decodeState(raw, encoding, where);
}

// Every state, each inflated and decoded on its own, on all cores at once. Where several fail,
// the first in the list is reported, as one by one would.
std::vector<std::shared_ptr<const sim::SimulationState>> readStates(const Manifest& m, QByteArrayView data, StateEncoding encoding)
{
    const std::size_t n = m.states.size();
    std::vector<std::shared_ptr<const sim::SimulationState>> states(n);
    std::vector<std::exception_ptr> failures(n);
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t i = next++; i < n; i = next++) {
            try {
                states[i] = std::make_shared<const sim::SimulationState>(
                    readState(m.states[i], data, encoding, KeyPath().key(u"states"_s).index(qsizetype(i))));
            } catch (...) {
                failures[i] = std::current_exception();
            }
        }
    };
    {
        std::vector<std::jthread> helpers(std::min<std::size_t>(n, std::max(1u, std::thread::hardware_concurrency())) - 1);
        for (std::jthread& helper : helpers)
            helper = std::jthread(work);
        work();
    }
    for (const std::exception_ptr& failure : failures)
        if (failure)
            std::rethrow_exception(failure);
    return states;
}

// Where each state was taken in a journal made again from the file: a state reached from another
// continues that one's line (a segment of its entries after the other's head), any other starts a
// line of its own. Those a state is reached from are made first; a cycle is an error.
std::vector<JournalMark> journalMarks(const Manifest& m)
{
    const std::size_t n = m.reached.size();
    std::vector<JournalMark> marks(n);
    enum class Progress : char { NotYet, Waiting, Done };
    std::vector<Progress> progress(n, Progress::NotYet);
    for (std::size_t first = 0; first < n; ++first) {
        std::vector<std::size_t> pending{first};  // each reached from the one above it
        while (!pending.empty()) {
            const std::size_t i = pending.back();
            if (progress[i] == Progress::Done) {
                pending.pop_back();
                continue;
            }
            const std::optional<Reached>& reached = m.reached[i];
            if (!reached) {
                marks[i] = {std::make_shared<const JournalSegment>(), 0};
            } else if (const auto from = std::size_t(reached->from); progress[from] != Progress::Done) {
                const KeyPath where = KeyPath().key(u"states"_s).index(qsizetype(i)).key(u"reached"_s).key(u"from"_s);
                if (progress[from] == Progress::Waiting)
                    where.fail(u"state %1 is reached, through others, from this one"_s.arg(from));
                progress[i] = Progress::Waiting;
                pending.push_back(from);
                continue;
            } else {
                const JournalMark& start = marks[from];
                if (reached->steps > kMaxJsonInteger - start.step)
                    KeyPath().key(u"states"_s).index(qsizetype(i)).key(u"reached"_s).key(u"steps"_s)
                        .fail(u"the states it is reached through take more than %1 steps"_s.arg(kMaxJsonInteger));
                std::vector<JournalEntry> entries = reached->entries;
                for (JournalEntry& e : entries)
                    e.step += start.step;
                marks[i] = {std::make_shared<const JournalSegment>(JournalSegment{std::move(entries), start.head}),
                            start.step + reached->steps};
            }
            progress[i] = Progress::Done;
            pending.pop_back();
        }
    }
    return marks;
}

Project assemble(Manifest& m, QByteArrayView data, StateEncoding encoding)
{
    const std::vector<std::shared_ptr<const sim::SimulationState>> states = readStates(m, data, encoding);
    auto shared = [&states](qint64 index) { return index == kNoState ? nullptr : states[std::size_t(index)]; };

    const std::vector<JournalMark> marks = journalMarks(m);
    auto markOf = [&marks](qint64 index) { return index == kNoState ? JournalMark{} : marks[std::size_t(index)]; };

    Project project = std::move(m.project);
    project.state = *states[std::size_t(m.state)];
    project.stateMark = markOf(m.state);
    project.origin = shared(m.origin);
    project.originMark = markOf(m.origin);
    project.history.reserve(m.history.size());
    for (HistoryRef& ref : m.history) {
        ref.entry.before = shared(ref.before);
        ref.entry.after = shared(ref.after);
        ref.entry.beforeMark = markOf(ref.before);
        ref.entry.afterMark = markOf(ref.after);
        project.history.push_back(std::move(ref.entry));
    }
    checkRegionTables(project);
    checkCommandEnds(project);
    return project;
}

// ---- the container ----------------------------------------------------------------------------

struct Sections {
    int version = kVersion;
    QByteArrayView manifest;
    QByteArrayView data;  // the state blobs; their offsets count from its start
};

Sections split(QByteArrayView bytes)
{
    auto fail = [](const QString& what) { throw ReadError{u"header"_s, what}; };
    if (!bytes.startsWith(kMagic))
        fail(u"not a vectorfluid project (it does not start with \"%1\")"_s.arg(QString::fromLatin1(kMagic.trimmed())));
    const qsizetype lineEnd = bytes.first(std::min(bytes.size(), kMaxHeaderLine)).indexOf('\n');
    if (lineEnd < 0)
        fail(u"the first line does not end within %1 bytes"_s.arg(kMaxHeaderLine));
    const QByteArrayView versionText = bytes.sliced(kMagic.size(), lineEnd - kMagic.size());
    bool isNumber = false;
    const int version = versionText.toInt(&isNumber);
    if (!isNumber)
        fail(u"the first line has no version number after \"%1\""_s.arg(QString::fromLatin1(kMagic.trimmed())));
    if (version < kOldestVersion || version > kVersion)
        fail(u"version %1 is not supported (this program reads versions %2 to %3)"_s.arg(version).arg(kOldestVersion).arg(kVersion));
    const QByteArrayView rest = bytes.sliced(lineEnd + 1);
    if (rest.size() < kLengthBytes)
        fail(u"the file is truncated: it ends before the manifest's length"_s);
    const quint64 length = qFromLittleEndian<quint64>(rest.data());
    if (length > quint64(rest.size() - kLengthBytes))
        fail(u"the file is truncated: the manifest is %1 bytes but only %2 follow"_s.arg(length).arg(rest.size() - kLengthBytes));
    return {version, rest.sliced(kLengthBytes, qsizetype(length)), rest.sliced(kLengthBytes + qsizetype(length))};
}

Manifest readManifest(QByteArrayView text)
{
    // Unlike a scene file, the manifest is only ever written by the program: no friendlier
    // diagnosis of binary bytes than the JSON parser's own.
    const QByteArray json = text.toByteArray();
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError)
        throw ReadError{u"manifest "_s + location(json, error.offset - 1), u"broken JSON: %1"_s.arg(error.errorString())};
    if (!document.isObject())
        throw ReadError{u"manifest"_s, u"must be a JSON object {…}"_s};
    Manifest manifest;
    readObject(Field(document.object(), KeyPath()), manifest, std::span<const Key<Manifest>>(manifestKeys));
    readJournals(manifest);
    checkReferences(manifest);
    return manifest;
}

} // namespace

ProjectReadResult parseProject(const QByteArray& bytes, const QString& sourceName)
{
    ProjectReadResult result;
    try {
        const Sections sections = split(bytes);
        Manifest manifest = readManifest(sections.manifest);
        result.project = assemble(manifest, sections.data, stateEncoding(sections.version));
    } catch (const ReadError& error) {
        result.project = Project();
        result.error = oneLine(u"%1: %2: %3"_s.arg(sourceName, error.where, error.what));
    }
    return result;
}

ProjectReadResult readProjectFile(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {Project(), oneLine(u"%1: cannot open: %2"_s.arg(path, file.errorString()))};
    // Mapped rather than read: the states are inflated straight from the file's pages.
    if (uchar* mapped = file.map(0, file.size()))
        return parseProject(QByteArray::fromRawData(reinterpret_cast<const char*>(mapped), file.size()), path);
    const QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError)
        return {Project(), oneLine(u"%1: cannot read: %2"_s.arg(path, file.errorString()))};
    return parseProject(bytes, path);
}

} // namespace vf::model
