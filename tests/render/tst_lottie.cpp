// Lottie export played by a real player: Debian's librlottie renders the file frame by frame, and
// each frame must agree with our own PNG render of the same frame (render/PngWriter) on at least
// 98% of its pixels. The frames come from a small scene played by model::SceneRunner, with a drop
// landing part-way (a layer that starts later, vertex counts that change) in a translucent colour
// on another region, which shows through it. Regions with holes are filled even-odd: a ring whose
// two contours wind the same way must show the background in its hole.
#include "render/Animation.h"
#include "render/Writers.h"
#include "AnimationScene.h"
#include "FrameCompare.h"
#include "TestGeometry.h"

#include <rlottie.h>

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

using namespace vf;

namespace {

constexpr int kFrames = 6;

render::ExportOptions frameOptions()
{
    render::ExportOptions options;
    options.pageWidth = 250;  // Lottie pixels; PNG at 72 dpi has the same
    options.dpi = 72;
    return options;
}

QImage playerRender(rlottie::Animation& player, int frame)
{
    std::size_t width = 0, height = 0;
    player.size(width, height);
    QImage image(int(width), int(height), QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    rlottie::Surface surface(reinterpret_cast<std::uint32_t*>(image.bits()), width, height,
                             std::size_t(image.bytesPerLine()));
    player.renderSync(std::size_t(frame), surface);
    return image.convertToFormat(QImage::Format_ARGB32);
}

std::unique_ptr<rlottie::Animation> load(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return rlottie::Animation::loadFromData(file.readAll().toStdString(), path.toStdString(), "", false);
}

} // namespace

class TestLottie : public QObject {
    Q_OBJECT

private slots:
    void rlottiePlaysTheFramesAsWeRenderThem();
    void evenOddHoleShowsWhatIsBelow();
    void cancelledExportWritesNothing();
};

void TestLottie::rlottiePlaysTheFramesAsWeRenderThem()
{
    model::SceneRunner runner(test::animationScene());
    std::vector<model::Drawing> frames;
    const render::Animation animation = test::recordedAnimation(runner, kFrames, frames);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ink.json"));
    QCOMPARE(render::exportAnimation(animation, path, frameOptions()), QString());

    // The drop lands at frame 2: its layer starts there, and the flow changed the vertices.
    QCOMPARE(frames.front().regions.size(), std::size_t(1));
    QCOMPARE(frames.back().regions.size(), std::size_t(2));
    QVERIFY(frames.back().regions[0].contours.front().size() != frames.front().regions[0].contours.front().size());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(root[QLatin1String("op")].toInt(), kFrames);
    const QJsonArray layers = root[QLatin1String("layers")].toArray();
    QCOMPARE(layers.size(), 3);  // madder on top, ink, the background
    QCOMPARE(layers[0].toObject()[QLatin1String("nm")].toString(), QStringLiteral("madder"));
    QCOMPARE(layers[0].toObject()[QLatin1String("ip")].toInt(), 2);
    QCOMPARE(layers[1].toObject()[QLatin1String("ip")].toInt(), 0);
    const QJsonObject inkPath = layers[1].toObject()[QLatin1String("shapes")].toArray()[0].toObject();
    const QJsonArray keyframes = inkPath[QLatin1String("ks")].toObject()[QLatin1String("k")].toArray();
    QCOMPARE(keyframes.size(), kFrames);
    for (const QJsonValue& keyframe : keyframes)
        QCOMPARE(keyframe.toObject()[QLatin1String("h")].toInt(), 1);

    const std::unique_ptr<rlottie::Animation> player = load(path);
    QVERIFY(player);
    QCOMPARE(player->totalFrame(), std::size_t(kFrames));
    for (int frame = 0; frame < kFrames; ++frame) {
        const QImage ours = test::ourRender(frames[std::size_t(frame)], frameOptions());
        const QImage played = playerRender(*player, frame);
        const double agree = test::agreement(ours, played);
        qInfo("frame %d: %.2f%% of pixels agree", frame, 100 * agree);
        if (agree < 0.98) {
            ours.save(dir.filePath(QStringLiteral("ours-%1.png").arg(frame)));
            played.save(dir.filePath(QStringLiteral("played-%1.png").arg(frame)));
            dir.setAutoRemove(false);
        }
        QVERIFY2(agree >= 0.98, qPrintable(QStringLiteral("frame %1: %2% agree; images in %3")
                                               .arg(frame).arg(100 * agree).arg(dir.path())));
    }
    // The check can fail: the last frame, played, is not the first one rendered.
    QVERIFY(test::agreement(test::ourRender(frames.front(), frameOptions()), playerRender(*player, kFrames - 1)) < 0.98);
}

// A ring (two contours wound the same way) over the background: the hole must show the background.
void TestLottie::evenOddHoleShowsWhatIsBelow()
{
    model::Drawing ring;
    ring.background = QColor(255, 255, 255);
    ring.regions.push_back({QStringLiteral("ring"), QColor(0, 0, 0), true,
                            {test::circlePolygon({0.5, 0.5}, 0.4, 200), test::circlePolygon({0.5, 0.5}, 0.2, 100)}});
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ring.json"));
    QCOMPARE(render::exportAnimation({1, 24.0, [&](int) { return ring; }}, path, frameOptions()), QString());
    const std::unique_ptr<rlottie::Animation> player = load(path);
    QVERIFY(player);
    const QImage played = playerRender(*player, 0);
    QCOMPARE(played.size(), QSize(250, 250));
    QCOMPARE(played.pixel(125, 125), qRgb(255, 255, 255));  // the hole
    QCOMPARE(played.pixel(125, 45), qRgb(0, 0, 0));         // the ring, 0.3 from the centre
    QCOMPARE(played.pixel(5, 5), qRgb(255, 255, 255));      // outside
    QVERIFY(test::agreement(test::ourRender(ring, frameOptions()), played) >= 0.98);
}

void TestLottie::cancelledExportWritesNothing()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("cancelled.json"));
    model::Drawing empty;
    const QString error = render::exportAnimation({10, 30.0, [&](int) { return empty; }}, path, frameOptions(),
                                                  [](int done) { return done < 3; });
    QCOMPARE(error, path + QStringLiteral(": cancelled"));
    QVERIFY(!QFile::exists(path));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList());
}

QTEST_GUILESS_MAIN(TestLottie)
#include "tst_lottie.moc"
