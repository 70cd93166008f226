#include "render/Exporter.h"

#include "model/AtomicFile.h"
#include "render/Page.h"
#include "render/Writers.h"

#include <QFileInfo>

#include <array>
#include <cmath>

namespace vf::render {
namespace {

using Writer = QString (*)(const model::Drawing&, const ExportOptions&, QIODevice&);

struct Format {
    const char* suffix; // lower case, without the dot
    Writer write;
    double maxPageSide; // points; 0 for no limit
};

// PDF viewers and PostScript interpreters take pages of at most 200 inches a side (the PDF
// reference's implementation limit, which Ghostscript enforces for EPS too); Cairo's 24.8 fixed
// point would also overflow far beyond it.
constexpr double kPrintLimit = 14400.0;

constexpr std::array kFormats{
    Format{"svg", writeSvg, 0.0},
    Format{"pdf", writePdf, kPrintLimit},
    Format{"eps", writeEps, kPrintLimit},
    Format{"png", writePng, 0.0},
};

const Format* formatFor(const QString& path) { return formatBySuffix(kFormats, path); }

bool isPositive(double value) { return std::isfinite(value) && value > 0; }

QString checkRegion(const model::DrawnRegion& region)
{
    for (const sim::Polygon& contour : region.contours) {
        for (const sim::Vec2& p : contour) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y))
                return QStringLiteral("region \"%1\" has a non-finite vertex").arg(region.name);
        }
    }
    return {};
}

QString failure(const QString& path, const QString& what)
{
    return path + QStringLiteral(": ") + what.simplified(); // one line, whatever the cause said
}

} // namespace

QString checkExport(const model::Drawing& drawing, const ExportOptions& options)
{
    if (!isPositive(drawing.width) || !isPositive(drawing.height))
        return QStringLiteral("canvas size %1 x %2 is not positive").arg(drawing.width).arg(drawing.height);
    if (!isPositive(options.pageWidth))
        return QStringLiteral("page width %1 pt is not positive").arg(options.pageWidth);
    if (!std::isfinite(options.pageHeight) || options.pageHeight < 0)
        return QStringLiteral("page height %1 pt is not positive (or 0 for the canvas's aspect)").arg(options.pageHeight);
    if (!isPositive(options.dpi))
        return QStringLiteral("resolution %1 dpi is not positive").arg(options.dpi);
    if (!std::isfinite(options.bezierTolerance) || options.bezierTolerance < 0)
        return QStringLiteral("Bézier tolerance %1 is not a length (0 picks the default)").arg(options.bezierTolerance);
    for (const model::DrawnRegion& region : drawing.regions) {
        if (QString error = checkRegion(region); !error.isEmpty())
            return error;
    }
    return {};
}

QString exportDrawing(const model::Drawing& drawing, const QString& path, const ExportOptions& options)
{
    model::FileBatch batch;
    if (const QString error = exportDrawing(drawing, path, options, batch); !error.isEmpty())
        return error;
    return batch.commit();
}

QString exportDrawing(const model::Drawing& drawing, const QString& path, const ExportOptions& options,
                      model::FileBatch& batch)
{
    const Format* format = formatFor(path);
    if (!format)
        return failure(path, QStringLiteral("unknown export format (use .svg, .pdf, .eps or .png)"));
    if (const QString error = checkExport(drawing, options); !error.isEmpty())
        return failure(path, error);
    if (const Page page = pageFor(drawing, options);
        format->maxPageSide > 0 && std::max(page.width, page.height) > format->maxPageSide)
        return failure(path, QStringLiteral("the page would be %1 x %2 pt; %3 pages are at most %4 pt a side")
                                 .arg(page.width, 0, 'g', 4)
                                 .arg(page.height, 0, 'g', 4)
                                 .arg(QString::fromLatin1(format->suffix).toUpper())
                                 .arg(format->maxPageSide));

    return batch.write(path, [&](QIODevice& file) { return format->write(drawing, options, file); });
}

bool isExportSuffix(const QString& path)
{
    return formatFor(path) != nullptr;
}

} // namespace vf::render
