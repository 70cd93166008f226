// `vectorfluid animate`: the frames of a time range written as Lottie, animated SVG or video, of a
// scene or of a project's history played again, with the command line's conventions: one line on
// stderr and exit 2 for bad input, nothing written then, a file that was there before left as it was.
#include "CliRun.h"
#include "../LiveSession.h"
#include "model/ProjectFile.h"

#include <QFile>
#include <QImage>
#include <QStandardPaths>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace vf;
using namespace vf::test;

namespace {

// 1.0 x 0.8 canvas, dt 0.01, 50 steps; a drop lands at 0.1 s.
const QString kStirred = QStringLiteral(VF_TEST_DATA "/scenes/stirred.vfscene");

QJsonObject readJson(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(file.readAll()).object() : QJsonObject();
}

} // namespace

class TestCliAnimate : public QObject {
    Q_OBJECT

private slots:
    void lottieOfATimeRange();
    void animatedSvgTransparent();
    void mp4();
    void pdfPagesAndFrames();
    void badInputWritesNothing_data();
    void badInputWritesNothing();
    void historyOfAProject();
    void projectWithoutItsJournal();
    void videoWithoutFfmpeg();
    void vertexLimitWritesNothing();

private:
    QTemporaryDir m_dir;
};

void TestCliAnimate::lottieOfATimeRange()
{
    const QString out = m_dir.filePath(QStringLiteral("stirred.json"));
    const CliResult r = runCli({QStringLiteral("animate"), kStirred, QStringLiteral("--out"), out, QStringLiteral("--start"),
                                QStringLiteral("0.05"), QStringLiteral("--end"), QStringLiteral("0.25"), QStringLiteral("--fps"),
                                QStringLiteral("20"), QStringLiteral("--width"), QStringLiteral("300"),
                                QStringLiteral("--backend"), QStringLiteral("reference")});
    QVERIFY2(r.exitCode == 0 && r.err.isEmpty(), qPrintable(describe(r)));
    QCOMPARE(r.out, QByteArray("wrote " + out.toUtf8() + '\n'));
    const QJsonObject lottie = readJson(out);
    QCOMPARE(lottie[QLatin1String("fr")].toDouble(), 20.0);
    QCOMPARE(lottie[QLatin1String("op")].toInt(), 4);  // 0.05, 0.10, 0.15, 0.20 s
    QCOMPARE(lottie[QLatin1String("w")].toInt(), 300);
    QCOMPARE(lottie[QLatin1String("h")].toInt(), 240);
    const QJsonArray layers = lottie[QLatin1String("layers")].toArray();
    QCOMPARE(layers.size(), 4);  // splash, madder, ink, background
    QCOMPARE(layers[0].toObject()[QLatin1String("nm")].toString(), QStringLiteral("splash"));
    // The drop lands at 0.1 s, as the step from 0.1 s begins: the frame at 0.15 s is its first.
    QCOMPARE(layers[0].toObject()[QLatin1String("ip")].toInt(), 2);
    QCOMPARE(layers[3].toObject()[QLatin1String("nm")].toString(), QStringLiteral("Background"));
}

void TestCliAnimate::animatedSvgTransparent()
{
    const QString out = m_dir.filePath(QStringLiteral("stirred.svg"));
    const CliResult r = runCli({QStringLiteral("animate"), kStirred, QStringLiteral("--out"), out, QStringLiteral("--end"),
                                QStringLiteral("0.1"), QStringLiteral("--fps"), QStringLiteral("50"),
                                QStringLiteral("--transparent"), QStringLiteral("--backend"), QStringLiteral("reference")});
    QVERIFY2(r.exitCode == 0 && r.err.isEmpty(), qPrintable(describe(r)));
    QFile file(out);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray svg = file.readAll();
    QCOMPARE(svg.count("<g id=\"frame-"), 5);
    QCOMPARE(svg.count("dur=\"0.1s\""), 5);
    QVERIFY(!svg.contains("Background"));
}

void TestCliAnimate::mp4()
{
    const QString out = m_dir.filePath(QStringLiteral("stirred.mp4"));
    const CliResult r = runCli({QStringLiteral("animate"), kStirred, QStringLiteral("--out"), out, QStringLiteral("--end"),
                                QStringLiteral("0.1"), QStringLiteral("--fps"), QStringLiteral("50"), QStringLiteral("--width"),
                                QStringLiteral("100"), QStringLiteral("--backend"), QStringLiteral("reference")});
    QVERIFY2(r.exitCode == 0 && r.err.isEmpty(), qPrintable(describe(r)));
    QFile file(out);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.read(8).mid(4), QByteArray("ftyp"));  // an MP4 file; tests/render/tst_video probes the stream
}

