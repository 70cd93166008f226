#include "app/RenderOptions.h"

#include "model/Scene.h"

#include <cmath>
#include <functional>
#include <map>

namespace vf::app {

namespace {

// Each option that takes a value: reads it into the options, or returns what is wrong with it.
using Setter = std::function<QString(RenderOptions&, const QString&)>;

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

const std::map<QString, Setter>& valueOptions()
{
    static const std::map<QString, Setter> options{
        {"--steps", [](RenderOptions& o, const QString& v) {
             qint64 n = 0;
             QString error = wholeNumber("--steps", v, 0, model::limits::maxSteps, n);
             o.steps = n;
             return error;
         }},
        {"--dt", [](RenderOptions& o, const QString& v) {
             double dt = 0.0;
             QString error = positiveNumber("--dt", v, 1e6, dt);
             o.dt = dt;
             return error;
         }},
        {"--backend", [](RenderOptions& o, const QString& v) {
             o.backend = v;
             return v == "reference" || v == "opencl"
                        ? QString()
                        : QStringLiteral("--backend: '%1' is not one of reference, opencl").arg(v);
         }},
        {"--device", [](RenderOptions& o, const QString& v) {
             qint64 n = 0;
             QString error = wholeNumber("--device", v, 0, 1 << 20, n);
             o.device = int(n);
             return error;
         }},
        {"--out", [](RenderOptions& o, const QString& v) {
             o.outputs << v;
             return render::isExportSuffix(v)
                        ? QString()
                        : QStringLiteral("--out %1: the format must be .svg, .pdf, .eps or .png").arg(v);
         }},
        {"--dpi", [](RenderOptions& o, const QString& v) { return positiveNumber("--dpi", v, 4800.0, o.exportOptions.dpi); }},
        {"--frames", [](RenderOptions& o, const QString& v) { o.framesDir = v; return QString(); }},
        {"--every", [](RenderOptions& o, const QString& v) { return wholeNumber("--every", v, 1, model::limits::maxSteps, o.every); }},
        {"--stats", [](RenderOptions& o, const QString& v) { o.statsFile = v; return QString(); }},
        {"--check-topology", [](RenderOptions& o, const QString& v) {
             return wholeNumber("--check-topology", v, 1, model::limits::maxSteps, o.checkTopologyEvery);
         }},
    };
    return options;
}

// One argument (and the value after it, for a value option); returns what is wrong, if anything.
QString takeArgument(RenderOptions& o, const QStringList& args, qsizetype& i)
{
    const QString& a = args[i];
    if (a == QLatin1String("--polyline")) {
        o.exportOptions.bezier = false;
        return {};
    }
    if (!a.startsWith(QLatin1String("--"))) {
        if (!o.scene.isEmpty())
            return QStringLiteral("only one scene file may be given (got %1 and %2)").arg(o.scene, a);
        o.scene = a;
        return {};
    }
    const auto option = valueOptions().find(a);
    if (option == valueOptions().end())
        return QStringLiteral("unknown option %1").arg(a);
    if (i + 1 >= args.size())
        return QStringLiteral("%1 needs a value").arg(a);
    return option->second(o, args[++i]);
}

} // namespace

std::optional<RenderOptions> parseRenderOptions(const QStringList& args, QString& error)
{
    RenderOptions o;
    for (qsizetype i = 0; i < args.size() && error.isEmpty(); ++i)
        error = takeArgument(o, args, i);
    if (error.isEmpty() && o.scene.isEmpty())
        error = QStringLiteral("no scene file given");
    if (error.isEmpty() && o.framesDir.isEmpty() && o.every > 0)
        error = QStringLiteral("--every needs --frames DIR");
    if (!o.framesDir.isEmpty() && o.every == 0)
        o.every = 1;
    return error.isEmpty() ? std::optional(o) : std::nullopt;
}

} // namespace vf::app
