// Project files: a written project reads back bit for bit with its states shared as they were, a
// failed save keeps the old file, the writer refuses what the reader would refuse, and every kind
// of broken file (made here by corrupting a good one) gives one line naming the problem.
// One file past 500 lines: each kind of broken file is a case, made by the corrupting helpers below.
#include "model/EngineSettings.h"
#include "model/ProjectFile.h"
#include "model/ProjectFormat.h"
#include "model/StateBlob.h"

#include "../TestFiles.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtEndian>
#include <QRegularExpression>
#include <QtTest>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <numbers>

using namespace vf;
using namespace vf::model;
using namespace Qt::StringLiterals;

namespace {

// Numbers that need all 17 digits, a negative zero and a subnormal: text would lose some of them.
sim::Contour contour(int region, int n, double shift)
{
    sim::Contour c;
    c.region = region;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n;
        c.positions.emplace_back(0.5 + shift + 0.1 * std::cos(a), 0.5 + 0.1 * std::sin(a) / 3.0);
        c.previous.emplace_back(c.positions.back() - sim::Vec2(1e-7 / 7.0, -0.0));
        c.spacing.push_back(0.004 + i * std::numeric_limits<double>::denorm_min());
    }
    c.targetArea = std::numbers::pi * 0.01 / 3.0;
    return c;
}

sim::SimulationState fluidState(double time, int regionCount)
{
    sim::SimulationState s;
    s.time = time;
    s.regionCount = regionCount;
    for (int r = 0; r < regionCount; ++r)
        s.contours.push_back(contour(r, 5 + r, 0.01 * r + time));
    sim::FluidState fluid;
    fluid.velocity = {6, 4, 1.0 / 6.0, 0.25, {}, {}};
    for (int i = 0; i < 7 * 4; ++i)
        fluid.velocity.u.push_back(std::sin(i + time) / 3.0);
    for (int i = 0; i < 6 * 5; ++i)
        fluid.velocity.v.push_back(i % 3 ? -std::cos(i) / 7.0 : -0.0);
    for (int i = 0; i < 6 * 4; ++i)
        fluid.pressure.push_back(1e-300 * i - 1e300 / (i + 1));
    s.fluid = fluid;
    s.pendingStylus.push_back({{0.1, 0.2}, {0.3 + 1e-16, 0.4}, 0.03, 1.0 / 60.0});
    s.pendingStylus.push_back({{0.3, 0.4}, {0.35, 0.45}, 0.03, 0.0});
    return s;
}

// `state` with each contour resampled to `vertices` float32 points on its ellipse, moved a little
// since the previous ones, with a varying spacing and a smooth float32 fluid, as a snapshot of the
// OpenCL backend holds them.
sim::SimulationState float32State(sim::SimulationState state, int vertices)
{
    // Computed in float throughout: GCC 12 at -O2 was seen to drop the rounding of a double to
    // float and back.
    for (sim::Contour& c : state.contours) {
        const auto centre = float(0.5 + 0.01 * c.region + state.time);
        c = contour(c.region, vertices, 0.0);
        for (std::size_t i = 0; i < c.positions.size(); ++i) {
            const float a = 2.0f * std::numbers::pi_v<float> * float(i) / float(vertices);
            const float x = centre + 0.1f * std::cos(a), y = 0.5f + 0.033f * std::sin(a);
            c.positions[i] = {x, y};
            c.previous[i] = {x - 1e-3f * std::sin(a), y + 1e-3f * std::cos(a)};
            c.spacing[i] = 0.003f + 0.001f * std::sin(3.0f * a);
        }
    }
    for (std::vector<double>* field : {&state.fluid->velocity.u, &state.fluid->velocity.v, &state.fluid->pressure})
        for (std::size_t i = 0; i < field->size(); ++i)
            (*field)[i] = std::sin(0.1f * float(i) + float(state.time));
    return state;
}

sim::SimulationState analyticState()
{
    sim::SimulationState s;
    s.time = 1.0 / 3.0;
    s.regionCount = 2;
    s.contours = {contour(1, 7, 0.0), contour(0, 3, 0.2), contour(1, 4, -0.2)};
    return s;
}

Scene fluidScene()
{
    Scene scene;
    scene.canvas = {1.5, 0.7071067811865476, QColor(18, 52, 86, 200)};
    scene.flow.gridX = 6;
    scene.flow.gridY = 4;
    scene.regions.push_back({u"ink"_s, QColor(29, 53, 87), true, CircleShape{{0.5, 0.5}, 0.1}});
    scene.strokes.push_back(DropStroke{0.5, {0.5, 0.5}, 0.1, QColor(241, 196, 15), u"sun"_s});
    return scene;
}

RegionTable table(std::initializer_list<RegionLook> looks) { return looks; }