// A PDF of a page a frame, and the same frames as PNG files of their own.
void TestCliAnimate::pdfPagesAndFrames()
{
    const QString pdf = m_dir.filePath(QStringLiteral("stirred.pdf"));
    const QStringList range{QStringLiteral("--end"), QStringLiteral("0.1"), QStringLiteral("--fps"), QStringLiteral("30"),
                            QStringLiteral("--width"), QStringLiteral("100"), QStringLiteral("--backend"), QStringLiteral("reference")};
    CliResult r = runCli(QStringList{QStringLiteral("animate"), kStirred, QStringLiteral("--out"), pdf} + range);
    QVERIFY2(r.exitCode == 0 && r.err.isEmpty(), qPrintable(describe(r)));
    const QString pdfinfo = QStandardPaths::findExecutable(QStringLiteral("pdfinfo"));
    if (!pdfinfo.isEmpty()) {
        r = runProgram(pdfinfo, {pdf});
        QVERIFY2(r.exitCode == 0 && QString::fromUtf8(r.out).contains(QRegularExpression(QStringLiteral("Pages: +3\\n"))),
                 qPrintable(describe(r)));
    }
    const QString frames = m_dir.filePath(QStringLiteral("frames"));
    r = runCli(QStringList{QStringLiteral("animate"), kStirred, QStringLiteral("--frames"), frames, QStringLiteral("--frame-format"),
                           QStringLiteral("png")} + range);
    QVERIFY2(r.exitCode == 0 && r.err.isEmpty(), qPrintable(describe(r)));
    QCOMPARE(QDir(frames).entryList(QDir::Files),
             (QStringList{QStringLiteral("frame-000000.png"), QStringLiteral("frame-000001.png"), QStringLiteral("frame-000002.png")}));
    QCOMPARE(QImage(QDir(frames).filePath(QStringLiteral("frame-000002.png"))).size(), QSize(100, 80));
}

void TestCliAnimate::badInputWritesNothing_data()
{
    QTest::addColumn<QStringList>("arguments");  // after SCENE; --out is the file `kept`
    QTest::addColumn<QStringList>("saying");
    QTest::newRow("unknown format") << QStringList{QStringLiteral("--out"), QStringLiteral("kept.txt")}
                                    << QStringList{QStringLiteral("kept.txt"), QStringLiteral(".json, .svg, .pdf, .mp4 or .gif")};
    QTest::newRow("no --out") << QStringList{} << QStringList{QStringLiteral("give either --out FILE or --frames DIR")};
    QTest::newRow("bad frame format") << QStringList{QStringLiteral("--frames"), QStringLiteral("kept-frames"), QStringLiteral("--frame-format"),
                                                     QStringLiteral("gif")}
                                      << QStringList{QStringLiteral("--frame-format: 'gif'")};
    QTest::newRow("empty range") << QStringList{QStringLiteral("--out"), QStringLiteral("kept.json"), QStringLiteral("--start"),
                                                QStringLiteral("0.3"), QStringLiteral("--end"), QStringLiteral("0.3")}
                                 << QStringList{QStringLiteral("0 frames")};
    QTest::newRow("negative start") << QStringList{QStringLiteral("--out"), QStringLiteral("kept.json"), QStringLiteral("--start"),
                                                   QStringLiteral("-1")}
                                    << QStringList{QStringLiteral("--start: '-1'")};
    QTest::newRow("bad fps") << QStringList{QStringLiteral("--out"), QStringLiteral("kept.json"), QStringLiteral("--fps"),
                                            QStringLiteral("0")}
                             << QStringList{QStringLiteral("--fps: '0'")};
    QTest::newRow("unknown option") << QStringList{QStringLiteral("--out"), QStringLiteral("kept.json"), QStringLiteral("--bogus")}
                                    << QStringList{QStringLiteral("unknown option --bogus (see vectorfluid animate --help)")};
    QTest::newRow("transparent MP4") << QStringList{QStringLiteral("--out"), QStringLiteral("kept.mp4"), QStringLiteral("--transparent")}
                                     << QStringList{QStringLiteral("MP4 has no transparency")};
    QTest::newRow("missing folder") << QStringList{QStringLiteral("--out"), QStringLiteral("no/such/folder/a.json")}
                                    << QStringList{QStringLiteral("does not exist")};
}

