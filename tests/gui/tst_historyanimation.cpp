// File ▸ Export Animation…, "The history, as it was made", through the real window: a drop clicked
// and a stroke dragged on the canvas, with single steps (the . key) before, between and after, are
// played again at the steps they came. The replay takes as many steps as the document did since it
// was opened and ends in the live state exactly (both run the reference backend, which is
// deterministic), and the Lottie file the dialog writes has a frame per step. Saved and opened
// again, the project plays its history from the first opening on, through what was done after.
#include "FindChild.h"
#include "WindowTest.h"
#include "app/AnimationDialog.h"
#include "app/MainWindow.h"
#include "model/ProjectFile.h"
#include "model/SceneFile.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>

using namespace vf;
using namespace vf::app;

// The window shown with `path` open and paused; any report fails the test.
bool showPaused(MainWindow& w, const QString& path)
{
    w.setReport([](const QString&, const QString& text) { QFAIL(qPrintable(text)); });
    if (!test::showActive(w) || !w.openFile(path))
        return false;
    w.simulation().setPlaying(false);
    return true;
}

// The document's history played again through all its spans.
struct Replayed {
    int unrecorded = -1;     // commands whose span the journal does not hold
    std::int64_t steps = 0;  // the spans' steps, all played
    int regions = 0;         // at the end
    bool endsLive = false;   // in the live state, bit for bit
};

Replayed replayHistory(MainWindow& w)
{
    const model::ProjectDraft draft = w.document().draftProject();
    Replayed replayed;
    const std::vector<model::ReplaySpan> spans = draft.replaySpans(&replayed.unrecorded);
    for (const model::ReplaySpan& span : spans)
        replayed.steps += span.steps;
    model::HistoryReplay replay(draft.scene(), spans);
    for (std::int64_t k = 0; k < replayed.steps; ++k)
        replay.step();
    replayed.regions = replay.simulation().regionCount();
    replayed.endsLive = replay.simulation().snapshot() == draft.finish().state;
    return replayed;
}

class TestHistoryAnimation : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        test::useTestSettings("tst_historyanimation", m_dir);
        model::Scene scene;
        scene.flow.gridX = scene.flow.gridY = 32;
        scene.time.dt = 0.01;
        scene.tracking.maxSpacing = 0.01;
        scene.regions.push_back({QStringLiteral("ink"), QColor(0x1d, 0x35, 0x57), true, model::CircleShape{{0.5, 0.5}, 0.2}});
        m_scenePath = m_dir.filePath(QStringLiteral("small.vfscene"));
        QCOMPARE(model::writeSceneFile(scene, m_scenePath), QString());
    }

    void historyIsPlayedAgainAsItWasMade()
    {
        MainWindow w;
        QVERIFY(showPaused(w, m_scenePath));
        Canvas& canvas = w.canvas();
        const auto at = [&canvas](double x, double y) { return canvas.mapFromCanvas({x, y}).toPoint(); };

        QTest::keyClick(&w, Qt::Key_Period);
        QTest::keyClick(&w, Qt::Key_D);
        QTest::mouseClick(&canvas, Qt::LeftButton, {}, at(0.25, 0.3));
        for (int k = 0; k < 3; ++k)
            QTest::keyClick(&w, Qt::Key_Period);
        QTest::keyClick(&w, Qt::Key_S);
        QTest::mousePress(&canvas, Qt::LeftButton, {}, at(0.15, 0.6));
        for (int i = 1; i <= 8; ++i) {
            QTest::qWait(20);  // the water runs while the pen is down
            QTest::mouseMove(&canvas, at(0.15 + 0.08 * i, 0.6), 20);
        }
        QTest::mouseRelease(&canvas, Qt::LeftButton, {}, at(0.79, 0.6), 20);
        QTest::keyClick(&w, Qt::Key_Period);
        w.simulation().sync();
        const std::int64_t steps = w.simulation().frame()->steps;

        const Replayed replayed = replayHistory(w);
        QCOMPARE(replayed.unrecorded, 0);
        QCOMPARE(replayed.steps, steps);
        QVERIFY2(steps > 6, qPrintable(QString::number(steps)));  // the stroke's steps too
        QCOMPARE(replayed.regions, 2);
        QVERIFY(replayed.endsLive);

        const QString json = m_dir.filePath(QStringLiteral("history.json"));
        test::whenModal<AnimationDialog>([json](AnimationDialog* dialog) {
            auto* source = test::child<QComboBox>(*dialog, "source");
            source->setFocus();
            QTest::keyClick(source, Qt::Key_Down);  // the history
            test::child<QLineEdit>(*dialog, "path")->setText(json);
            test::child<QSpinBox>(*dialog, "fps")->setValue(100);  // a frame a step
            QTest::mouseClick(test::child<QPushButton>(*dialog, "export"), Qt::LeftButton);
            static_cast<void>(QTest::qWaitFor([dialog] { return !dialog->running(); }, 30000));  // checked below
            QTest::mouseClick(test::child<QPushButton>(*dialog, "close"), Qt::LeftButton);
        });
        test::clickFileMenuItem(w, QStringLiteral("Export &Animation"));
        QFile written(json);
        QVERIFY(written.open(QIODevice::ReadOnly));
        const QJsonObject lottie = QJsonDocument::fromJson(written.readAll()).object();
        QCOMPARE(lottie[QLatin1String("op")].toInt(), int(steps));
        QStringList layers;
        for (const QJsonValue& layer : lottie[QLatin1String("layers")].toArray())
            layers << layer[QLatin1String("nm")].toString();
        QVERIFY2(layers.contains(QStringLiteral("ink")) && layers.filter(QStringLiteral("drop")).size() == 1,
                 qPrintable(layers.join(u", ")));  // the scene's ink and the drop
        w.document().undoStack().setClean();  // no prompt on close
    }

    // The journal goes into the project file: a drop before saving and one after opening it again,
    // with steps around both, play again from the scene's opening to now, ending in the live state.
    void historyPlaysAgainAfterTheProjectIsOpened()
    {
        MainWindow w;
        QVERIFY(showPaused(w, m_scenePath));
        Canvas& canvas = w.canvas();
        const auto dropAt = [&](double x, double y) {
            QTest::keyClick(&w, Qt::Key_D);
            QTest::mouseClick(&canvas, Qt::LeftButton, {}, canvas.mapFromCanvas({x, y}).toPoint());
        };
        QTest::keyClick(&w, Qt::Key_Period);
        dropAt(0.25, 0.3);
        QTest::keyClick(&w, Qt::Key_Period);
        QTest::keyClick(&w, Qt::Key_Period);
        const QString project = m_dir.filePath(QStringLiteral("two drops.vfproj"));
        QCOMPARE(model::writeProjectFile(w.document().draftProject().finish(), project), QString());

        QVERIFY(showPaused(w, project));
        QTest::keyClick(&w, Qt::Key_Period);
        dropAt(0.7, 0.7);
        QTest::keyClick(&w, Qt::Key_Period);
        w.simulation().sync();

        const Replayed replayed = replayHistory(w);
        QCOMPARE(replayed.unrecorded, 0);
        QCOMPARE(replayed.steps, std::int64_t(5));  // three before saving, two after opening
        QCOMPARE(replayed.regions, 3);
        QVERIFY(replayed.endsLive);
        w.document().undoStack().setClean();
    }

private:
    QTemporaryDir m_dir;
    QString m_scenePath;
};

QTEST_MAIN(TestHistoryAnimation)
#include "tst_historyanimation.moc"