// Four commands: a drop, a recolour (no states), a stroke whose start is the drop's end, and an
// undone stroke; the current state is the third command's end.
Project fluidProject()
{
    auto s0 = std::make_shared<const sim::SimulationState>(fluidState(0.0, 1));
    auto s1 = std::make_shared<const sim::SimulationState>(fluidState(0.5, 2));
    auto s2 = std::make_shared<const sim::SimulationState>(fluidState(0.75, 2));
    auto s3 = std::make_shared<const sim::SimulationState>(fluidState(1.0, 2));
    const RegionLook ink{u"ink"_s, QColor(29, 53, 87), true, 0};
    const RegionLook sun{u"sün ☀ \"drop\""_s, QColor(241, 196, 15, 17), false, 1};
    RegionLook sunRed = sun;
    sunRed.color = QColor(255, 0, 0, 0);

    Project p;
    p.scene = fluidScene();
    p.regions = table({sun, ink});
    p.state = *s2;
    p.steps = 375;
    p.history = {
        {u"Drop"_s, table({ink}), table({ink, sun}), s0, s1, {}, {}, {}, {}, {}, {}},
        {u"Recolour “sün”"_s, table({ink, sun}), table({ink, sunRed}), nullptr, nullptr, {}, {}, {}, {}, {}, {}},
        {u"Stroke"_s, table({ink, sunRed}), table({sun, ink}), s1, s2, {}, {}, {}, {}, {}, {}},
        {u"Stroke"_s, table({sun, ink}), table({sun, ink}), s2, s3, {}, {}, {}, {}, {}, {}},
    };
    // The last stroke came after a switch to shape design and a finer spacing.
    p.history[3].flowBefore.viscosity = p.history[3].flowAfter.viscosity = shapeDesignPreset.viscosity;
    p.history[3].trackingBefore.maxSpacing = p.history[3].trackingAfter.maxSpacing = 0.002;
    p.history[2].flowAfter = p.history[3].flowBefore;
    p.historyIndex = 3;
    return p;
}

Project analyticProject()
{
    Project p;
    p.scene.flow = {FlowSpec::Type::Analytic, 64, 64, 5e-4, true, u"-(y - 0.5)"_s, u"x - 0.5"_s};
    p.regions = table({{u"a"_s, QColor(1, 2, 3), true, 1}, {u"b"_s, QColor(4, 5, 6, 7), true, 0}});
    p.state = analyticState();
    p.steps = 123;
    return p;
}

// Doubles compared by their bits: operator== takes -0.0 for 0.0.
template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool sameBits(const sim::SimulationState& a, const sim::SimulationState& b)
{
    if (!(a == b) || a.fluid.has_value() != b.fluid.has_value())
        return false;
    for (std::size_t i = 0; i < a.contours.size(); ++i) {
        const sim::Contour &ca = a.contours[i], &cb = b.contours[i];
        if (!sameBits(ca.positions, cb.positions) || !sameBits(ca.previous, cb.previous) || !sameBits(ca.spacing, cb.spacing))
            return false;
    }
    return !a.fluid || (sameBits(a.fluid->velocity.u, b.fluid->velocity.u) && sameBits(a.fluid->velocity.v, b.fluid->velocity.v)
                        && sameBits(a.fluid->pressure, b.fluid->pressure));
}

std::vector<const sim::SimulationState*> statePointers(const Project& p)
{
    std::vector<const sim::SimulationState*> pointers;
    for (const HistoryEntry& e : p.history) {
        pointers.push_back(e.before.get());
        pointers.push_back(e.after.get());
    }
    return pointers;
}

void verifySameProject(const Project& read, const Project& written)
{
    QCOMPARE(read.scene, written.scene);
    QCOMPARE(read.regions, written.regions);
    QVERIFY(sameBits(read.state, written.state));
    QCOMPARE(read.steps, written.steps);
    QCOMPARE(read.historyIndex, written.historyIndex);
    QCOMPARE(read.history.size(), written.history.size());
    for (std::size_t i = 0; i < read.history.size(); ++i) {
        const HistoryEntry &r = read.history[i], &w = written.history[i];
        QCOMPARE(r.text, w.text);
        QCOMPARE(r.regionsBefore, w.regionsBefore);
        QCOMPARE(r.regionsAfter, w.regionsAfter);
        QCOMPARE(r.flowBefore, w.flowBefore);
        QCOMPARE(r.flowAfter, w.flowAfter);
        QCOMPARE(r.trackingBefore, w.trackingBefore);
        QCOMPARE(r.trackingAfter, w.trackingAfter);
        for (const auto& [rs, ws] : {std::pair(r.before, w.before), std::pair(r.after, w.after)}) {
            QCOMPARE(bool(rs), bool(ws));
            QVERIFY(!rs || sameBits(*rs, *ws));
        }
    }
    // Sharing: two references name one object after reading exactly when they did before.
    const auto r = statePointers(read), w = statePointers(written);
    for (std::size_t i = 0; i < r.size(); ++i) {
        for (std::size_t j = 0; j < r.size(); ++j)
            QCOMPARE(r[i] == r[j], w[i] == w[j]);
    }
}

