// `vectorfluid animate SCENE --out FILE ...`: play a scene headless, or a project's history again,
// and write a time range of it as an animation (docs/command-line.md, docs/animation.md).
#include "app/Backend.h"
#include "app/CommandLine.h"
#include "app/Commands.h"
#include "app/MemoryBudget.h"
#include "app/RenderOptions.h"
#include "app/RenderProgress.h"
#include "app/RenderSignals.h"
#include "app/SceneFrames.h"
#include "model/AtomicFile.h"
#include "model/HistoryReplay.h"
#include "model/ProjectFile.h"
#include "model/SceneFile.h"
#include "model/SceneRunner.h"
#include "render/Animation.h"

#include <QDir>
#include <QFileInfo>
#include <QTextStream>

#include <array>
#include <cmath>
#include <optional>

namespace vf::app {

namespace {

const char* const animateUsage =
    "usage: vectorfluid animate SCENE|PROJECT (--out FILE | --frames DIR [--frame-format F]) [--start S]\n"
    "                           [--end S] [--fps N] [--width N] [--transparent] [--polyline]\n"
    "                           [--backend reference|opencl] [--device N]\n"
    "Plays SCENE (.vfscene) headless, or the history of PROJECT (.vfproj) again as it was made, and\n"
    "writes the time from --start to --end as an animation: FILE.json (Lottie), FILE.svg (animated\n"
    "SVG), FILE.pdf (a page a frame), FILE.mp4 or FILE.gif (video, through ffmpeg); or each frame as\n"
    "DIR/frame-NNNNNN.svg (or .pdf, .eps, .png).\n";

struct AnimateOptions {
    QString scene;
    QString out;
    QString framesDir;
    QString frameFormat = QStringLiteral("svg");
    double start = 0;
    std::optional<double> end;  // default: the scene's time.steps × time.dt
    double fps = 30;
    QString backend;
    std::optional<int> device;
    render::ExportOptions exportOptions;
};

void addOptions(QCommandLineParser& parser)
{
    // name, value name (none for a flag), description
    const std::array<std::array<const char*, 3>, 11> options{{
        {"out", "FILE", "The animation: .json (Lottie), .svg (animated SVG), .pdf, .mp4 or .gif."},
        {"frames", "DIR", "Instead, each frame as DIR/frame-NNNNNN.svg; DIR is created."},
        {"frame-format", "F", "The frames' format: svg (default), pdf, eps or png."},
        {"start", "S", "Seconds of scene time where the animation starts (default 0)."},
        {"end", "S", "Seconds of scene time where it ends (default: the scene's time.steps x time.dt, or the whole history)."},
        {"fps", "N", "Frames per second (default 30)."},
        {"width", "N", "Width in points, which Lottie and video take as pixels (default 576)."},
        {"transparent", "", "Leave the background out (not in .mp4)."},
        {"polyline", "", "Write the vertices as they are, not fitted Béziers."},
        {"backend", "reference|opencl", "The simulation backend (default: OpenCL where a device exists)."},
        {"device", "N", "The OpenCL device, numbered as `vectorfluid devices` lists them."},
    }};
    for (const auto& [name, valueName, description] : options)
        parser.addOption(QCommandLineOption(QString::fromLatin1(name), QString::fromUtf8(description),
                                            QString::fromLatin1(valueName)));
    parser.addPositionalArgument(QStringLiteral("SCENE|PROJECT"),
                                 QStringLiteral("The scene file (.vfscene) to play, or the project (.vfproj) whose history to play again."));
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
    else if (isSet("out") == isSet("frames"))
        error = QStringLiteral("give either --out FILE or --frames DIR");
    else if (parser.values(QStringLiteral("out")).size() > 1 || parser.values(QStringLiteral("frames")).size() > 1)
        error = QStringLiteral("only one --out or --frames may be given");
    else if (isSet("out") && !render::isAnimationSuffix(value("out")))
        error = QStringLiteral("--out %1: the format must be .json, .svg, .pdf, .mp4 or .gif").arg(value("out"));
    else if (isSet("frame-format") && !isSet("frames"))
        error = QStringLiteral("--frame-format needs --frames DIR");
    else if (isSet("frame-format") && !render::isExportSuffix(QStringLiteral("frame.") + value("frame-format")))
        error = QStringLiteral("--frame-format: '%1' is not one of svg, pdf, eps, png").arg(value("frame-format"));
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
    o.framesDir = value("frames");
    if (isSet("frame-format"))
        o.frameFormat = value("frame-format");
    o.exportOptions.background = !isSet("transparent");
    o.exportOptions.bezier = !isSet("polyline");
    o.exportOptions.dpi = 72;  // raster frames: a pixel a point
    return o;
}

// What to play: a scene from its start, or a project's history again (its spans).
struct Playable {
    model::Scene scene;
    std::optional<std::vector<model::ReplaySpan>> history;
    QString notice;  // commands of the history that cannot be played again, if any

