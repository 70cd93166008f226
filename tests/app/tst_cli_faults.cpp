// `vectorfluid render` under faults (README, "The command line"): an output that cannot be written
// is found before the first step; a write that fails at the end (file size limit, full disk)
// says why and puts none of the run's outputs in place; Ctrl+C writes nothing half-done.
#include "../TestFiles.h"
#include "CliRun.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <unistd.h>

using namespace vf;
using namespace vf::test;

namespace {

const QString kStirred = QStringLiteral(VF_TEST_DATA "/scenes/stirred.vfscene");
const QByteArray kKeepSvg = "<svg>the previous picture</svg>\n";
const QByteArray kKeepJson = "{\"previous\": true}\n";

QStringList entries(const QString& dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden);
}

// Runs `render SCENE arguments` through bash with `ulimit -f kilobytes`: every write past it fails
// (EFBIG, and SIGXFSZ, which the program must ignore), for root too. On the reference backend:
// PoCL's compiler writes its kernel cache and dies at the limit.
CliResult runWithFileSizeLimit(int kilobytes, const QStringList& arguments)
{
    return runProgram(QStringLiteral("/bin/bash"),
                      QStringList{QStringLiteral("-c"), QStringLiteral("ulimit -f %1 && exec \"$0\" \"$@\"").arg(kilobytes), kBinary,
                                  QStringLiteral("render"), kStirred, QStringLiteral("--backend"), QStringLiteral("reference")}
                          + arguments);
}

// stirred.vfscene with `object`'s `key` set to `value`, written into `dir`.
QString editedScene(const QString& dir, const QString& object, const QString& key, const QJsonValue& value)
{
    QJsonObject root = QJsonDocument::fromJson(readAll(kStirred)).object();
    QJsonObject edited = root.value(object).toObject();
    edited[key] = value;
    root[object] = edited;
    const QString path = QDir(dir).filePath(QStringLiteral("edited.vfscene"));
    return writeFile(path, QJsonDocument(root).toJson()) ? path : QString();
}

} // namespace

