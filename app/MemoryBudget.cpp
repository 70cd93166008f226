#include "app/MemoryBudget.h"

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vf::app {

namespace {

// Resident bytes per vertex at the vertex budget: the engine's peak, 150 B a vertex measured on
// OpenCL in fine detail (109 on the reference, docs/BENCHMARKS.md), plus the finished drawing
// and the writers' copies of the contours.
constexpr double kBytesPerVertex = 200;
// The fluid solver's fields, its multigrid levels and the stream function's samples per grid cell.
constexpr double kBytesPerCell = 600;
// A PNG holds its image (4 bytes a pixel) and its encoding, at worst about as large again.
constexpr double kBytesPerPixel = 8;

struct Part {
    QString what;  // the limit that sets it, as the user wrote it
    double bytes = 0;
};

} // namespace

QString bytesText(double bytes)
{
    const bool giga = bytes >= 1e9;
    const double value = bytes / (giga ? 1e9 : 1e6);
    return QStringLiteral("%1 %2").arg(value >= 100 ? QString::number(value, 'f', 0) : QString::number(value, 'g', 2),
                                       giga ? QStringLiteral("GB") : QStringLiteral("MB"));
}

double vertexBytes(std::int64_t maxVertices) { return double(maxVertices) * kBytesPerVertex; }

double gridBytes(const model::FlowSpec& flow)
{
    return flow.type == model::FlowSpec::Type::Fluid ? double(flow.gridX) * flow.gridY * kBytesPerCell : 0.0;
}

double pngBytes(const render::RasterSize& pixels) { return pixels.width * pixels.height * kBytesPerPixel; }

std::int64_t maxVerticesFitting(const model::FlowSpec& flow, double available)
{
    if (available <= 0)
        return std::numeric_limits<std::int64_t>::max();
    return std::int64_t(std::floor(std::max(0.0, available - gridBytes(flow)) / kBytesPerVertex));
}

double availableMemory()
{
    QFile meminfo(QStringLiteral("/proc/meminfo"));
    if (!meminfo.open(QIODevice::ReadOnly))
        return 0;
    const QRegularExpressionMatch match =
        QRegularExpression(QStringLiteral("^MemAvailable:\\s*(\\d+) kB"), QRegularExpression::MultilineOption)
            .match(QString::fromLatin1(meminfo.readAll()));
    return match.hasMatch() ? match.captured(1).toDouble() * 1024 : 0;
}

QString checkMemory(const model::Scene& scene, const RenderOptions& options, double available)
{
    std::vector<Part> parts;
    parts.push_back({QStringLiteral("tracking.max_vertices %1").arg(scene.tracking.maxVertices),
                     vertexBytes(scene.tracking.maxVertices)});
    if (scene.flow.type == model::FlowSpec::Type::Fluid)
        parts.push_back({QStringLiteral("flow.grid %1 x %2").arg(scene.flow.gridX).arg(scene.flow.gridY), gridBytes(scene.flow)});
    model::Drawing canvas;
    canvas.width = scene.canvas.width;
    canvas.height = scene.canvas.height;
    const bool png = std::any_of(options.outputs.begin(), options.outputs.end(),
                                 [](const QString& out) { return QFileInfo(out).suffix().toLower() == QLatin1String("png"); });
    if (png) {  // the PNGs are written one after the other, so only one image is held
        const render::RasterSize size = render::pngPixels(canvas, options.exportOptions);
        parts.push_back({QStringLiteral("--dpi %1 (a %2 x %3 pixel PNG)").arg(options.exportOptions.dpi).arg(size.width, 0, 'f', 0).arg(size.height, 0, 'f', 0),
                         pngBytes(size)});
    }
    double total = 0;
    QStringList described;
    for (const Part& part : parts) {
        total += part.bytes;
        described << QStringLiteral("%1: %2").arg(part.what, bytesText(part.bytes));
    }
    if (available <= 0 || total <= available)
        return {};
    return QStringLiteral("needs about %1 of memory (%2), more than the %3 available")
        .arg(bytesText(total), described.join(QStringLiteral(", ")), bytesText(available));
}

} // namespace vf::app
