// `vectorfluid animate`: the frames of a time range written as Lottie or animated SVG, with the
// command line's conventions: one line on stderr and exit 2 for bad input, nothing written then,
// a file that was there before left as it was.
#include "CliRun.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
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
    void badInputWritesNothing_data();
    void badInputWritesNothing();

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

void TestCliAnimate::badInputWritesNothing_data()
{
    QTest::addColumn<QStringList>("arguments");  // after SCENE; --out is the file `kept`
    QTest::addColumn<QStringList>("saying");
    QTest::newRow("unknown format") << QStringList{QStringLiteral("--out"), QStringLiteral("kept.txt")}
                                    << QStringList{QStringLiteral("kept.txt"), QStringLiteral(".json or .svg")};
    QTest::newRow("no --out") << QStringList{} << QStringList{QStringLiteral("no --out FILE given")};
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
    QTest::newRow("missing folder") << QStringList{QStringLiteral("--out"), QStringLiteral("no/such/folder/a.json")}
                                    << QStringList{QStringLiteral("does not exist")};
}

void TestCliAnimate::badInputWritesNothing()
{
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, saying);
    QTemporaryDir dir;
    for (const QString& name : {QStringLiteral("kept.txt"), QStringLiteral("kept.json")}) {
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write("before") == 6);
    }
    for (QString& argument : arguments)
        if (argument.startsWith(QLatin1String("kept")) || argument.startsWith(QLatin1String("no/")))
            argument = dir.filePath(argument);
    const CliResult r = runCli(QStringList{QStringLiteral("animate"), kStirred} + arguments);
    CHECK_OK(checkOneLineError(r, saying));
    for (const QString& name : {QStringLiteral("kept.txt"), QStringLiteral("kept.json")}) {
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), QByteArray("before"));
    }
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 2);
}

QTEST_GUILESS_MAIN(TestCliAnimate)
#include "tst_cli_animate.moc"