// ---- the file's parts, to corrupt one at a time -----------------------------------------------

struct FileParts {
    QByteArray headerLine;  // "VFPROJ 1\n"
    QJsonObject manifest;
    QByteArray data;
};

FileParts partsOf(const QByteArray& file)
{
    FileParts parts;
    const qsizetype lineEnd = file.indexOf('\n') + 1;
    parts.headerLine = file.first(lineEnd);
    const auto length = qsizetype(qFromLittleEndian<quint64>(file.constData() + lineEnd));
    parts.manifest = QJsonDocument::fromJson(file.sliced(lineEnd + 8, length)).object();
    parts.data = file.sliced(lineEnd + 8 + length);
    return parts;
}

QByteArray withManifest(const QByteArray& headerLine, const QByteArray& manifest, const QByteArray& data)
{
    const quint64 length = qToLittleEndian(quint64(manifest.size()));
    return headerLine + QByteArray(reinterpret_cast<const char*>(&length), 8) + manifest + data;
}

QByteArray fileOf(const FileParts& parts)
{
    return withManifest(parts.headerLine, QJsonDocument(parts.manifest).toJson(), parts.data);
}

// Sets the value at "history/1/before" (array indices as numbers) inside a manifest.
QJsonValue setAt(const QJsonValue& node, QStringList path, const QJsonValue& value)
{
    if (path.isEmpty())
        return value;
    const QString step = path.takeFirst();
    if (node.isArray()) {
        QJsonArray array = node.toArray();
        const int i = step.toInt();
        array[i] = setAt(array[i], path, value);
        return array;
    }
    QJsonObject object = node.toObject();
    if (value.isUndefined() && path.isEmpty())
        object.remove(step);
    else
        object[step] = setAt(object[step], path, value);
    return object;
}

using Corruption = std::function<QByteArray(const QByteArray&)>;

Corruption setManifest(const QString& path, const QJsonValue& value)
{
    return [path, value](const QByteArray& good) {
        FileParts parts = partsOf(good);
        parts.manifest = setAt(parts.manifest, path.split(u'/'), value).toObject();
        return fileOf(parts);
    };
}

// Each state blob of `file` (a written project) re-encoded by `encode`, stored uncompressed, and
// the manifest's offsets and lengths fixed; `header` replaces the first line.
QByteArray reencodeStates(const QByteArray& file, const QByteArray& header,
                          const std::function<QByteArray(qsizetype index, const QByteArray& packed)>& encode)
{
    FileParts parts = partsOf(file);
    parts.headerLine = header;
    QJsonArray states = parts.manifest[u"states"_s].toArray();
    QByteArray data;
    for (qsizetype i = 0; i < states.size(); ++i) {
        const QJsonObject s = states[i].toObject();
        const QByteArray raw = encode(i, qUncompress(parts.data.sliced(s[u"offset"_s].toInteger(), s[u"length"_s].toInteger())));
        const QByteArray blob = qCompress(raw, 0);
        states[i] = QJsonObject{{u"offset"_s, qint64(data.size())}, {u"length"_s, qint64(blob.size())}, {u"raw_length"_s, qint64(raw.size())}};
        data += blob;
    }
    parts.manifest[u"states"_s] = states;
    parts.data = data;
    return fileOf(parts);
}

// A written project with its states laid out as an older version did (version 1 plain, version 2
// packed from the value before): the same manifest.
QByteArray asVersion(const QByteArray& file, int version)
{
    return reencodeStates(file, "VFPROJ " + QByteArray::number(version) + '\n', [version](qsizetype, const QByteArray& packed) {
        return encodeState(decodeState(packed, StateEncoding::PackedLinear, json::KeyPath()), projectformat::stateEncoding(version));
    });
}
QByteArray asVersion1(const QByteArray& file) { return asVersion(file, 1); }

// Replaces state 0's blob by `edit` of its encoded bytes: plain in a version 1 file (whose layout
// the edits poke at), or packed as written.
Corruption setState0(const std::function<QByteArray(QByteArray)>& edit, StateEncoding encoding = StateEncoding::Plain)
{
    return [edit, encoding](const QByteArray& good) {
        const QByteArray file = encoding == StateEncoding::Plain ? asVersion1(good) : good;
        return reencodeStates(file, file.first(file.indexOf('\n') + 1),
                              [&edit](qsizetype index, const QByteArray& raw) { return index == 0 ? edit(raw) : raw; });
    };
}

QByteArray poke(QByteArray raw, qsizetype at, const auto& value)
{
    std::memcpy(raw.data() + at, &value, sizeof value);
    return raw;
}

