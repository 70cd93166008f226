#pragma once
// Animation exports: a sequence of frames written as one file, the format following the suffix:
// .json (Lottie), .svg (animated SVG, SMIL), .pdf (a page a frame), .mp4 (H.264) or .gif, the
// videos through the ffmpeg command-line tool; or each frame a still file of its own.
#include "model/Drawing.h"
#include "render/Exporter.h"

#include <QString>

#include <functional>

namespace vf::render {

// Frame `index` of the animation. Writers ask for the frames in order, each once, so a source may
// play a simulation forward and hand out its picture; no writer keeps the frames' geometry.
using FrameSource = std::function<model::Drawing(int index)>;

struct Animation {
    int frames = 0;     // at least 1
    double fps = 30.0;  // frames per second
    FrameSource frame;
};

// Called after each frame is written with the count done so far; returning false cancels the
// export, which then writes nothing and returns "path: cancelled".
using AnimationProgress = std::function<bool(int framesDone)>;

// Writes the animation to `path` atomically (model::saveAtomically). `options` as for a still
// export: the page size (Lottie's width and height in pixels are its points), the Bézier fit,
// `dpi` for video, `background` false for a transparent background (not in MP4).
// Every frame must have the first frame's canvas size. Returns an empty string, or one line
// "path: what went wrong".
[[nodiscard]] QString exportAnimation(const Animation& animation, const QString& path, const ExportOptions& options,
                                      const AnimationProgress& progress = {});

bool isAnimationSuffix(const QString& path);

// FOLDER/frame-NNNNNN.SUFFIX: the index padded to six digits, or to the width of `last`, so the
// names sort in order.
QString framePath(const QString& folder, qint64 index, qint64 last, const QString& suffix);

// Each frame written as a still (exportDrawing) to framePath(folder, index, frames - 1, suffix),
// `suffix` one of svg, pdf, eps, png. Each file is atomic and written as its frame comes, so an
// export that fails or is cancelled part-way leaves the frames done before. Returns an empty
// string, or one line "path: what went wrong" ("folder: cancelled").
[[nodiscard]] QString exportFrames(const Animation& animation, const QString& folder, const QString& suffix,
                                   const ExportOptions& options, const AnimationProgress& progress = {});

} // namespace vf::render
