// PNG through QPainter on a QImage. Raster painting without text needs no QGuiApplication, so the
// headless command line can use it with a QCoreApplication or none at all.
#include "render/Writers.h"

#include "model/AtomicFile.h"
#include "render/Page.h"
#include "render/PathEmitter.h"

#include <QBuffer>
#include <QImage>
#include <QImageWriter>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <climits>
#include <cmath>

namespace vf::render {
namespace {

constexpr double kPointsPerInch = 72.0;
constexpr double kMetresPerInch = 0.0254;

class PainterPathSink final : public PathSink {
public:
    explicit PainterPathSink(QPainterPath& path) : m_path(path) {}

    void moveTo(sim::Vec2 point) override { m_path.moveTo(point.x, point.y); }
    void lineTo(sim::Vec2 point) override { m_path.lineTo(point.x, point.y); }
    void cubicTo(sim::Vec2 control1, sim::Vec2 control2, sim::Vec2 end) override
    {
        m_path.cubicTo(control1.x, control1.y, control2.x, control2.y, end.x, end.y);
    }
    void closePath() override { m_path.closeSubpath(); }

private:
    QPainterPath& m_path;
};

QSize pixelSize(const model::Drawing& drawing, const ExportOptions& options)
{
    const RasterSize size = pngPixels(drawing, options);
    // Beyond int range QImage cannot even be asked; report it as too large below.
    if (size.width > INT_MAX || size.height > INT_MAX)
        return {};
    return {static_cast<int>(size.width), static_cast<int>(size.height)};
}

void paint(QImage& image, const model::Drawing& drawing, const ExportOptions& options)
{
    // The canvas's pixels: the image less whole-pixel margins (none when the page has the
    // canvas's aspect), both axes stretched to them, so the canvas covers them exactly. QPainter
    // maps to pixels in doubles before it rasterises, so canvas units lose nothing here (unlike cairo).
    const Page page = pageFor(drawing, options);
    const double pixelsPerPoint = options.dpi / kPointsPerInch;
    const double left = std::round(page.left * pixelsPerPoint), top = std::round(page.top * pixelsPerPoint);
    const QRectF canvas(left, top, image.width() - 2 * left, image.height() - 2 * top);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    if (options.background)
        painter.fillRect(canvas, drawing.background);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(Qt::NoPen);
    painter.translate(canvas.topLeft());
    painter.scale(canvas.width() / drawing.width, canvas.height() / drawing.height);
    const PathStyle style = pathStyle(drawing, options);
    for (const model::DrawnRegion& region : drawing.regions) {
        if (!region.visible)
            continue;
        QPainterPath path;
        path.setFillRule(Qt::OddEvenFill);
        PainterPathSink sink(path);
        emitRegion(region, style, sink);
        painter.fillPath(path, region.color);
    }
}

} // namespace

RasterSize pngPixels(const model::Drawing& drawing, const ExportOptions& options)
{
    const Page page = pageFor(drawing, options);
    const double pixelsPerPoint = options.dpi / kPointsPerInch;
    const auto pixels = [&](double points) { return std::max(1.0, std::round(points * pixelsPerPoint)); };
    return {pixels(page.width), pixels(page.height)};
}

QImage paintedImage(const model::Drawing& drawing, const ExportOptions& options)
{
    QImage image(pixelSize(drawing, options), QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        return image;
    const int dotsPerMetre = static_cast<int>(std::lround(options.dpi / kMetresPerInch));
    image.setDotsPerMeterX(dotsPerMetre);
    image.setDotsPerMeterY(dotsPerMetre);
    paint(image, drawing, options);
    return image;
}

QString writePng(const model::Drawing& drawing, const ExportOptions& options, QIODevice& out)
{
    const QImage image = paintedImage(drawing, options);
    if (image.isNull())
        return QStringLiteral("image too large to allocate (%1 dpi)").arg(options.dpi);
    // Encoded in memory first: libpng reports a failed write by longjmp through Qt's encoder,
    // which leaks and loses the reason. The compressed file is small next to the image itself.
    QBuffer encoded;
    encoded.open(QIODevice::WriteOnly);
    QImageWriter writer(&encoded, "png");
    if (!writer.write(image))
        return QStringLiteral("PNG: %1").arg(writer.errorString());
    return model::writeAll(out, encoded.data());
}

} // namespace vf::render
