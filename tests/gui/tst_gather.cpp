// Tools ▸ Gather Into… in the main window, by keys: Ctrl+Shift+G opens the dialog, which outlines the
// text typed and refuses blank text; OK gathers the ink into it while the simulation plays, one step
// of the history, and the undo key takes it back. The drops beside the word's letter move toward it.
// The Gathering box sets the drive's gathering term.
#include "FindChild.h"
#include "WindowTest.h"
#include "app/GatherDialog.h"
#include "app/MainWindow.h"
#include "app/SimulationController.h"
#include "model/SceneFile.h"
#include "sim/Coverage.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTest>

using namespace vf;
using namespace vf::app;

namespace {

// Drops left and right of the middle, where a fitted "I" stands, in water that flows.
model::Scene dropsBesideTheMiddle()
{
    model::Scene scene;
    scene.time.dt = 0.01;
    scene.tracking.maxSpacing = 0.008;
    int k = 0;
    for (const double x : {0.3, 0.7})
        for (const double y : {0.35, 0.5, 0.65})
            scene.regions.push_back({QStringLiteral("drop %1").arg(++k), QColor(0xe7, 0x6f, 0x51), true,
                                     model::CircleShape{{x, y}, 0.05}});
    return scene;
}

double overlapWithI(MainWindow& w)
{
    w.simulation().sync();
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setBold(true);
    return sim::intersectionOverUnion(w.simulation().frame()->regions, fittedText(QStringLiteral("I"), font, {}),
                                      {256, 256, 1.0, 1.0});
}

} // namespace

class TestGather : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        test::useTestSettings("tst_gather", m_dir);
        m_scenePath = m_dir.filePath(QStringLiteral("drops.vfscene"));
        QCOMPARE(model::writeSceneFile(dropsBesideTheMiddle(), m_scenePath), QString());
    }

    void blankTextIsRefusedInTheDialog()
    {
        MainWindow w;
        QVERIFY(test::showActive(w));
        QVERIFY(w.openFile(m_scenePath));
        QString summary;
        bool okEnabled = true;
        test::whenModal<GatherDialog>([&](GatherDialog* dialog) {
            auto* text = test::child<QLineEdit>(*dialog, "gatherText");
            text->setFocus();
            QTest::keyClick(text, Qt::Key_A, Qt::ControlModifier);
            QTest::keyClick(text, Qt::Key_Space);
            summary = test::child<QLabel>(*dialog, "gatherSummary")->text();
            okEnabled = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->isEnabled();
            QTest::keyClick(dialog, Qt::Key_Escape);
        });
        QTest::keyClick(&w, Qt::Key_G, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(!okEnabled);
        QCOMPARE(summary, QStringLiteral("Type the text to gather into."));
        QCOMPARE(w.document().undoStack().count(), 0);
    }

    // The Gathering box, typed into, sets the gathering term of the drive the dialog gives.
    void gatheringIsTypedInTheDialog()
    {
        MainWindow w;
        QVERIFY(test::showActive(w));
        QVERIFY(w.openFile(m_scenePath));
        double before = -1.0, typed = -1.0;
        test::whenModal<GatherDialog>([&](GatherDialog* dialog) {
            before = dialog->choice().drive.gathering;
            auto* box = test::child<QDoubleSpinBox>(*dialog, "gatherGathering");
            box->setFocus();
            box->selectAll();
            QTest::keyClicks(box, QStringLiteral("12"));
            typed = dialog->choice().drive.gathering;
            QTest::keyClick(dialog, Qt::Key_Escape);
        });
        QTest::keyClick(&w, Qt::Key_G, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(before, sim::TargetDriveSettings{}.gathering);
        QCOMPARE(typed, 12.0);
    }

    void gatherIntoTextIsOneStepThatPlays()
    {
        MainWindow w;
        QVERIFY(test::showActive(w));
        QVERIFY(w.openFile(m_scenePath));
        w.simulation().setPlaying(false);
        const double before = overlapWithI(w);
        QString summary;
        test::whenModal<GatherDialog>([&](GatherDialog* dialog) {
            auto* text = test::child<QLineEdit>(*dialog, "gatherText");
            text->setFocus();
            QTest::keyClick(text, Qt::Key_A, Qt::ControlModifier);
            QTest::keyClicks(text, QStringLiteral("I"));
            summary = test::child<QLabel>(*dialog, "gatherSummary")->text();
            QTest::keyClick(dialog, Qt::Key_Return);
        });
        QTest::keyClick(&w, Qt::Key_G, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY2(summary.startsWith(QStringLiteral("The fluid draws the ink into I for 6 s")), qPrintable(summary));
        QUndoStack& history = w.document().undoStack();
        QCOMPARE(history.count(), 1);
        QCOMPARE(history.text(0), QStringLiteral("Gather into I"));
        QVERIFY(w.findChild<QAction*>(QStringLiteral("play"))->isChecked());
        // A second of simulated time, played in real time.
        QTRY_VERIFY_WITH_TIMEOUT((w.simulation().sync(), w.simulation().frame()->time > 1.0), 60000);
        w.findChild<QAction*>(QStringLiteral("play"))->setChecked(false);
        const double after = overlapWithI(w);
        qInfo("overlap with the I: %.3f before, %.3f after a second", before, after);
        QVERIFY2(after > before + 0.05, qPrintable(QString("%1 -> %2").arg(before).arg(after)));

        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTest::keyClick(&w, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(history.index(), 0);
        QCOMPARE(overlapWithI(w), before);
        history.setClean();
    }

private:
    QTemporaryDir m_dir;
    QString m_scenePath;
};

QTEST_MAIN(TestGather)
#include "tst_gather.moc"