// The raw layout of docs/project-format.md: time, region count, contour count, then contour 0's
// region, target area, position count and first position.
constexpr qsizetype kRegionCountAt = 8, kContourCountAt = 12, kContour0RegionAt = 20, kContour0XAt = 40;

void verifyOneLineError(const QString& error, const QString& file, const QString& expected)
{
    QVERIFY2(!error.isEmpty(), qPrintable(file + u" was accepted"_s));
    QVERIFY2(error.startsWith(file + u": "_s), qPrintable(error));
    QVERIFY2(error.contains(expected), qPrintable(u"expected \"%1\" in: %2"_s.arg(expected, error)));
    QVERIFY2(!error.contains(u'\n') && !error.contains(u'\r'), qPrintable(error));
}

} // namespace

Q_DECLARE_METATYPE(Corruption)
Q_DECLARE_METATYPE(vf::model::Project)

class TestProjectFile : public QObject {
    Q_OBJECT

private slots:
    void fluidProjectRoundTripsExactly()
    {
        const QTemporaryDir dir;
        const QString path = dir.filePath(u"work ü.vfproj"_s);
        const Project written = fluidProject();
        QCOMPARE(writeProjectFile(written, path), QString());
        const ProjectReadResult read = readProjectFile(path);
        QVERIFY2(read.ok(), qPrintable(read.error));
        verifySameProject(read.project, written);
        QVERIFY(read.project.history[1].before == nullptr && read.project.history[1].after == nullptr);
        QCOMPARE(read.project.history[0].after.get(), read.project.history[2].before.get());
        QVERIFY(read.project.history[0].before != read.project.history[0].after);
    }

    // The files in tests/data/projects (also the fuzzer's seeds, docs/fuzzing.md) were written from
    // these projects; reading them keeps files written by earlier builds readable.
    void committedProjectsRead_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<Project>("written");
        QTest::newRow("fluid") << u"fluid.vfproj"_s << fluidProject();
        QTest::newRow("analytic") << u"analytic.vfproj"_s << analyticProject();
    }
    void committedProjectsRead()
    {
        QFETCH(QString, file);
        QFETCH(Project, written);
        const QString path = QStringLiteral(VF_TEST_DATA "/projects/") + file;
        const ProjectReadResult read = readProjectFile(path);
        QVERIFY2(read.ok(), qPrintable(read.error));
        verifySameProject(read.project, written);
    }

    void eachDistinctStateIsStoredOnce()
    {
        const Project project = fluidProject();
        const QByteArray bytes = projectToBytes(project);
        const FileParts parts = partsOf(bytes);
        // s0..s3; the current state is s2 again, bit for bit.
        QCOMPARE(parts.manifest[u"states"_s].toArray().size(), 4);
        QCOMPARE(parts.manifest[u"state"_s].toInteger(), parts.manifest[u"history"_s][2][u"after"_s].toInteger());
        // A current state that differs only in a zero's sign is a state of its own.
        Project signedZero = project;
        signedZero.state.fluid->velocity.v[0] = 0.0;
        const FileParts other = partsOf(projectToBytes(signedZero));
        QCOMPARE(other.manifest[u"states"_s].toArray().size(), 5);
        const ProjectReadResult read = parseProject(projectToBytes(signedZero), u"p"_s);
        QVERIFY2(read.ok(), qPrintable(read.error));
        QVERIFY(!std::signbit(read.project.state.fluid->velocity.v[0]));
        QVERIFY(std::signbit(read.project.history[2].after->fluid->velocity.v[0]));
    }

    // The writer stores its blobs without deflating them; a reader must take deflated ones too.
    void deflatedStatesRead()
    {
        const Project written = fluidProject();
        FileParts parts = partsOf(projectToBytes(written));
        QJsonArray states = parts.manifest[u"states"_s].toArray();
        QByteArray data;
        for (qsizetype i = 0; i < states.size(); ++i) {
            QJsonObject s = states[i].toObject();
            const QByteArray blob = qCompress(qUncompress(parts.data.sliced(s[u"offset"_s].toInteger(), s[u"length"_s].toInteger())), 9);
            s[u"offset"_s] = qint64(data.size());
            s[u"length"_s] = qint64(blob.size());
            states[i] = s;
            data += blob;
        }
        QVERIFY(data.size() < parts.data.size());
        parts.manifest[u"states"_s] = states;
        parts.data = data;
        const ProjectReadResult read = parseProject(fileOf(parts), u"deflated"_s);
        QVERIFY2(read.ok(), qPrintable(read.error));
        verifySameProject(read.project, written);
    }

    // Projects written before the states were packed, or packed from the value before, read the same.
    void olderVersionsRead()
    {
        const Project written = fluidProject();
        const QByteArray current = projectToBytes(written);
        QVERIFY(current.startsWith("VFPROJ 3\n"));
        for (int version : {1, 2}) {
            const QByteArray old = asVersion(current, version);
            QVERIFY(old != current);
            const ProjectReadResult read = parseProject(old, u"old.vfproj"_s);
            QVERIFY2(read.ok(), qPrintable(read.error));
            verifySameProject(read.project, written);
        }
    }

    // A history of states as the OpenCL backend leaves them (float32 values widened to double,
    // smooth along the contours and the grid): packed and deflated, they take a fifth of the plain
    // version 1 file or less (docs/BENCHMARKS.md, "Project files", has a played project's figures).
    void packedStatesAreAFifthOfPlainOnes()
    {
        Project project = fluidProject();
        for (HistoryEntry& entry : project.history) {
            if (entry.before)
                entry.before = std::make_shared<const sim::SimulationState>(float32State(*entry.before, 20000));
            if (entry.after)
                entry.after = std::make_shared<const sim::SimulationState>(float32State(*entry.after, 20000));
        }
        project.state = *project.history[2].after;
        const QByteArray packed = projectToBytes(project), plain = asVersion1(packed);
        QVERIFY(!packed.isEmpty());
        QVERIFY2(packed.size() * 5 <= plain.size(), qPrintable(u"%1 bytes packed, %2 plain"_s.arg(packed.size()).arg(plain.size())));
        // Smooth contours: the linear prediction leaves smaller differences than version 2's.
        const QByteArray version2 = asVersion(packed, 2);
        QVERIFY2(packed.size() < version2.size(), qPrintable(u"%1 bytes linear, %2 from the value before"_s.arg(packed.size()).arg(version2.size())));
        const ProjectReadResult read = parseProject(packed, u"p"_s);
        QVERIFY2(read.ok(), qPrintable(read.error));
        verifySameProject(read.project, project);
    }

    void analyticProjectRoundTripsExactly()
    {
        const Project written = analyticProject();
        const ProjectReadResult read = parseProject(projectToBytes(written), u"a.vfproj"_s);
        QVERIFY2(read.ok(), qPrintable(read.error));
        QVERIFY(!read.project.state.fluid.has_value());
        verifySameProject(read.project, written);
    }

    void writeIntoMissingDirectoryFails()
    {
        const QTemporaryDir dir;
        const QString path = dir.filePath(u"missing/p.vfproj"_s);
        verifyOneLineError(writeProjectFile(fluidProject(), path), path, u"cannot write"_s);
        QVERIFY(!QFile::exists(path));
    }

    // Permissions do not stop root, so the write is made to fail with a file size limit instead.
    void failedWriteKeepsThePreviousFile()
    {
#ifdef Q_OS_UNIX
        const QTemporaryDir dir;
        const QString path = dir.filePath(u"p.vfproj"_s);
        QCOMPARE(writeProjectFile(analyticProject(), path), QString());
        const QByteArray previous = test::readAll(path);
        QString error;
        {
            const test::FileSizeLimit limit(previous.size() + 64);
            QVERIFY(limit.active());
            error = writeProjectFile(fluidProject(), path);
        }
        verifyOneLineError(error, path, u"write failed: File too large"_s);
        QCOMPARE(test::readAll(path), previous);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{u"p.vfproj"_s});
