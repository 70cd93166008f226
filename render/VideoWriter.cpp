// Video through the ffmpeg command-line tool: each frame is painted as the PNG export paints it
// (paintedImage) and piped to ffmpeg as raw RGBA; ffmpeg encodes into a temporary folder and the
// finished file is copied into the caller's (atomic) output. MP4 is H.264 in yuv420p, which every
// player takes, cropped to even sides as yuv420p needs; GIF gets a palette made from all its frames
// (palettegen, paletteuse without dithering, which keeps flat ink flat), transparent where the
// frames are.
#include "render/AnimationWriters.h"

#include "model/AtomicFile.h"
#include "render/Writers.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>

namespace vf::render {
namespace {

// How long ffmpeg may take to take a frame or to finish the file.
constexpr int kFrameTimeoutMs = 60'000;
constexpr int kFinishTimeoutMs = 600'000;

QStringList encoderArguments(bool gif)
{
    if (gif)
        return {QStringLiteral("-filter_complex"),
                QStringLiteral("[0:v]split[a][b];[a]palettegen=reserve_transparent=1:stats_mode=full[p];"
                               "[b][p]paletteuse=dither=none"),
                QStringLiteral("-loop"), QStringLiteral("0")};
    return {QStringLiteral("-vf"), QStringLiteral("crop=trunc(iw/2)*2:trunc(ih/2)*2"), QStringLiteral("-c:v"),
            QStringLiteral("libx264"), QStringLiteral("-pix_fmt"), QStringLiteral("yuv420p"),
            QStringLiteral("-movflags"), QStringLiteral("+faststart")};
}

// ffmpeg's last line on stderr: with -loglevel error, what went wrong.
QString lastLine(QProcess& process)
{
    const QList<QByteArray> lines = process.readAllStandardError().trimmed().split('\n');
    return QString::fromLocal8Bit(lines.back()).trimmed();
}

QString ffmpegFailure(QProcess& process)
{
    if (process.error() == QProcess::FailedToStart)
        return QStringLiteral("ffmpeg could not be started: %1").arg(process.errorString());
    const QString line = lastLine(process);
    return QStringLiteral("ffmpeg failed%1").arg(line.isEmpty() ? QString() : QStringLiteral(": ") + line);
}

QString writeVideo(const Animation& animation, const ExportOptions& options, const AnimationProgress& progress,
                   QIODevice& out, bool gif)
{
    const QString ffmpeg = ffmpegProgram();  // exportAnimation checked that there is one
    QTemporaryDir folder;
    if (!folder.isValid())
        return QStringLiteral("cannot create a temporary folder: %1").arg(folder.errorString());
    const QString video = folder.filePath(gif ? QStringLiteral("video.gif") : QStringLiteral("video.mp4"));
    QProcess process;
    process.setStandardOutputFile(QProcess::nullDevice());
    bool started = false;
    const QString error = forEachFrame(animation, options, progress, [&](int, const model::Drawing& frame) {
        const QImage image = paintedImage(frame, options).convertToFormat(QImage::Format_RGBA8888);
        if (image.isNull())
            return QStringLiteral("a frame is too large to allocate (%1 dpi)").arg(options.dpi);
        if (!started) {
            process.start(ffmpeg, QStringList{QStringLiteral("-nostdin"), QStringLiteral("-loglevel"), QStringLiteral("error"),
                                              QStringLiteral("-f"), QStringLiteral("rawvideo"), QStringLiteral("-pix_fmt"),
                                              QStringLiteral("rgba"), QStringLiteral("-s"),
                                              QStringLiteral("%1x%2").arg(image.width()).arg(image.height()),
                                              QStringLiteral("-framerate"), QString::number(animation.fps, 'g', 9),
                                              QStringLiteral("-i"), QStringLiteral("-")}
                                      + encoderArguments(gif) + QStringList{QStringLiteral("-y"), video});
            if (!process.waitForStarted())
                return ffmpegFailure(process);
            started = true;
        }
        for (int y = 0; y < image.height(); ++y) {  // rows without the padding a QImage may have
            const char* row = reinterpret_cast<const char*>(image.constScanLine(y));
            if (process.write(row, qint64(image.width()) * 4) < 0)
                return ffmpegFailure(process);
        }
        while (process.bytesToWrite() > 0) {
            if (!process.waitForBytesWritten(kFrameTimeoutMs))
                return ffmpegFailure(process);
        }
        return QString();
    });
    if (!error.isEmpty()) {
        process.kill();
        process.waitForFinished();
        return error;
    }
    process.closeWriteChannel();
    if (!process.waitForFinished(kFinishTimeoutMs) || process.exitStatus() != QProcess::NormalExit
        || process.exitCode() != 0)
        return ffmpegFailure(process);
    QFile file(video);
    if (!file.open(QIODevice::ReadOnly))
        return QStringLiteral("ffmpeg wrote no video: %1").arg(file.errorString());
    return model::writeAll(out, file.readAll());
}

} // namespace

QString ffmpegProgram()
{
    return QStandardPaths::findExecutable(QStringLiteral("ffmpeg"));
}

QString writeMp4(const Animation& animation, const ExportOptions& options, const AnimationProgress& progress,
                 QIODevice& out)
{
    return writeVideo(animation, options, progress, out, false);
}

QString writeGif(const Animation& animation, const ExportOptions& options, const AnimationProgress& progress,
                 QIODevice& out)
{
    return writeVideo(animation, options, progress, out, true);
}

} // namespace vf::render
