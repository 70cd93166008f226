#include "app/RenderOptions.h"

#include "model/Scene.h"

#include <QDir>
#include <QFileInfo>

#include <cmath>
#include <functional>
#include <vector>

namespace vf::app {

QString wholeNumber(const QString& option, const QString& value, qint64 minimum, qint64 maximum, qint64& into)
{
    bool ok = false;
    into = value.toLongLong(&ok);
    if (ok && into >= minimum && into <= maximum)
        return {};
    return QStringLiteral("%1: '%2' is not a whole number from %3 to %4").arg(option, value).arg(minimum).arg(maximum);
}

QString positiveNumber(const QString& option, const QString& value, double maximum, double& into)
{
    bool ok = false;
    into = value.toDouble(&ok);
    if (ok && std::isfinite(into) && into > 0.0 && into <= maximum)
        return {};
    return QStringLiteral("%1: '%2' is not a number in (0, %3]").arg(option, value).arg(maximum);
}

namespace {

// Each option that takes a value: reads it into the options, or returns what is wrong with it.
using Setter = std::function<QString(RenderOptions&, const QString&)>;

struct ValueOption {
    QString name;  // without the dashes
    QString valueName;
    QString description;
    Setter set;
};

const std::vector<ValueOption>& valueOptions()
{
    static const std::vector<ValueOption> options{
        {"steps", "N", "Steps to run (default: the scene's time.steps).", [](RenderOptions& o, const QString& v) {
             qint64 n = 0;
             QString error = wholeNumber("--steps", v, 0, model::limits::maxSteps, n);
             o.steps = n;
             return error;
         }},
        {"dt", "S", "Seconds of simulated time per step (default: the scene's time.dt).", [](RenderOptions& o, const QString& v) {
             double dt = 0.0;
             QString error = positiveNumber("--dt", v, 1e6, dt);
             o.dt = dt;
             return error;
         }},
        {"backend", "reference|opencl", "The simulation backend (default: OpenCL where a device exists).",
         [](RenderOptions& o, const QString& v) {
             o.backend = v;
             return v == "reference" || v == "opencl"
                        ? QString()
                        : QStringLiteral("--backend: '%1' is not one of reference, opencl").arg(v);
         }},
        {"device", "N", "The OpenCL device, numbered as `vectorfluid devices` lists them.", [](RenderOptions& o, const QString& v) {
             qint64 n = 0;
             QString error = wholeNumber("--device", v, 0, 1 << 20, n);
             o.device = int(n);
             return error;
         }},
        {"out", "FILE", "Write the last step to FILE: .svg, .pdf, .eps or .png (repeatable).", [](RenderOptions& o, const QString& v) {
             o.outputs << v;
             return render::isExportSuffix(v)
                        ? QString()
                        : QStringLiteral("--out %1: the format must be .svg, .pdf, .eps or .png").arg(v);
         }},
        {"dpi", "N", "Resolution of .png outputs.",
         [](RenderOptions& o, const QString& v) { return positiveNumber("--dpi", v, 4800.0, o.exportOptions.dpi); }},
        {"frames", "DIR", "Also write DIR/frame-NNNNNN.svg every K steps.",
         [](RenderOptions& o, const QString& v) { o.framesDir = v; return QString(); }},
        {"every", "K", "The frames' interval in steps (default 1).",
         [](RenderOptions& o, const QString& v) { return wholeNumber("--every", v, 1, model::limits::maxSteps, o.every); }},
        {"stats", "FILE.json", "Write per-region vertex counts, areas and perimeters, and the run's totals.",
         [](RenderOptions& o, const QString& v) { o.statsFile = v; return QString(); }},
        {"check-topology", "K", "Check every K steps that no two contour edges cross; stop at the first crossing (exit 4).",
         [](RenderOptions& o, const QString& v) {
             return wholeNumber("--check-topology", v, 1, model::limits::maxSteps, o.checkTopologyEvery);
         }},
    };
    return options;
}

const QString polyline = QStringLiteral("polyline");

// With nothing else to write, the picture goes beside the scene: "a/b.vfscene" writes "a/b.svg".
QString defaultOutput(const QString& scene)
{
    const QFileInfo info(scene);
    return info.dir().filePath(info.completeBaseName() + QStringLiteral(".svg"));
}

} // namespace

const char* const renderUsage =
    "usage: vectorfluid render SCENE [--steps N] [--dt S] [--backend reference|opencl] [--device N]\n"
    "                          [--out FILE]... [--polyline] [--dpi N] [--frames DIR --every K]\n"
    "                          [--stats FILE.json] [--check-topology K]\n"
    "Runs SCENE headless and writes what the options ask for; with none of --out, --stats and\n"
    "--frames, writes SCENE's name with .svg beside it.\n";

void addRenderOptions(QCommandLineParser& parser)
{
    for (const ValueOption& option : valueOptions())
        parser.addOption(QCommandLineOption(option.name, option.description, option.valueName));
    parser.addOption(QCommandLineOption(polyline, QStringLiteral("Write the vertices as they are, not fitted Béziers.")));
    parser.addPositionalArgument(QStringLiteral("SCENE"), QStringLiteral("The scene file (.vfscene) to run."));
}

std::optional<RenderOptions> renderOptions(const QCommandLineParser& parser, QString& error)
{
    RenderOptions o;
    o.exportOptions.bezier = !parser.isSet(polyline);
    for (const ValueOption& option : valueOptions())
        for (const QString& value : parser.values(option.name))
            if (error.isEmpty())
                error = option.set(o, value);
    const QStringList scenes = parser.positionalArguments();
    if (error.isEmpty() && scenes.isEmpty())
        error = QStringLiteral("no scene file given");
    if (error.isEmpty() && scenes.size() > 1)
        error = QStringLiteral("only one scene file may be given (got %1 and %2)").arg(scenes[0], scenes[1]);
    if (error.isEmpty() && o.framesDir.isEmpty() && o.every > 0)
        error = QStringLiteral("--every needs --frames DIR");
    if (!error.isEmpty())
        return std::nullopt;
    o.scene = scenes.front();
    if (!o.framesDir.isEmpty() && o.every == 0)
        o.every = 1;
    if (o.outputs.isEmpty() && o.statsFile.isEmpty() && o.framesDir.isEmpty())
        o.outputs << defaultOutput(o.scene);
    return o;
}

} // namespace vf::app
