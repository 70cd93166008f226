// `vectorfluid render SCENE ...`: run a scene headless and write files (docs/command-line.md).
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
#include "sim/Coverage.h"
#include "sim/Crossings.h"
#include "sim/opencl/OpenClSimulation.h"
#include "render/Animation.h"
#include "render/Exporter.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <stdexcept>

namespace vf::app {

namespace {

struct RunTotals {
    qint64 steps = 0;
    qint64 vertexSteps = 0;  // sum over steps of the vertex count after the step
    double simSeconds = 0.0; // wall time inside simulation steps only
    bool limitHit = false;
    QString limit;           // which limit, when limitHit
    QString crossing;        // --check-topology: the first crossing found, if any
};

// The backend the options ask for (app/Backend.h); a fallback notice is shown once the run is done.
model::SimulationFactory backendFactory(const RenderOptions& options, QString& notice)
{
    return [&options, &notice](const sim::SimulationSettings& settings) {
        return makeBackend(settings, options.backend, options.device, notice);
    };
}

QString writeStats(const QString& path, const model::Scene& scene, const model::Drawing& drawing,
                   const RunTotals& totals, const sim::Simulation& simulation, model::FileBatch& batch)
{
    QJsonArray regions;
    for (const model::DrawnRegion& r : drawing.regions) {
        qint64 count = 0;
        double length = 0.0;
        for (const sim::Polygon& p : r.contours) {
            count += qint64(p.size());
            length += sim::perimeter(p);
        }
        regions.append(QJsonObject{{"name", r.name}, {"vertices", count}, {"area", sim::filledArea(r.contours)},
                                   {"perimeter", length}});
    }
    // How well the ink fills each gather's target at the end: intersection over union on a lattice
    // of 512 points across the canvas's larger side.
    const model::Canvas& canvas = scene.canvas;
    const double across = 512.0 / std::max(canvas.width, canvas.height);
    const sim::CellLattice lattice{int(std::ceil(canvas.width * across)), int(std::ceil(canvas.height * across)),
                                   canvas.width, canvas.height};
    std::vector<std::vector<sim::Polygon>> ink;
    for (const model::DrawnRegion& r : drawing.regions)
        ink.push_back(r.contours);
    QJsonArray gathers;
    for (const model::Stroke& stroke : scene.strokes)
        if (const auto* gather = std::get_if<model::GatherStroke>(&stroke))
            gathers.append(QJsonObject{{"time", gather->time},
                                       {"target_overlap", sim::intersectionOverUnion(ink, gather->contours, lattice)}});
    const QJsonObject root{
        {"backend", QString::fromStdString(simulation.backendName())},
        {"regions", regions},
        {"gathers", gathers},
        {"totals", QJsonObject{{"steps", totals.steps},
                               {"vertices", qint64(simulation.vertexCount())},
                               {"vertex_steps", totals.vertexSteps},
                               {"sim_seconds", totals.simSeconds}}},
        {"limit_reached", totals.limitHit},
    };
    const QByteArray json = QJsonDocument(root).toJson();
    return batch.write(path, [&json](QIODevice& file) { return model::writeAll(file, json); });
}

// The files written at the end: the pictures and the stats.
QStringList finalFiles(const RenderOptions& options)
{
    QStringList files = options.outputs;
    if (!options.statsFile.isEmpty())
        files << options.statsFile;
    return files;
}

// Fails before any simulation when an output could not be written at the end: every file is
// tried (a temporary created and removed beside it), so a read-only folder or file is found now.
QString checkOutputs(const RenderOptions& options, qint64 steps)
{
    QStringList files = finalFiles(options);
    for (const QString& file : files) {
        const QFileInfo info(file);
        if (!info.absoluteDir().exists())
            return QStringLiteral("%1: the folder %2 does not exist").arg(file, info.absolutePath());
    }
    if (!options.framesDir.isEmpty()) {
        if (!QDir().mkpath(options.framesDir))
            return QStringLiteral("%1: cannot create the frames folder").arg(options.framesDir);
        files << render::framePath(options.framesDir, 0, steps, QStringLiteral("svg"));
    }
    for (const QString& file : files) {
        if (const QString error = model::checkWritable(file); !error.isEmpty())
            return error;
    }
    return {};
}

// No output may replace an SVG file the scene starts from: `render logo.vfscene` alone writes
// logo.svg beside it, which may be the very logo it imports.
QString checkInputsKept(const model::Scene& scene, const RenderOptions& options)
{
    const QDir sceneFolder = QFileInfo(options.scene).absoluteDir();
    const QStringList files = finalFiles(options);
    for (std::size_t i = 0; i < scene.regions.size(); ++i) {
        const auto* svg = std::get_if<model::SvgShape>(&scene.regions[i].shape);
        if (!svg)
            continue;
        const QString input = QFileInfo(sceneFolder.filePath(svg->file)).canonicalFilePath();
        for (const QString& file : files) {
            if (!input.isEmpty() && QFileInfo(file).canonicalFilePath() == input)
                return QStringLiteral("%1: would overwrite the SVG file of regions[%2].shape.svg; write elsewhere with --out")
                    .arg(file).arg(i);
        }
    }
    return {};
}

// --check-topology: contours must stay simple, and two contours that were apart when the later of
// them appeared must stay apart. Regions may start overlapping (a scene may stack shapes): their
// contours then cross from the start, which the flow keeps and the check accepts.
class TopologyCheck {
public:
    // The first crossing the simulation made, in one line, or nothing.
    QString run(const model::SceneRunner& runner, qint64 step)
    {
        const std::vector<sim::Contour> contours = runner.simulation().contours();
        std::vector<const sim::Polygon*> polygons;
        for (const sim::Contour& c : contours)
            polygons.push_back(&c.positions);
        const std::size_t known = m_known;
        m_known = contours.size();
        for (const sim::EdgeCrossing& x : sim::findCrossings(polygons)) {
            const std::pair pair{x.polygonA, x.polygonB};
            if (x.polygonA != x.polygonB && x.polygonB >= known)
                m_overlapping.insert(pair);  // appeared overlapping
            if (m_overlapping.count(pair) == 0)
                return describe(runner, contours, x, step);
        }
        return {};
    }

private:
    static QString describe(const model::SceneRunner& runner, const std::vector<sim::Contour>& contours,
                            const sim::EdgeCrossing& x, qint64 step)
    {
        const auto edge = [&](std::size_t contour, std::size_t index) {
            return QStringLiteral("'%1' (contour %2, edge %3)")
                .arg(runner.regionName(contours[contour].region))
                .arg(contour)
                .arg(index);
        };
        return QStringLiteral("contours cross at step %1 (t = %2 s): %3 and %4 at (%5, %6)")
            .arg(step)
            .arg(runner.simulation().time(), 0, 'g', 9)
            .arg(edge(x.polygonA, x.edgeA), edge(x.polygonB, x.edgeB))
            .arg(x.point.x, 0, 'g', 9)
            .arg(x.point.y, 0, 'g', 9);
    }

