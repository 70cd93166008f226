// `vectorfluid render` on scenes whose regions start from SVG files: the demo renders with one
// region per shape of its logo, and no output may replace the SVG a scene reads. The bad SVG
// scenes are rows of tests/data/bad/EXPECTED.tsv, run by tst_cli's badSceneIsRefused.
#include "CliRun.h"

#include "../TestFiles.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

using namespace vf::test;

namespace {

const QString kScenes = QStringLiteral(VF_SOURCE_DIR "/resources/scenes");

} // namespace

class TestCliSvgShape : public QObject {
    Q_OBJECT

private slots:
    void demoRendersOneRegionPerShape()
    {
        const QTemporaryDir dir;
        const QString stats = dir.filePath(QStringLiteral("s.json"));
        const QString picture = dir.filePath(QStringLiteral("p.svg"));
        const CliResult r = runCli({QStringLiteral("render"), kScenes + QStringLiteral("/swirl-logo.vfscene"), QStringLiteral("--steps"),
                                    QStringLiteral("5"), QStringLiteral("--stats"), stats, QStringLiteral("--out"), picture});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        QStringList names;
        for (const QJsonValue& region : QJsonDocument::fromJson(readAll(stats)).object()[QStringLiteral("regions")].toArray()) {
            names << region[QStringLiteral("name")].toString();
            QVERIFY(region[QStringLiteral("area")].toDouble() > 0.0);
        }
        QCOMPARE(names, (QStringList{QStringLiteral("logo/ring"), QStringLiteral("logo/sun"), QStringLiteral("logo/wave")}));
        QVERIFY(readAll(picture).contains("inkscape:label=\"logo/sun\""));
    }

    // `render logo.vfscene` alone writes logo.svg beside it: here, the logo it reads.
    void theSceneSvgIsNeverOverwritten()
    {
        const QTemporaryDir dir;
        const QString logo = dir.filePath(QStringLiteral("logo.svg"));
        const QByteArray original = readAll(kScenes + QStringLiteral("/logo-mark.svg"));
        QVERIFY(writeFile(logo, original));
        const QString scene = dir.filePath(QStringLiteral("logo.vfscene"));
        QVERIFY(writeFile(scene, R"({"vectorfluid": 1, "time": {"steps": 1},
                                     "regions": [{"name": "logo", "shape": {"svg": "logo.svg"}}]})"));
        for (const QStringList& outputs : {QStringList{}, QStringList{QStringLiteral("--out"), logo}}) {
            const CliResult r = runCli(QStringList{QStringLiteral("render"), scene} + outputs);
            CHECK_OK(checkOneLineError(r, {QStringLiteral("would overwrite the SVG file of regions[0].shape.svg")}));
            QCOMPARE(readAll(logo), original);
        }
    }
};

QTEST_GUILESS_MAIN(TestCliSvgShape)
#include "tst_cli_svgshape.moc"