class TestCliFaults : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        m_dir = std::make_unique<QTemporaryDir>();
        QVERIFY(m_dir->isValid());
        QVERIFY(writeFile(path(QStringLiteral("keep.svg")), kKeepSvg));
        QVERIFY(writeFile(path(QStringLiteral("keep.json")), kKeepJson));
    }

    // The check comes before the scene runs: not even frame 0 is written.
    void unwritableOutputIsFoundBeforeTheRun_data()
    {
        QTest::addColumn<QString>("culprit");
        QTest::addColumn<QString>("expected");
        // procfs refuses new files whoever asks; permissions do not stop root.
        QTest::newRow("a folder no one may write") << QStringLiteral("/proc/vectorfluid-test.svg") << QStringLiteral("cannot write");
        if (geteuid() != 0)
            QTest::newRow("a read-only folder") << QStringLiteral("@readonly/x.png") << QStringLiteral("cannot write");
        QTest::newRow("a folder in place of the file") << QStringLiteral("@dir") << QStringLiteral("cannot write");
    }
    void unwritableOutputIsFoundBeforeTheRun()
    {
        QFETCH(QString, culprit);
        QFETCH(QString, expected);
        const QString readOnly = path(QStringLiteral("readonly"));
        QVERIFY(QDir().mkpath(readOnly));
        QVERIFY(QFile::setPermissions(readOnly, QFile::ReadOwner | QFile::ExeOwner));
        culprit.replace(QStringLiteral("@readonly"), readOnly);
        culprit.replace(QStringLiteral("@dir"), path(QStringLiteral("a-folder.svg")));
        QVERIFY(QDir().mkpath(path(QStringLiteral("a-folder.svg"))));
        const QString frames = path(QStringLiteral("frames"));

        const CliResult r = runCli({QStringLiteral("render"), kStirred, QStringLiteral("--out"), path(QStringLiteral("keep.svg")),
                                    QStringLiteral("--stats"), path(QStringLiteral("keep.json")), QStringLiteral("--frames"),
                                    frames, QStringLiteral("--out"), culprit});
        QFile::setPermissions(readOnly, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        CHECK_OK(checkOneLineError(r, {culprit, expected}));
        QCOMPARE(entries(frames), QStringList());
        QCOMPARE(readAll(path(QStringLiteral("keep.svg"))), kKeepSvg);
        QCOMPARE(readAll(path(QStringLiteral("keep.json"))), kKeepJson);
    }

    // The SVG and the stats fit under the limit, the PNG does not: the run says why, and neither
    // the SVG nor the stats replace the previous files.
    void fileSizeLimitPutsNothingInPlace()
    {
        const QString png = path(QStringLiteral("big.png"));
        const CliResult r = runWithFileSizeLimit(
            256, {QStringLiteral("--steps"), QStringLiteral("3"), QStringLiteral("--out"),
                  path(QStringLiteral("keep.svg")), QStringLiteral("--stats"), path(QStringLiteral("keep.json")),
                  QStringLiteral("--out"), png, QStringLiteral("--dpi"), QStringLiteral("2400")});
        CHECK_OK(checkOneLineError(r, {png, QStringLiteral("write failed: File too large")}));
        QCOMPARE(readAll(path(QStringLiteral("keep.svg"))), kKeepSvg);
        QCOMPARE(readAll(path(QStringLiteral("keep.json"))), kKeepJson);
        QCOMPARE(entries(m_dir->path()), (QStringList{QStringLiteral("keep.json"), QStringLiteral("keep.svg")}));
    }

    // Each format's writer reports the limit in the system's words, not "Unknown error".
    void fileSizeLimitNamesTheCause_data()
    {
        QTest::addColumn<QString>("file");
        for (const char* name : {"x.svg", "x.pdf", "x.eps", "x.png"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }
    void fileSizeLimitNamesTheCause()
    {
        QFETCH(QString, file);
        const QString out = path(file);
        const CliResult r = runWithFileSizeLimit(
            1, {QStringLiteral("--steps"), QStringLiteral("3"), QStringLiteral("--polyline"),
                QStringLiteral("--out"), out});
        // Cairo's PostScript surface spools to a temporary file of its own first and hides a failed
        // write there: the EPS writer finds the document incomplete instead.
        const QString cause = file.endsWith(QLatin1String(".eps")) ? QStringLiteral("the EPS is incomplete")
                                                                    : QStringLiteral("File too large");
        CHECK_OK(checkOneLineError(r, {out, cause}));
        QVERIFY(!QFileInfo::exists(out));
    }

    // A full file system: a tiny tmpfs, which only root may mount.
    void fullDiskSaysDiskFull()
    {
        if (geteuid() != 0)
            QSKIP("mounting a tmpfs needs root; fileSizeLimitPutsNothingInPlace covers failed writes");
        const QString mountPoint = path(QStringLiteral("tiny"));
        QVERIFY(QDir().mkpath(mountPoint));
        QProcess mount;
        mount.start(QStringLiteral("mount"), {QStringLiteral("-t"), QStringLiteral("tmpfs"), QStringLiteral("-o"),
                                              QStringLiteral("size=64k"), QStringLiteral("tmpfs"), mountPoint});
        if (!mount.waitForFinished(10000) || mount.exitCode() != 0)
            QSKIP(qPrintable(QStringLiteral("cannot mount a tmpfs here: %1").arg(QString::fromUtf8(mount.readAllStandardError()).trimmed())));
        const QString out = QDir(mountPoint).filePath(QStringLiteral("x.svg"));
        const CliResult r = runCli({QStringLiteral("render"), kStirred, QStringLiteral("--steps"), QStringLiteral("3"),
                                    QStringLiteral("--polyline"), QStringLiteral("--out"), out, QStringLiteral("--dpi"),
                                    QStringLiteral("2400"), QStringLiteral("--out"), QDir(mountPoint).filePath(QStringLiteral("x.png"))});
        const QStringList left = entries(mountPoint);
        QProcess::execute(QStringLiteral("umount"), {mountPoint});
        CHECK_OK(checkOneLineError(r, {QStringLiteral("disk full")}));
        QCOMPARE(left, QStringList());
    }

    // Ctrl+C during the run: exit 130, one line, no output and no temporary left; the frames
    // written so far are whole files.
    void interruptWritesNothing()
    {
        const QString frames = path(QStringLiteral("frames"));
        QProcess process;
        process.start(kBinary, {QStringLiteral("render"), kStirred, QStringLiteral("--steps"), QStringLiteral("100000000"),
                                QStringLiteral("--out"), path(QStringLiteral("keep.svg")), QStringLiteral("--stats"),
                                path(QStringLiteral("keep.json")), QStringLiteral("--frames"), frames});
        QVERIFY(process.waitForStarted());
        // Frame 1 is written after the first step: the signal comes in the middle of the run.
        QVERIFY(QTest::qWaitFor([&] { return QFileInfo::exists(QDir(frames).filePath(QStringLiteral("frame-000000002.svg"))); }, 60000));
        QCOMPARE(::kill(pid_t(process.processId()), SIGINT), 0);
        QVERIFY(process.waitForFinished(60000));
        const CliResult r{process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
                          process.readAllStandardOutput(), process.readAllStandardError()};
        CHECK_OK(checkOneLineError(r, {kStirred, QStringLiteral("interrupted at step"), QStringLiteral("no output written")}, 130));
        QVERIFY2(r.out.isEmpty(), qPrintable(describe(r)));
        QCOMPARE(readAll(path(QStringLiteral("keep.svg"))), kKeepSvg);
        QCOMPARE(readAll(path(QStringLiteral("keep.json"))), kKeepJson);
        QCOMPARE(entries(m_dir->path()), (QStringList{QStringLiteral("frames"), QStringLiteral("keep.json"), QStringLiteral("keep.svg")}));
        for (const QString& frame : entries(frames))
            QVERIFY2(QRegularExpression(QStringLiteral("^frame-\\d{9}\\.svg$")).match(frame).hasMatch()
                         && readAll(QDir(frames).filePath(frame)).endsWith("</svg>\n"),
                     qPrintable(frame));
    }

    // Estimates far beyond any test machine's memory (200 GB and 600 GB): refused before the
    // scene runs, in one line that names the limit.
    void memoryLimitsRefuseBeforeAllocating_data()
    {
        QTest::addColumn<QString>("object");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QStringList>("extra");
        QTest::addColumn<QString>("expected");
        QTest::newRow("max_vertices 1e9") << QStringLiteral("tracking") << QStringLiteral("max_vertices") << QJsonValue(1e9)
                                          << QStringList() << QStringLiteral("tracking.max_vertices 1000000000: 200 GB");
        QTest::newRow("--dpi 4800 on a tall canvas")
            << QStringLiteral("canvas") << QStringLiteral("height") << QJsonValue(100)
            << QStringList{QStringLiteral("--out"), QStringLiteral("@dir/x.png"), QStringLiteral("--dpi"), QStringLiteral("4800")}
            << QStringLiteral("--dpi 4800 (a 38400 x 3840000 pixel PNG)");
    }
    void memoryLimitsRefuseBeforeAllocating()
    {
        QFETCH(QString, object);
        QFETCH(QString, key);
        QFETCH(QJsonValue, value);
        QFETCH(QStringList, extra);
        QFETCH(QString, expected);
        const QString scene = editedScene(m_dir->path(), object, key, value);
        QVERIFY(!scene.isEmpty());
        extra.replaceInStrings(QStringLiteral("@dir"), m_dir->path());
        const QString frames = path(QStringLiteral("frames"));
        const CliResult r = runCli(QStringList{QStringLiteral("render"), scene, QStringLiteral("--frames"), frames} + extra);
        CHECK_OK(checkOneLineError(r, {scene, expected, QStringLiteral("available")}));
        QVERIFY(!QFileInfo::exists(frames));
    }

private:
    QString path(const QString& name) const { return m_dir->filePath(name); }

    std::unique_ptr<QTemporaryDir> m_dir;
};

QTEST_GUILESS_MAIN(TestCliFaults)
#include "tst_cli_faults.moc"