    std::size_t m_known = 0;  // contours seen so far; later ones are appended
    std::set<std::pair<std::size_t, std::size_t>> m_overlapping;
};

} // namespace

int renderCommand(const QStringList& arguments)
{
    CommandLine commandLine(QStringLiteral("vectorfluid render"), QString::fromLatin1(renderUsage));
    addRenderOptions(commandLine.parser());
    if (const std::optional<int> exitCode = commandLine.parse(arguments))
        return *exitCode;
    QString error;
    const auto options = renderOptions(commandLine.parser(), error);
    if (!options) {
        printError(error);
        return BadInput;
    }
    const model::SceneReadResult read = model::readSceneFile(options->scene);
    if (!read.ok()) {
        printError(read.error);
        return BadInput;
    }
    const qint64 steps = options->steps.value_or(read.scene.time.steps);
    const double dt = options->dt.value_or(read.scene.time.dt);
    if (const QString error = checkMemory(read.scene, *options, availableMemory()); !error.isEmpty()) {
        printError(QStringLiteral("%1: %2").arg(options->scene, error));
        return BadInput;
    }
    if (const QString error = checkInputsKept(read.scene, *options); !error.isEmpty()) {
        printError(error);
        return BadInput;
    }
    if (const QString error = checkOutputs(*options, steps); !error.isEmpty()) {
        printError(error);
        return BadInput;
    }
    handleRenderSignals();
    RunTotals totals;
    QString notice;
    try {
        model::SceneRunner runner(read.scene, backendFactory(*options, notice));
        auto writeFrame = [&](qint64 step) {
            if (options->framesDir.isEmpty() || step % options->every != 0)
                return QString();
            return render::exportDrawing(runner.drawing(), render::framePath(options->framesDir, step, steps, QStringLiteral("svg")), options->exportOptions);
        };
        const QString vertexLimit = vertexLimitLabel(runner.simulation()) + QStringLiteral(" reached");
        if (runner.vertexLimitReached()) {  // drops at t = 0 already took it there
            totals.limitHit = true;
            totals.limit = vertexLimit;
        }
        TopologyCheck topology;
        RenderProgress progress(steps);
        auto checkTopology = [&] {
            const qint64 every = options->checkTopologyEvery;
            if (every > 0 && (totals.steps % every == 0 || totals.steps == steps || totals.limitHit))
                totals.crossing = topology.run(runner, totals.steps);
        };
        error = writeFrame(0);
        checkTopology();
        while (error.isEmpty() && totals.steps < steps && !totals.limitHit && totals.crossing.isEmpty()
               && !interruptRequested()) {
            const auto start = std::chrono::steady_clock::now();
            try {
                if (runner.step(dt).vertexLimitReached) {
                    totals.limitHit = true;
                    totals.limit = vertexLimit;
                }
            } catch (const sim::opencl::DeviceError& e) {  // e.g. the device ran out of memory
                totals.limitHit = true;
                totals.limit = QString::fromUtf8(e.what()).section('\n', 0, 0);
            }
            totals.simSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            ++totals.steps;
            totals.vertexSteps += qint64(runner.simulation().vertexCount());
            error = writeFrame(totals.steps);
            checkTopology();
            progress.update(totals.steps, runner.simulation().vertexCount());
        }
        // Every output goes to a temporary first; they are put in place together, and only when
        // all of them were written and no interrupt came meanwhile.
        const model::Drawing drawing = runner.drawing();
        model::FileBatch batch;
        for (const QString& out : options->outputs) {
            if (error.isEmpty() && !interruptRequested())
                error = render::exportDrawing(drawing, out, options->exportOptions, batch);
        }
        if (error.isEmpty() && !options->statsFile.isEmpty() && !interruptRequested())
            error = writeStats(options->statsFile, runner.scene(), drawing, totals, runner.simulation(), batch);
        if (error.isEmpty() && !interruptRequested() && (error = batch.commit()).isEmpty()) {
            for (const QString& out : options->outputs)
                QTextStream(stdout) << "wrote " << out << '\n';
        }
    } catch (const std::exception& e) {
        error = QStringLiteral("%1: %2").arg(options->scene, QString::fromUtf8(e.what()));
    }
    if (!error.isEmpty()) {
        printError(error);  // the one line bad input gets; a fallback notice would only distract from it
        return BadInput;
    }
    if (interruptRequested()) {
        printError(QStringLiteral("%1: interrupted at step %2 of %3; no output written")
                       .arg(options->scene)
                       .arg(totals.steps)
                       .arg(steps));
        return Interrupted;
    }
    if (!notice.isEmpty())
        printError(notice);
    if (!totals.crossing.isEmpty()) {
        printError(QStringLiteral("%1: %2; the files hold the state at that step").arg(options->scene, totals.crossing));
        return TopologyBroken;
    }
    if (totals.limitHit) {
        printError(QStringLiteral("%1: %2 at step %3 of %4; the files hold the state at that step")
                 .arg(options->scene, totals.limit)
                 .arg(totals.steps)
                 .arg(steps));
        return LimitHit;
    }
    return Done;
}

} // namespace vf::app