    double duration() const
    {
        return history ? model::replayDuration(*history, scene.time.dt) : double(scene.time.steps) * scene.time.dt;
    }
};

bool isProjectPath(const QString& path) { return path.endsWith(QLatin1String(".vfproj"), Qt::CaseInsensitive); }

std::optional<Playable> readPlayable(const QString& path, QString& error)
{
    if (!isProjectPath(path)) {
        model::SceneReadResult read = model::readSceneFile(path);
        error = read.error;
        return read.ok() ? std::optional<Playable>(Playable{std::move(read.scene), std::nullopt, {}}) : std::nullopt;
    }
    const model::ProjectReadResult read = model::readProjectFile(path);
    if (!read.ok()) {
        error = read.error;
        return std::nullopt;
    }
    int unrecorded = 0;
    std::vector<model::ReplaySpan> spans = model::replaySpans(read.project, &unrecorded);
    if (spans.empty()) {
        error = QStringLiteral("%1: its history holds no step that can be played again").arg(path);
        return std::nullopt;
    }
    Playable playable{read.project.scene, std::move(spans), {}};
    if (unrecorded > 0)
        playable.notice = QStringLiteral("%1: %2 command(s) of its history were saved without what they did, and are left out")
                              .arg(path).arg(unrecorded);
    return playable;
}

// Fails before any simulation when the output could not be written: its folder must exist (a
// frames folder is created) and a temporary is created and removed where the file would go.
QString checkOutput(const AnimateOptions& options, qint64 frames)
{
    QString file = options.out;
    if (!options.framesDir.isEmpty()) {
        if (!QDir().mkpath(options.framesDir))
            return QStringLiteral("%1: cannot create the frames folder").arg(options.framesDir);
        file = render::framePath(options.framesDir, 0, frames - 1, options.frameFormat);
    }
    if (!QFileInfo(file).absoluteDir().exists())
        return QStringLiteral("%1: the folder %2 does not exist").arg(file, QFileInfo(file).absolutePath());
    return model::checkWritable(file);
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
    const std::optional<Playable> read = readPlayable(options->scene, error);
    if (!read) {
        printError(error);
        return BadInput;
    }
    const FrameRange range{options->start, options->end.value_or(read->duration()), options->fps};
    const qint64 frames = frameCount(range);
    if (frames < 1 || frames > 100'000'000) {
        printError(QStringLiteral("%1 to %2 s at %3 fps is %4 frames (1 to 100000000)")
                       .arg(range.start).arg(range.end).arg(range.fps).arg(frames));
        return BadInput;
    }
    if (const QString error = checkMemory(read->scene, RenderOptions{}, availableMemory()); !error.isEmpty()) {
        printError(QStringLiteral("%1: %2").arg(options->scene, error));
        return BadInput;
    }
    if (const QString error = checkOutput(*options, frames); !error.isEmpty()) {
        printError(error);
        return BadInput;
    }
    handleRenderSignals();
    QString notice;
    QString limit;  // the limit that stopped the run, if one did
    int framesDone = 0;
    try {
        const model::SimulationFactory factory = [&](const sim::SimulationSettings& settings) {
            return makeBackend(settings, options->backend, options->device, notice);
        };
        std::unique_ptr<model::Player> player;
        if (read->history)
            player = std::make_unique<model::HistoryReplay>(read->scene, *read->history, factory);
        else
            player = std::make_unique<model::SceneRunner>(read->scene, factory);
        RenderProgress progress(frames, QStringLiteral("frame"));
        SceneFrames sceneFrames(*player, range, interruptRequested);
        const render::Animation animation = sceneFrames.animation();
        const render::AnimationProgress goOn = [&](int done) {
            framesDone = done;
            progress.update(done, player->simulation().vertexCount());
            limit = sceneFrames.limit();
            return limit.isEmpty() && !interruptRequested();
        };
        error = options->framesDir.isEmpty()
                    ? render::exportAnimation(animation, options->out, options->exportOptions, goOn)
                    : render::exportFrames(animation, options->framesDir, options->frameFormat, options->exportOptions, goOn);
    } catch (const std::exception& e) {
        error = QStringLiteral("%1: %2").arg(options->scene, QString::fromUtf8(e.what()));
    }
    const QString kept = options->framesDir.isEmpty() ? QStringLiteral("no output written")
                                                       : QStringLiteral("the frames written so far stay");
    if (!limit.isEmpty()) {
        printError(QStringLiteral("%1: %2 at frame %3 of %4; %5").arg(options->scene, limit).arg(framesDone).arg(frames).arg(kept));
        return LimitHit;
    }
    if (interruptRequested()) {
        printError(QStringLiteral("%1: interrupted at frame %2 of %3; %4").arg(options->scene).arg(framesDone).arg(frames).arg(kept));
        return Interrupted;
    }
    if (!error.isEmpty()) {
        printError(error);
        return BadInput;
    }
    for (const QString& line : {read->notice, notice})
        if (!line.isEmpty())
            printError(line);
    QTextStream(stdout) << "wrote " << (options->framesDir.isEmpty() ? options->out : options->framesDir) << '\n';
    return Done;
}

} // namespace vf::app