#else
        QSKIP("needs RLIMIT_FSIZE");
#endif
    }

    void writerRefusesWhatCouldNotBeRead_data()
    {
        QTest::addColumn<Project>("project");
        QTest::addColumn<QString>("expected");
        Project p = fluidProject();
        auto bad = std::make_shared<sim::SimulationState>(*p.history[3].after);
        bad->contours[1].positions[2].y = std::numeric_limits<double>::quiet_NaN();
        p.history[3].after = bad;
        QTest::newRow("NaN in a history state") << p << u"history[3].after: contour 1 positions holds a value that is not finite"_s;

        p = fluidProject();
        p.state.contours[0].previous.pop_back();
        QTest::newRow("lengths disagree") << p << u"state: contour 0 has 5 positions but 4 previous positions"_s;

        p = fluidProject();
        p.state.fluid->pressure.push_back(0.0);
        QTest::newRow("pressure off the grid") << p << u"state: the pressure has 25 values, expected 24"_s;

        p = fluidProject();
        p.regions[1].name = p.regions[0].name;
        QTest::newRow("duplicate name") << p << u"regions[1].name: the name"_s;

        p = fluidProject();
        p.history[0].regionsBefore[0].simIndex = 1;  // the drop's start has one region
        QTest::newRow("sim index past the state's regions") << p << u"history[0].regions_before[0].sim_index: 1 is outside"_s;

        p = fluidProject();
        p.historyIndex = 5;
        QTest::newRow("history index") << p << u"history_index: 5 is outside [0, 4]"_s;

        p = fluidProject();
        p.scene.canvas.width = -1.0;
        QTest::newRow("scene") << p << u"scene.canvas.width: must be positive"_s;
    }

    void writerRefusesWhatCouldNotBeRead()
    {
        QFETCH(Project, project);
        QFETCH(QString, expected);
        const QTemporaryDir dir;
        const QString path = dir.filePath(u"p.vfproj"_s);
        QCOMPARE(writeProjectFile(analyticProject(), path), QString());
        const QByteArray previous = test::readAll(path);
        verifyOneLineError(writeProjectFile(project, path), path, u"cannot save: "_s + expected);
        QCOMPARE(test::readAll(path), previous);
        QVERIFY(projectToBytes(project).isEmpty());
    }

    void brokenFilesGiveOneLine_data()
    {
        QTest::addColumn<Corruption>("corrupt");
        QTest::addColumn<QString>("expected");
        auto row = [](const char* name, Corruption c, const QString& expected) { QTest::newRow(name) << c << expected; };
        const auto bytes = [](auto edit) { return Corruption(edit); };

        row("empty", bytes([](const QByteArray&) { return QByteArray(); }), u"header: not a vectorfluid project"_s);
        row("a scene file", bytes([](const QByteArray&) { return QByteArray("{\"vectorfluid\": 1}"); }),
            u"header: not a vectorfluid project (it does not start with \"VFPROJ\")"_s);
        row("newer version", bytes([](QByteArray b) { return b.replace(0, 9, "VFPROJ 4\n"); }),
            u"header: version 4 is not supported (this program reads versions 1 to 3)"_s);
        row("version 0", bytes([](QByteArray b) { return b.replace(0, 9, "VFPROJ 0\n"); }),
            u"header: version 0 is not supported"_s);
        row("no version", bytes([](QByteArray b) { return b.replace(0, 9, "VFPROJ x\n"); }), u"header: the first line has no version number"_s);
        row("endless first line", bytes([](const QByteArray&) { return QByteArray("VFPROJ ").append(40, '1'); }),
            u"header: the first line does not end within 32 bytes"_s);
        row("cut in the header", bytes([](const QByteArray& b) { return b.first(12); }), u"header: the file is truncated"_s);
        row("cut in the manifest", bytes([](const QByteArray& b) { return b.first(100); }),
            u"header: the file is truncated: the manifest is"_s);
        row("cut in the states", bytes([](const QByteArray& b) { return b.chopped(10); }),
            u"states[3]: its bytes ["_s);
        row("hostile manifest length", bytes([](QByteArray b) { return poke(b, 9, qToLittleEndian(~quint64(0))); }),
            u"header: the file is truncated: the manifest is 18446744073709551615 bytes"_s);
        row("broken JSON", bytes([](const QByteArray& b) { return withManifest(partsOf(b).headerLine, "{\n  \"scene\": }", partsOf(b).data); }),
            u"manifest 2:12: broken JSON"_s);
        row("manifest not an object", bytes([](const QByteArray& b) { return withManifest(partsOf(b).headerLine, "[]", partsOf(b).data); }),
            u"manifest: must be a JSON object"_s);
        row("unknown key", setManifest(u"colour"_s, 1), u"colour: unknown key (expected one of: scene, regions,"_s);
        row("missing key", setManifest(u"states"_s, QJsonValue::Undefined), u"states: missing (required)"_s);
        row("scene", setManifest(u"scene/canvas/width"_s, -1), u"scene.canvas.width: must be positive, is -1"_s);
        row("scene version", setManifest(u"scene/vectorfluid"_s, 2), u"scene.vectorfluid: version 2 is not supported"_s);
        row("colour", setManifest(u"regions/0/color"_s, u"red"_s), u"regions[0].color: must be \"#rrggbb\" or \"#rrggbbaa\""_s);
        row("empty name", setManifest(u"regions/1/name"_s, u" "_s), u"regions[1].name: must not be empty"_s);
        row("duplicate name", setManifest(u"history/2/regions_after/1/name"_s, u"sün ☀ \"drop\""_s),
            u"history[2].regions_after[1].name: the name \"sün ☀ \"drop\"\" is already used by entry 0"_s);
        row("sim index past the regions", setManifest(u"regions/1/sim_index"_s, 2),
            u"regions[1].sim_index: 2 is outside the simulation's 2 regions"_s);
        row("negative sim index", setManifest(u"regions/1/sim_index"_s, -1), u"regions[1].sim_index: must be in [0, 99999], is -1"_s);
        row("sim index of a stateless entry", setManifest(u"history/1/regions_after/1/sim_index"_s, 2),
            u"history[1].regions_after[1].sim_index: 2 is outside the simulation's 2 regions"_s);
        row("command with one end", setManifest(u"history/0/after"_s, QJsonValue::Null),
            u"history[0].after: null while before is a state"_s);
        row("fractional steps", setManifest(u"steps"_s, 1.5), u"steps: must be a whole number, is 1.5"_s);
        row("history index", setManifest(u"history_index"_s, 5), u"history_index: 5 is past the 4 history entries"_s);
        row("state index", setManifest(u"history/3/after"_s, 9), u"history[3].after: state 9 does not exist (\"states\" lists 4)"_s);
        row("state index as text", setManifest(u"state"_s, u"2"_s), u"state: must be a number, not the string \"2\""_s);
        row("unused state", setManifest(u"history/3/after"_s, QJsonValue::Null),
            u"states[3]: no history entry, not the current state and not the origin refers to it"_s);
        const auto reached = [](qint64 from, qint64 steps, const QJsonArray& entries) {
            return QJsonObject{{u"from"_s, from}, {u"steps"_s, steps}, {u"entries"_s, entries}};
        };
        const auto entry = [](const QJsonArray& values) { return QJsonArray{values}; };
        row("reached from itself", setManifest(u"states/1/reached"_s, reached(1, 0, {})),
            u"states[1].reached.from: a state cannot be reached from itself"_s);
        row("reached from no state", setManifest(u"states/1/reached"_s, reached(7, 0, {})),
            u"states[1].reached.from: state 7 does not exist (\"states\" lists 4)"_s);
        row("reached in a cycle", bytes([reached](const QByteArray& good) {
                FileParts parts = partsOf(good);
                parts.manifest = setAt(parts.manifest, {u"states"_s, u"0"_s, u"reached"_s}, reached(1, 1, {})).toObject();
                parts.manifest = setAt(parts.manifest, {u"states"_s, u"1"_s, u"reached"_s}, reached(0, 1, {})).toObject();
                return fileOf(parts);
            }),
            u"states[1].reached.from: state 0 is reached, through others, from this one"_s);
        row("journal entry past its steps", setManifest(u"states/1/reached"_s, reached(0, 2, entry({3, u"drop"_s, 0.5, 0.5, 0.1}))),
            u"states[1].reached.entries[0][0]: must be in [0, 2], is 3"_s);
        row("journal entries out of order",
            setManifest(u"states/1/reached"_s, reached(0, 2, {QJsonArray{1, u"remove"_s, 0}, QJsonArray{0, u"remove"_s, 0}})),
            u"states[1].reached.entries[1][0]: must be in [1, 2], is 0"_s);
        row("journal entry kind", setManifest(u"states/1/reached"_s, reached(0, 2, entry({0, u"splash"_s}))),
            u"states[1].reached.entries[0][1]: must be one of \"drop\", \"pen\""_s);
        row("journal entry values", setManifest(u"states/1/reached"_s, reached(0, 2, entry({0, u"drop"_s, 0.5}))),
            u"states[1].reached.entries[0]: a \"drop\" entry has 1 values after its step and kind, not 3"_s);
        row("journal comb sharpness", setManifest(u"states/1/reached"_s,
                                                  reached(0, 2, entry({0, u"comb"_s, 0, 0, 1, 0, 2, 0.1, 0, 0, 1, 0}))),
            u"states[1].reached.entries[0][8]: must be positive"_s);
        row("journal drive without drives", setManifest(u"states/1/reached"_s, reached(0, 2, entry({0, u"drive"_s, 0}))),
            u"states[1].reached.entries[0][2]: names a drive, but the project lists none in \"drives\""_s);
        row("drive covering nothing", setManifest(u"drives"_s, QJsonArray{QJsonObject{
                {u"target"_s, QJsonArray{QJsonArray{QJsonArray{5, 5, 5.1, 5, 5, 5.1}}}}, {u"cells"_s, QJsonArray{8, 8}},
                {u"width"_s, 1}, {u"height"_s, 1}, {u"strength"_s, 1}, {u"attenuation"_s, 1}, {u"blur"_s, 0.1}, {u"gathering"_s, 0}}}),
            u"drives[0]: target drive: the target covers none of the canvas"_s);
        row("drives too large", setManifest(u"drives"_s, [] {
                QJsonArray drives;
                for (int k = 0; k < 5; ++k)
                    drives.append(QJsonObject{{u"target"_s, QJsonArray{QJsonArray{QJsonArray{0.1, 0.1, 0.9, 0.1, 0.5, 0.9}}}},
                                              {u"cells"_s, QJsonArray{1024, 1024}}, {u"width"_s, 1}, {u"height"_s, 1},
                                              {u"strength"_s, 1}, {u"attenuation"_s, 1}, {u"blur"_s, 0.1}, {u"gathering"_s, 0}});
                return drives;
            }()),
            u"drives: the drives' grids hold 5242880 cells in all, more than 4194304"_s);
        row("blob past the end", setManifest(u"states/1/offset"_s, 1e9), u"states[1]: its bytes [1000000000,"_s);
        row("blob length past the end", setManifest(u"states/0/length"_s, 1e15), u"states[0]: its bytes [0, 1000000000000000)"_s);
        row("raw length disagrees", setManifest(u"states/0/raw_length"_s, 7),
            u"states[0]: corrupt compressed data (it does not start with raw_length 7)"_s);
        row("hostile raw length", bytes([](const QByteArray& good) {
                FileParts parts = partsOf(good);
                parts.data = poke(parts.data, 0, qToBigEndian(quint32(0xfffffff0)));
                parts.manifest = setAt(parts.manifest, {u"states"_s, u"0"_s, u"raw_length"_s}, qint64(0xfffffff0)).toObject();
                return fileOf(parts);
            }),
            u"states[0]: raw_length 4294967280 is more than"_s);
        row("corrupt zlib stream", bytes([](const QByteArray& good) {
                FileParts parts = partsOf(good);
                for (int i = 20; i < 30; ++i)
                    parts.data[i] = char(parts.data[i] ^ 0x5a);
                return fileOf(parts);
            }),
            u"states[0]: corrupt compressed data"_s);
        row("blob ends early", setState0([](const QByteArray& raw) { return raw.first(10); }),
            u"states[0]: the state ends in the middle of the region count (at byte 8 of 10)"_s);
        row("blob cut in an array", setState0([](const QByteArray& raw) { return raw.chopped(3); }),
            u"states[0]: the pending stylus: 2 entries do not fit in the 93 bytes left"_s);
        row("bytes left over", setState0([](QByteArray raw) { return raw + "xyz"; }),
            u"states[0]: 3 bytes left over after the state"_s);
        row("hostile contour count", setState0([](QByteArray raw) { return poke(raw, kContourCountAt, qToLittleEndian(quint64(1) << 60)); }),
            u"states[0]: the contours: 1152921504606846976 entries do not fit"_s);
        row("NaN", setState0([](QByteArray raw) { return poke(raw, kContour0XAt, std::numeric_limits<double>::quiet_NaN()); }),
            u"states[0]: contour 0 positions holds a value that is not finite"_s);
        row("infinity", setState0([](QByteArray raw) { return poke(raw, kContour0XAt + 8, -std::numeric_limits<double>::infinity()); }),
            u"states[0]: contour 0 positions holds a value that is not finite"_s);
        row("contour region", setState0([](QByteArray raw) { return poke(raw, kContour0RegionAt, qToLittleEndian(qint32(1))); }),
            u"states[0]: contour 0 belongs to region 1, outside the state's 1 regions"_s);
        row("region count", setState0([](QByteArray raw) { return poke(raw, kRegionCountAt, qToLittleEndian(qint32(-3))); }),
            u"states[0]: the region count -3 is outside [0, 100000]"_s);
        row("lengths disagree", setState0([](const QByteArray&) {
                sim::SimulationState s = fluidState(0.0, 1);
                s.contours[0].spacing.pop_back();
                return encodeState(s, StateEncoding::Plain);
            }),
            u"states[0]: contour 0 has 5 positions but 5 previous positions and 4 spacings (they must agree)"_s);
        row("velocity off the grid", setState0([](const QByteArray&) {
                sim::SimulationState s = fluidState(0.0, 1);
                s.fluid->velocity.nx = 5;
                return encodeState(s, StateEncoding::Plain);
            }),
            u"states[0]: the velocity u has 28 values, expected 24"_s);
        row("packed previous positions of another length", setState0([](const QByteArray&) {
                sim::SimulationState s = fluidState(0.0, 1);
                s.contours[0].previous.pop_back();
                return encodeState(s, StateEncoding::PackedLinear);
            }, StateEncoding::PackedLinear),
            u"states[0]: a contour's previous positions: 8 values, but 10 to predict them from"_s);
        // Contour 0's positions: count, the first point as it is, then the shift and the planes.
        row("packed array without plane 0", setState0([](QByteArray raw) { return poke(raw, kContour0XAt + 16 + 1, quint8(0xfe)); },
                                                      StateEncoding::PackedLinear),
            u"states[0]: a contour's positions: a packed array's shift 0 or planes 254 are impossible"_s);
    }

    void brokenFilesGiveOneLine()
    {
        QFETCH(Corruption, corrupt);
        QFETCH(QString, expected);
        // The error line is all a broken file gives: no Qt message besides it (qUncompress printed
        // "Input data is corrupted" on stderr).
        QTest::failOnWarning(QRegularExpression(u".*"_s));
        const QByteArray good = projectToBytes(fluidProject());
        QVERIFY(parseProject(good, u"good"_s).ok());
        const ProjectReadResult read = parseProject(corrupt(good), u"broken.vfproj"_s);
        verifyOneLineError(read.error, u"broken.vfproj"_s, expected);
        QVERIFY(read.project.history.empty());
    }

    void missingFileSaysSo()
    {
        const QString path = QDir::temp().filePath(u"no such project ü.vfproj"_s);
        verifyOneLineError(readProjectFile(path).error, path, u"cannot open"_s);
    }
};

QTEST_GUILESS_MAIN(TestProjectFile)
#include "tst_projectfile.moc"
