#include "app/RenderOptions.h"

#include <cmath>

namespace vf::app {

namespace {

// Reads the value after a flag; false (with `error` set) when it is missing.
bool takeValue(const QStringList& args, qsizetype& i, QString& value, QString& error)
{
    if (i + 1 >= args.size()) {
        error = QStringLiteral("%1 needs a value").arg(args[i]);
        return false;
    }
    value = args[++i];
    return true;
}

} // namespace

std::optional<RenderOptions> parseRenderOptions(const QStringList& args, QString& error)
{
    RenderOptions o;
    bool ok = true;
    for (qsizetype i = 0; i < args.size() && ok; ++i) {
        const QString& a = args[i];
        QString value;
        if (a == QLatin1String("--polyline")) {
            o.exportOptions.bezier = false;
        } else if (!a.startsWith(QLatin1String("--"))) {
            if (!o.scene.isEmpty()) {
                error = QStringLiteral("only one scene file may be given (got %1 and %2)").arg(o.scene, a);
                return std::nullopt;
            }
            o.scene = a;
        } else if (!(ok = takeValue(args, i, value, error))) {
            break;
        } else if (a == QLatin1String("--steps")) {
            const qint64 n = value.toLongLong(&ok);
            ok = ok && n >= 0;
            o.steps = n;
            if (!ok)
                error = QStringLiteral("--steps: '%1' is not a non-negative whole number").arg(value);
        } else if (a == QLatin1String("--dt")) {
            const double dt = value.toDouble(&ok);
            ok = ok && std::isfinite(dt) && dt > 0.0;
            o.dt = dt;
            if (!ok)
                error = QStringLiteral("--dt: '%1' is not a positive number").arg(value);
        } else if (a == QLatin1String("--backend")) {
            ok = value == QLatin1String("reference") || value == QLatin1String("opencl");
            o.backend = value;
            if (!ok)
                error = QStringLiteral("--backend: '%1' is not one of reference, opencl").arg(value);
        } else if (a == QLatin1String("--out")) {
            ok = render::isExportSuffix(value);
            o.outputs << value;
            if (!ok)
                error = QStringLiteral("--out %1: the format must be .svg, .pdf, .eps or .png").arg(value);
        } else if (a == QLatin1String("--dpi")) {
            const double dpi = value.toDouble(&ok);
            ok = ok && std::isfinite(dpi) && dpi > 0.0 && dpi <= 4800.0;
            o.exportOptions.dpi = dpi;
            if (!ok)
                error = QStringLiteral("--dpi: '%1' is not a resolution between 0 and 4800").arg(value);
        } else if (a == QLatin1String("--frames")) {
            o.framesDir = value;
        } else if (a == QLatin1String("--every")) {
            o.every = value.toLongLong(&ok);
            ok = ok && o.every > 0;
            if (!ok)
                error = QStringLiteral("--every: '%1' is not a positive whole number").arg(value);
        } else if (a == QLatin1String("--stats")) {
            o.statsFile = value;
        } else {
            error = QStringLiteral("unknown option %1").arg(a);
            ok = false;
        }
    }
    if (ok && o.scene.isEmpty()) {
        error = QStringLiteral("no scene file given");
        ok = false;
    }
    if (ok && !o.framesDir.isEmpty() && o.every == 0)
        o.every = 1;
    if (ok && o.framesDir.isEmpty() && o.every > 0) {
        error = QStringLiteral("--every needs --frames DIR");
        ok = false;
    }
    return ok ? std::optional(o) : std::nullopt;
}

} // namespace vf::app
