#include "render/Animation.h"

#include "model/AtomicFile.h"
#include "render/AnimationWriters.h"
#include "render/Writers.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <array>
#include <cmath>

namespace vf::render {
namespace {

using Writer = QString (*)(const Animation&, const ExportOptions&, const AnimationProgress&, QIODevice&);

struct Format {
    const char* suffix;  // lower case, without the dot
    Writer write;
    bool transparency;   // can leave the background out
    bool ffmpeg;         // runs the ffmpeg program
};

constexpr std::array kFormats{
    Format{"json", writeLottie, true, false},
    Format{"svg", writeAnimatedSvg, true, false},
    Format{"pdf", writePdfPages, true, false},
    Format{"mp4", writeMp4, false, true},
    Format{"gif", writeGif, true, true},
};

const Format* formatFor(const QString& path) { return formatBySuffix(kFormats, path); }

// Beyond this many frames a frame number no longer fits the formats' integers comfortably, and
// no animation of this tool needs them (a day at 60 fps is 5,184,000).
constexpr int kMaxFrames = 100'000'000;

QString checkAnimation(const Animation& animation)
{
    if (animation.frames < 1 || animation.frames > kMaxFrames)
        return QStringLiteral("the animation has %1 frames (1 to %2)").arg(animation.frames).arg(kMaxFrames);
    if (!std::isfinite(animation.fps) || animation.fps <= 0 || animation.fps > 1000)
        return QStringLiteral("%1 frames per second is not in (0, 1000]").arg(animation.fps);
    if (!animation.frame)
        return QStringLiteral("the animation has no frames");
    return {};
}

} // namespace

QString forEachFrame(const Animation& animation, const ExportOptions& options, const AnimationProgress& progress,
                     const FrameWriter& write)
{
    double width = 0, height = 0;
    for (int index = 0; index < animation.frames; ++index) {
        const model::Drawing frame = animation.frame(index);
        if (QString error = checkExport(frame, options); !error.isEmpty())
            return QStringLiteral("frame %1: %2").arg(index).arg(error);
        if (index == 0) {
            width = frame.width;
            height = frame.height;
        } else if (frame.width != width || frame.height != height) {
            return QStringLiteral("frame %1: the canvas is %2 x %3, the first frame's %4 x %5")
                .arg(index).arg(frame.width).arg(frame.height).arg(width).arg(height);
        }
        if (QString error = write(index, frame); !error.isEmpty())
            return error;
        if (progress && !progress(index + 1))
            return QStringLiteral("cancelled");
    }
    return {};
}

QString exportAnimation(const Animation& animation, const QString& path, const ExportOptions& options,
                        const AnimationProgress& progress)
{
    const Format* format = formatFor(path);
    if (!format)
        return path + QStringLiteral(": unknown animation format (use .json, .svg, .pdf, .mp4 or .gif)");
    if (const QString error = checkAnimation(animation); !error.isEmpty())
        return path + QStringLiteral(": ") + error;
    if (!options.background && !format->transparency)
        return path + QStringLiteral(": %1 has no transparency; leave the background in")
                          .arg(QString::fromLatin1(format->suffix).toUpper());
    if (format->ffmpeg && ffmpegProgram().isEmpty())  // before any frame is played
        return path + QStringLiteral(": ffmpeg is not installed (not found on PATH); .mp4 and .gif need it");
    return model::saveAtomically(path, [&](QIODevice& file) {
        return format->write(animation, options, progress, file);
    });
}

QString framePath(const QString& folder, qint64 index, qint64 last, const QString& suffix)
{
    const int digits = std::max<int>(6, QString::number(last).size());
    return QDir(folder).filePath(QStringLiteral("frame-%1.%2").arg(index, digits, 10, QLatin1Char('0')).arg(suffix));
}

QString exportFrames(const Animation& animation, const QString& folder, const QString& suffix,
                     const ExportOptions& options, const AnimationProgress& progress)
{
    if (!isExportSuffix(QStringLiteral("frame.") + suffix))
        return QStringLiteral("%1: unknown frame format %2 (use svg, pdf, eps or png)").arg(folder, suffix);
    if (const QString error = checkAnimation(animation); !error.isEmpty())
        return folder + QStringLiteral(": ") + error;
    const QString error = forEachFrame(animation, options, progress, [&](int index, const model::Drawing& frame) {
        return exportDrawing(frame, framePath(folder, index, animation.frames - 1, suffix), options);
    });
    return error == QLatin1String("cancelled") ? folder + QStringLiteral(": cancelled") : error;
}

bool isAnimationSuffix(const QString& path)
{
    return formatFor(path) != nullptr;
}

} // namespace vf::render