void TestCliAnimate::badInputWritesNothing()
{
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, saying);
    QTemporaryDir dir;
    for (const QString& name : {QStringLiteral("kept.txt"), QStringLiteral("kept.json"), QStringLiteral("kept.mp4")}) {
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write("before") == 6);
    }
    for (QString& argument : arguments)
        if (argument.startsWith(QLatin1String("kept")) || argument.startsWith(QLatin1String("no/")))
            argument = dir.filePath(argument);
    const CliResult r = runCli(QStringList{QStringLiteral("animate"), kStirred} + arguments);
    CHECK_OK(checkOneLineError(r, saying));
    for (const QString& name : {QStringLiteral("kept.txt"), QStringLiteral("kept.json"), QStringLiteral("kept.mp4")}) {
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), QByteArray("before"));
    }
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 3);
}

// A project's history, played again: from where the work was opened, a frame a step, through the
// command (a drop and a pen) to now; its layers are the regions of each span.
void TestCliAnimate::historyOfAProject()
{
    Live live(water());
    const Live::Kept origin = live.keep();
    live.step();
    const Live::Kept before = live.keep();
    live.drop({0.7, 0.5}, 0.08);
    for (int k = 0; k < 4; ++k)
        live.step({pen(0.2 + 0.05 * k, 0.25 + 0.05 * k)});
    const Live::Kept after = live.keep();
    live.step();
    const QString project = m_dir.filePath(QStringLiteral("played.vfproj"));
    QCOMPARE(model::writeProjectFile(live.project(origin, before, after, live.keep()), project), QString());

    const QString out = m_dir.filePath(QStringLiteral("history.json"));
    const CliResult r = runCli({QStringLiteral("animate"), project, QStringLiteral("--out"), out, QStringLiteral("--fps"),
                                QStringLiteral("100"), QStringLiteral("--backend"), QStringLiteral("reference")});
    QVERIFY2(r.exitCode == 0 && r.err.isEmpty(), qPrintable(describe(r)));
    const QJsonObject lottie = readJson(out);
    QCOMPARE(lottie[QLatin1String("op")].toInt(), 6);  // the whole history: six steps of 0.01 s
    QStringList layers;
    for (const QJsonValue& layer : lottie[QLatin1String("layers")].toArray())
        layers << layer[QLatin1String("nm")].toString();
    QCOMPARE(layers, (QStringList{QStringLiteral("ink 1"), QStringLiteral("ink 0"), QStringLiteral("Background")}));
}

// A project saved before projects kept their journal has nothing to play: one line, exit 2.
void TestCliAnimate::projectWithoutItsJournal()
{
    const QString out = m_dir.filePath(QStringLiteral("old.json"));
    const CliResult r = runCli({QStringLiteral("animate"), QStringLiteral(VF_TEST_DATA "/projects/fluid.vfproj"),
                                QStringLiteral("--out"), out});
    CHECK_OK(checkOneLineError(r, {QStringLiteral("fluid.vfproj: its history holds no step that can be played again")}));
    QVERIFY(!QFile::exists(out));
}

// Video needs the ffmpeg program: without it on PATH, one line says so at once and nothing is written.
void TestCliAnimate::videoWithoutFfmpeg()
{
    const QString out = m_dir.filePath(QStringLiteral("no-ffmpeg.mp4"));
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("PATH"), m_dir.path());  // a folder without ffmpeg
    process.setProcessEnvironment(environment);
    // Said before any step: playing to 1000 s of the scene first would take minutes.
    process.start(kBinary, {QStringLiteral("animate"), kStirred, QStringLiteral("--out"), out, QStringLiteral("--start"),
                            QStringLiteral("1000"), QStringLiteral("--end"), QStringLiteral("1000.1"),
                            QStringLiteral("--backend"), QStringLiteral("reference")});
    QVERIFY(process.waitForFinished(20000));
    const CliResult r{process.exitCode(), process.readAllStandardOutput(), process.readAllStandardError()};
    CHECK_OK(checkOneLineError(r, {out, QStringLiteral("ffmpeg is not installed")}));
    QVERIFY(!QFile::exists(out));
}

// A limit that stops the simulation part-way stops the animation: exit 3, one line, no file.
void TestCliAnimate::vertexLimitWritesNothing()
{
    const QString out = m_dir.filePath(QStringLiteral("limit.json"));
    const CliResult r = runCli({QStringLiteral("animate"), QStringLiteral(VF_TEST_DATA "/scenes/vertex-limit.vfscene"),
                                QStringLiteral("--out"), out, QStringLiteral("--backend"), QStringLiteral("reference")});
    CHECK_OK(checkOneLineError(r, {QStringLiteral("max_vertices (200) reached at frame"), QStringLiteral("no output written")}, 3));
    QVERIFY(!QFile::exists(out));
}

QTEST_GUILESS_MAIN(TestCliAnimate)
#include "tst_cli_animate.moc"

