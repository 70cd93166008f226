#pragma once
// The format writers behind exportAnimation, and the frame loop they share. Each writes one whole
// file into `out` and returns an empty string, "cancelled", or what went wrong (without the path).
#include "render/Animation.h"

#include <QIODevice>

namespace vf::render {

// Called with each frame, in order, once it has been checked.
using FrameWriter = std::function<QString(int index, const model::Drawing& frame)>;

// Asks the animation for every frame in order, checks each (as a still export would, and that its
// canvas has the first frame's size), hands it to `write`, then reports progress. Stops at the
// first error or when the progress cancels.
[[nodiscard]] QString forEachFrame(const Animation& animation, const ExportOptions& options,
                                   const AnimationProgress& progress, const FrameWriter& write);

[[nodiscard]] QString writeLottie(const Animation& animation, const ExportOptions& options,
                                  const AnimationProgress& progress, QIODevice& out);
[[nodiscard]] QString writeAnimatedSvg(const Animation& animation, const ExportOptions& options,
                                       const AnimationProgress& progress, QIODevice& out);

// A page a frame (render/CairoWriter.cpp).
[[nodiscard]] QString writePdfPages(const Animation& animation, const ExportOptions& options,
                                    const AnimationProgress& progress, QIODevice& out);
// Video through the ffmpeg command-line tool (render/VideoWriter.cpp).
[[nodiscard]] QString writeMp4(const Animation& animation, const ExportOptions& options,
                               const AnimationProgress& progress, QIODevice& out);
[[nodiscard]] QString writeGif(const Animation& animation, const ExportOptions& options,
                               const AnimationProgress& progress, QIODevice& out);
// The ffmpeg program on PATH, or an empty string.
QString ffmpegProgram();

} // namespace vf::render
