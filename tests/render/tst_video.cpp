// Video through ffmpeg: ffprobe reads the MP4 as H.264 in yuv420p with every frame, the right
// duration and even sides; the GIF has every frame, its first decodes to our PNG render of the first
// frame (GIF's palette allows a wider tolerance), and a transparent GIF is clear where no ink is.
#include "AnimationScene.h"
#include "ExternalTools.h"
#include "FrameCompare.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace vf;

namespace {

constexpr int kFrames = 6;

render::ExportOptions frameOptions()
{
    render::ExportOptions options;
    options.pageWidth = 251;  // an odd width: H.264 in yuv420p needs even sides
    options.dpi = 72;
    return options;
}

// ffprobe's view of the first video stream: codec_name, pix_fmt, width, height, nb_read_frames,
// and the container's duration.
QJsonObject probe(const QString& ffprobe, const QString& path)
{
    const Run r = run(ffprobe, {QStringLiteral("-v"), QStringLiteral("error"), QStringLiteral("-count_frames"),
                                QStringLiteral("-select_streams"), QStringLiteral("v:0"), QStringLiteral("-show_entries"),
                                QStringLiteral("stream=codec_name,pix_fmt,width,height,nb_read_frames:format=duration"),
                                QStringLiteral("-of"), QStringLiteral("json"), path});
    if (r.exitCode != 0)
        return {};
    const QJsonObject root = QJsonDocument::fromJson(r.output).object();
    QJsonObject stream = root[QLatin1String("streams")].toArray().first().toObject();
    stream[QLatin1String("duration")] = root[QLatin1String("format")].toObject()[QLatin1String("duration")];
    return stream;
}

} // namespace

class TestVideo : public QObject {
    Q_OBJECT

private slots:
    void mp4();
    void gif();
    void transparentGif();
    void mp4HasNoTransparency();
};

void TestVideo::mp4()
{
    REQUIRE_TOOL(ffprobe, "ffprobe");
    model::SceneRunner runner(test::animationScene());
    std::vector<model::Drawing> frames;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ink.mp4"));
    QCOMPARE(render::exportAnimation(test::recordedAnimation(runner, kFrames, frames), path, frameOptions()), QString());
    const QJsonObject video = probe(ffprobe, path);
    QCOMPARE(video[QLatin1String("codec_name")].toString(), QStringLiteral("h264"));
    QCOMPARE(video[QLatin1String("pix_fmt")].toString(), QStringLiteral("yuv420p"));
    QCOMPARE(video[QLatin1String("width")].toInt(), 250);
    QCOMPARE(video[QLatin1String("height")].toInt(), 200);
    QCOMPARE(video[QLatin1String("nb_read_frames")].toString(), QString::number(kFrames));
    QCOMPARE(video[QLatin1String("duration")].toString().toDouble(), kFrames / 30.0);
}

void TestVideo::gif()
{
    REQUIRE_TOOL(ffprobe, "ffprobe");
    REQUIRE_TOOL(ffmpeg, "ffmpeg");
    model::SceneRunner runner(test::animationScene());
    std::vector<model::Drawing> frames;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ink.gif"));
    QCOMPARE(render::exportAnimation(test::recordedAnimation(runner, kFrames, frames), path, frameOptions()), QString());
    const QJsonObject video = probe(ffprobe, path);
    QCOMPARE(video[QLatin1String("codec_name")].toString(), QStringLiteral("gif"));
    QCOMPARE(video[QLatin1String("width")].toInt(), 251);
    QCOMPARE(video[QLatin1String("nb_read_frames")].toString(), QString::number(kFrames));

    const QString first = dir.filePath(QStringLiteral("first.png"));
    const Run decoded = run(ffmpeg, {QStringLiteral("-loglevel"), QStringLiteral("error"), QStringLiteral("-i"), path,
                                     QStringLiteral("-frames:v"), QStringLiteral("1"), first});
    QVERIFY2(decoded.exitCode == 0, decoded.output.constData());
    const double agree = test::agreement(test::ourRender(frames.front(), frameOptions()), QImage(first), 40);
    qInfo("the GIF's first frame and ours: %.2f%% of pixels agree", 100 * agree);
    QVERIFY(agree >= 0.98);
    QVERIFY(test::agreement(test::ourRender(frames.back(), frameOptions()), QImage(first), 40) < 0.98);
}

void TestVideo::transparentGif()
{
    REQUIRE_TOOL(ffmpeg, "ffmpeg");
    model::SceneRunner runner(test::animationScene());
    std::vector<model::Drawing> frames;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("clear.gif"));
    render::ExportOptions options = frameOptions();
    options.background = false;
    QCOMPARE(render::exportAnimation(test::recordedAnimation(runner, 2, frames), path, options), QString());
    const QString first = dir.filePath(QStringLiteral("first.png"));
    const Run decoded = run(ffmpeg, {QStringLiteral("-loglevel"), QStringLiteral("error"), QStringLiteral("-i"), path,
                                     QStringLiteral("-frames:v"), QStringLiteral("1"), first});
    QVERIFY2(decoded.exitCode == 0, decoded.output.constData());
    const QImage image = QImage(first).convertToFormat(QImage::Format_ARGB32);
    QCOMPARE(qAlpha(image.pixel(3, 3)), 0);        // no ink in the corner
    QCOMPARE(qAlpha(image.pixel(100, 100)), 255);  // the ink disc, 0.4 x 0.4 of the canvas
}

void TestVideo::mp4HasNoTransparency()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("clear.mp4"));
    render::ExportOptions options = frameOptions();
    options.background = false;
    model::Drawing empty;
    QCOMPARE(render::exportAnimation({1, 30.0, [&](int) { return empty; }}, path, options),
             path + QStringLiteral(": MP4 has no transparency; leave the background in"));
    QVERIFY(!QFile::exists(path));
}

QTEST_GUILESS_MAIN(TestVideo)
#include "tst_video.moc"
