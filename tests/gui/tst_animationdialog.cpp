// File ▸ Export Animation driven through its widgets: typing a path and a range and clicking
// Export writes the animation on a thread of its own while the progress bar counts the frames, and
// the dialog reports the file's size; Cancel mid-way writes nothing; a path without a known suffix
// cannot be exported, and MP4 offers no transparency. (tst_mainwindow opens it from the File menu
// and checks that the document stays as it was.)
#include "FindChild.h"
#include "app/AnimationDialog.h"
#include "model/SceneFile.h"

#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>

using namespace vf;
using vf::test::child;

namespace {

// 1.0 x 0.8 canvas, dt 0.01, 50 steps.
model::Scene stirred()
{
    const model::SceneReadResult read = model::readSceneFile(QStringLiteral(VF_TEST_DATA "/scenes/stirred.vfscene"));
    if (!read.ok())
        qFatal("%s", qPrintable(read.error));
    return read.scene;
}

void typeInto(QLineEdit* edit, const QString& text)
{
    QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(edit, text);
}

void typeInto(QAbstractSpinBox* box, const QString& text)
{
    box->selectAll();
    QTest::keyClicks(box, text);
}

} // namespace

class TestAnimationDialog : public QObject {
    Q_OBJECT

private slots:
    void exportsAndReportsTheSize();
    void cancelWritesNothing();
    void formatFollowsTheSuffix();
};

void TestAnimationDialog::exportsAndReportsTheSize()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("logo.json"));
    app::AnimationDialog dialog(stirred());
    dialog.show();
    QCOMPARE(child<QDoubleSpinBox>(dialog, "end")->value(), 0.5);  // the scene's 50 steps of 0.01 s
    QCOMPARE(child<QSpinBox>(dialog, "fps")->value(), 30);
    typeInto(child<QLineEdit>(dialog, "path"), path);
    typeInto(child<QDoubleSpinBox>(dialog, "end"), QStringLiteral("0.2"));
    typeInto(child<QSpinBox>(dialog, "fps"), QStringLiteral("20"));
    QTest::mouseClick(child<QPushButton>(dialog, "export"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(child<QLabel>(dialog, "result")->text().startsWith(QStringLiteral("Wrote")), 30000);
    QVERIFY(!dialog.running());
    QCOMPARE(dialog.writtenPath(), path);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject lottie = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(lottie[QLatin1String("op")].toInt(), 4);
    QCOMPARE(lottie[QLatin1String("fr")].toDouble(), 20.0);
    QCOMPARE(child<QProgressBar>(dialog, "progress")->value(), 4);
    QVERIFY2(child<QLabel>(dialog, "result")->text().contains(QLocale().formattedDataSize(file.size())),
             qPrintable(child<QLabel>(dialog, "result")->text()));
    QVERIFY(child<QLineEdit>(dialog, "path")->isEnabled());
    QCOMPARE(child<QPushButton>(dialog, "close")->text(), QStringLiteral("Close"));
}

void TestAnimationDialog::cancelWritesNothing()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("long.svg"));
    app::AnimationDialog dialog(stirred());
    dialog.show();
    typeInto(child<QLineEdit>(dialog, "path"), path);
    typeInto(child<QDoubleSpinBox>(dialog, "end"), QStringLiteral("1000"));  // 30,000 frames
    QTest::mouseClick(child<QPushButton>(dialog, "export"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(child<QProgressBar>(dialog, "progress")->value() > 0, 30000);
    QVERIFY(dialog.running());
    QVERIFY(!child<QLineEdit>(dialog, "path")->isEnabled());  // the inputs wait while it runs
    QVERIFY(!child<QPushButton>(dialog, "export")->isEnabled());
    QPushButton* cancel = child<QPushButton>(dialog, "close");
    QCOMPARE(cancel->text(), QStringLiteral("Cancel"));
    QTest::mouseClick(cancel, Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(child<QLabel>(dialog, "result")->text(), QStringLiteral("Cancelled; nothing written."), 30000);
    QVERIFY(dialog.isVisible());  // the first Cancel stops the export, not the dialog
    QVERIFY(dialog.writtenPath().isEmpty());
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList());
    QTest::mouseClick(child<QPushButton>(dialog, "close"), Qt::LeftButton);
    QVERIFY(!dialog.isVisible());
}

void TestAnimationDialog::formatFollowsTheSuffix()
{
    app::AnimationDialog dialog(stirred());
    dialog.show();
    QLineEdit* path = child<QLineEdit>(dialog, "path");
    QPushButton* exportButton = child<QPushButton>(dialog, "export");
    typeInto(path, QStringLiteral("/tmp/a.txt"));
    QVERIFY(!exportButton->isEnabled());
    QVERIFY(child<QLabel>(dialog, "format")->text().contains(QStringLiteral(".json, .svg, .pdf, .mp4 or .gif")));
    typeInto(path, QStringLiteral("/tmp/a.mp4"));
    QVERIFY(exportButton->isEnabled());
    QVERIFY(!child<QCheckBox>(dialog, "transparent")->isEnabled());
    typeInto(path, QStringLiteral("/tmp/a.gif"));
    QVERIFY(child<QCheckBox>(dialog, "transparent")->isEnabled());
    typeInto(child<QDoubleSpinBox>(dialog, "end"), QStringLiteral("0"));  // an empty range
    QVERIFY(!exportButton->isEnabled());
}

QTEST_MAIN(TestAnimationDialog)
#include "tst_animationdialog.moc"
