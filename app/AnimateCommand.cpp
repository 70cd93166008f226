// `vectorfluid animate SCENE --out FILE ...`: play a scene headless and write a time range of it as
// an animation (docs/command-line.md, docs/animation.md).
#include "app/Backend.h"
#include "app/CommandLine.h"
#include "app/Commands.h"
#include "app/MemoryBudget.h"
#include "app/RenderOptions.h"
#include "app/RenderProgress.h"
#include "app/RenderSignals.h"
#include "model/AtomicFile.h"
#include "model/SceneFile.h"
#include "model/SceneRunner.h"
#include "render/Animation.h"
#include "sim/opencl/OpenClSimulation.h"

#include <QDir>
#include <QFileInfo>
#include <QTextStream>

#include <cmath>
#include <optional>

namespace vf::app {

namespace {

const char* const animateUsage =
    "usage: vectorfluid animate SCENE --out FILE [--start S] [--end S] [--fps N] [--width N]\n"
    "                           [--transparent] [--polyline] [--backend reference|opencl] [--device N]\n"
    "Plays SCENE headless and writes the time from --start to --end as an animation: FILE.json\n"
    "(Lottie), FILE.svg (animated SVG), FILE.mp4 or FILE.gif (video, through ffmpeg).\n";

struct AnimateOptions {
    QString scene;
    QString out;
    double start = 0;
    std::optional<double> end;  // default: the scene's time.steps × time.dt
    double fps = 30;
    QString backend;
    std::optional<int> device;
    render::ExportOptions exportOptions;
};

void addOptions(QCommandLineParser& parser)
{
    parser.addOption({QStringLiteral("out"), QStringLiteral("The animation: .json (Lottie), .svg (animated SVG), .mp4 or .gif."), QStringLiteral("FILE")});
    parser.addOption({QStringLiteral("start"), QStringLiteral("Seconds of scene time where the animation starts (default 0)."), QStringLiteral("S")});
    parser.addOption({QStringLiteral("end"), QStringLiteral("Seconds of scene time where it ends (default: the scene's time.steps x time.dt)."), QStringLiteral("S")});
    parser.addOption({QStringLiteral("fps"), QStringLiteral("Frames per second (default 30)."), QStringLiteral("N")});
    parser.addOption({QStringLiteral("width"), QStringLiteral("Width in points, which Lottie and video take as pixels (default 576)."), QStringLiteral("N")});
    parser.addOption({QStringLiteral("transparent"), QStringLiteral("Leave the background out (not in .mp4).")});
    parser.addOption({QStringLiteral("polyline"), QStringLiteral("Write the vertices as they are, not fitted Béziers.")});
    parser.addOption({QStringLiteral("backend"), QStringLiteral("The simulation backend (default: OpenCL where a device exists)."), QStringLiteral("reference|opencl")});
    parser.addOption({QStringLiteral("device"), QStringLiteral("The OpenCL device, numbered as `vectorfluid devices` lists them."), QStringLiteral("N")});
    parser.addPositionalArgument(QStringLiteral("SCENE"), QStringLiteral("The scene file (.vfscene) to play."));
}

// The options, or nullopt with `error` set to one line.
std::optional<AnimateOptions> animateOptions(const QCommandLineParser& parser, QString& error)
{
    AnimateOptions o;
    const auto value = [&](const char* name) { return parser.value(QLatin1String(name)); };
    const auto isSet = [&](const char* name) { return parser.isSet(QLatin1String(name)); };
    const QStringList scenes = parser.positionalArguments();
    if (scenes.isEmpty())
        error = QStringLiteral("no scene file given");
    else if (scenes.size() > 1)
        error = QStringLiteral("only one scene file may be given (got %1 and %2)").arg(scenes[0], scenes[1]);
    else if (!isSet("out"))
        error = QStringLiteral("no --out FILE given");
    else if (parser.values(QStringLiteral("out")).size() > 1)
        error = QStringLiteral("only one --out may be given");
    else if (!render::isAnimationSuffix(value("out")))
        error = QStringLiteral("--out %1: the format must be .json, .svg, .mp4 or .gif").arg(value("out"));
    if (error.isEmpty() && isSet("start")) {
        bool ok = false;
        o.start = value("start").toDouble(&ok);
        if (!ok || !std::isfinite(o.start) || o.start < 0 || o.start > 1e9)
            error = QStringLiteral("--start: '%1' is not a number in [0, 1e+09]").arg(value("start"));
    }
    if (error.isEmpty() && isSet("end")) {
        double end = 0;
        error = positiveNumber(QStringLiteral("--end"), value("end"), 1e9, end);
        o.end = end;
    }
    if (error.isEmpty() && isSet("fps"))
        error = positiveNumber(QStringLiteral("--fps"), value("fps"), 1000, o.fps);
    if (error.isEmpty() && isSet("width"))
        error = positiveNumber(QStringLiteral("--width"), value("width"), 14400, o.exportOptions.pageWidth);
    if (error.isEmpty() && isSet("backend")) {
        o.backend = value("backend");
        if (o.backend != QLatin1String("reference") && o.backend != QLatin1String("opencl"))
            error = QStringLiteral("--backend: '%1' is not one of reference, opencl").arg(o.backend);
    }
    if (error.isEmpty() && isSet("device")) {
        qint64 device = 0;
        error = wholeNumber(QStringLiteral("--device"), value("device"), 0, 1 << 20, device);
        o.device = int(device);
    }
    if (!error.isEmpty())
        return std::nullopt;
    o.scene = scenes.front();
    o.out = value("out");
    o.exportOptions.background = !isSet("transparent");
    o.exportOptions.bezier = !isSet("polyline");
    o.exportOptions.dpi = 72;  // raster frames: a pixel a point
    return o;
}

} // namespace

int animateCommand(const QStringList& arguments)
{
    CommandLine commandLine(QStringLiteral("vectorfluid animate"), QString::fromLatin1(animateUsage));
    addOptions(commandLine.parser());
    if (const std::optional<int> exitCode = commandLine.parse(arguments))
        return *exitCode;
    QString error;
    const auto options = animateOptions(commandLine.parser(), error);
    if (!options) {
        printError(error);
        return BadInput;
    }
    const model::SceneReadResult read = model::readSceneFile(options->scene);
    if (!read.ok()) {
        printError(read.error);
        return BadInput;
    }
    const double dt = read.scene.time.dt;
    const double end = options->end.value_or(double(read.scene.time.steps) * dt);
    const qint64 frames = std::llround((end - options->start) * options->fps);
    if (frames < 1 || frames > 100'000'000) {
        printError(QStringLiteral("%1 to %2 s at %3 fps is %4 frames (1 to 100000000)")
                       .arg(options->start).arg(end).arg(options->fps).arg(frames));
        return BadInput;
    }
    if (const QString error = checkMemory(read.scene, RenderOptions{}, availableMemory()); !error.isEmpty()) {
        printError(QStringLiteral("%1: %2").arg(options->scene, error));
        return BadInput;
    }
    if (!QFileInfo(options->out).absoluteDir().exists()) {
        printError(QStringLiteral("%1: the folder %2 does not exist").arg(options->out, QFileInfo(options->out).absolutePath()));
        return BadInput;
    }
    if (const QString error = model::checkWritable(options->out); !error.isEmpty()) {
        printError(error);
        return BadInput;
    }
    handleRenderSignals();
    QString notice;
    QString limit;  // the limit that stopped the run, if one did
    int framesDone = 0;
    try {
        model::SceneRunner runner(read.scene, [&](const sim::SimulationSettings& settings) {
            return makeBackend(settings, options->backend, options->device, notice);
        });
        RenderProgress progress(frames, QStringLiteral("frame"));
        // Frame k shows the scene at start + k / fps, to the nearest step.
        const render::Animation animation{int(frames), options->fps, [&](int index) {
            const qint64 steps = std::llround((options->start + index / options->fps) / dt);
            while (runner.stepsDone() < steps && limit.isEmpty() && !interruptRequested()) {
                try {
                    if (runner.step(dt).vertexLimitReached)
                        limit = vertexLimitLabel(runner.simulation()) + QStringLiteral(" reached");
                } catch (const sim::opencl::DeviceError& e) {
                    limit = QString::fromUtf8(e.what()).section('\n', 0, 0);
                }
            }
            return runner.drawing();
        }};
        error = render::exportAnimation(animation, options->out, options->exportOptions, [&](int done) {
            framesDone = done;
            progress.update(done, runner.simulation().vertexCount());
            return limit.isEmpty() && !interruptRequested();
        });
    } catch (const std::exception& e) {
        error = QStringLiteral("%1: %2").arg(options->scene, QString::fromUtf8(e.what()));
    }
    if (!limit.isEmpty()) {
        printError(QStringLiteral("%1: %2 at frame %3 of %4; no output written").arg(options->scene, limit).arg(framesDone).arg(frames));
        return LimitHit;
    }
    if (interruptRequested()) {
        printError(QStringLiteral("%1: interrupted at frame %2 of %3; no output written").arg(options->scene).arg(framesDone).arg(frames));
        return Interrupted;
    }
    if (!error.isEmpty()) {
        printError(error);
        return BadInput;
    }
    if (!notice.isEmpty())
        printError(notice);
    QTextStream(stdout) << "wrote " << options->out << '\n';
    return Done;
}

} // namespace vf::app
