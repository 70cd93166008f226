// `vectorfluid render` on a scene with a gather (target-driven design) whose target is text: eight
// drops beside a bold "I" flow into it, the stats say how much of the letter the ink fills before
// and after, nothing crosses (--check-topology) and every drop keeps its area.
#include "CliRun.h"

#include "../TestFiles.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <cmath>
#include <numbers>

using namespace vf::test;

class TestCliGather : public QObject {
    Q_OBJECT

private slots:
    void dropsGatherIntoTheLetter()
    {
        const QString scene = QStringLiteral(VF_TEST_DATA "/scenes/gather-letter.vfscene");
        const QTemporaryDir dir;
        QList<QJsonObject> stats;
        for (const char* steps : {"0", "300"}) {
            const QString path = dir.filePath(QStringLiteral("s%1.json").arg(QLatin1String(steps)));
            const CliResult r = runCli({QStringLiteral("render"), scene, QStringLiteral("--backend"), QStringLiteral("reference"),
                                        QStringLiteral("--steps"), QLatin1String(steps), QStringLiteral("--check-topology"),
                                        QStringLiteral("10"), QStringLiteral("--stats"), path});
            QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
            stats << QJsonDocument::fromJson(readAll(path)).object();
        }
        const auto overlap = [](const QJsonObject& s) {
            const QJsonArray gathers = s[QStringLiteral("gathers")].toArray();
            return gathers.size() == 1 ? gathers[0][QStringLiteral("target_overlap")].toDouble() : -1.0;
        };
        qInfo("overlap with the letter: %.3f at the start, %.3f after 3 s", overlap(stats[0]), overlap(stats[1]));
        QCOMPARE(overlap(stats[0]), 0.0);
        QVERIFY2(overlap(stats[1]) > 0.5, qPrintable(QString::number(overlap(stats[1]))));  // 0.75 measured
        const double drop = std::numbers::pi * 0.04 * 0.04;
        for (const QJsonValue& region : stats[1][QStringLiteral("regions")].toArray())
            QVERIFY2(std::abs(region[QStringLiteral("area")].toDouble() / drop - 1.0) < 0.01,
                     qPrintable(QString::number(region[QStringLiteral("area")].toDouble() / drop)));
    }
};

QTEST_GUILESS_MAIN(TestCliGather)
#include "tst_cli_gather.moc"
