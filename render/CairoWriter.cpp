// PDF and EPS through Cairo, streamed into the caller's device; an animation as a PDF of a page a frame.
//
// Cairo stores path coordinates in 24.8 fixed point. Drawing in canvas units through a scaling CTM
// would quantise every vertex to 1/256 of the canvas, so we scale to page points ourselves: the
// quantum is then 1/256 pt (0.0014 mm), far below anything visible or printable. The exact
// geometry is the SVG's job; PDF/EPS are for viewing and print.
//
// PostScript has no transparency: for translucent regions cairo flattens the colour against what
// lies below and, where needed, falls back to an image at its fallback resolution (300 ppi).
#include "render/Writers.h"

#include "model/AtomicFile.h"
#include "render/AnimationWriters.h"
#include "render/EpsBoundingBox.h"
#include "render/Page.h"
#include "render/PathEmitter.h"

#include <QColor>

#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cairo.h>

#include <cmath>
#include <memory>

namespace vf::render {
namespace {

struct SurfaceDeleter {
    void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
struct ContextDeleter {
    void operator()(cairo_t* context) const { cairo_destroy(context); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

// Cairo's write callback gets a status back only, so the reason is kept here for the message.
struct DeviceStream {
    QIODevice& device;
    QString error;

    static cairo_status_t write(void* closure, const unsigned char* data, unsigned int length)
    {
        auto* self = static_cast<DeviceStream*>(closure);
        self->error = model::writeAll(self->device, reinterpret_cast<const char*>(data), qint64(length));
        return self->error.isEmpty() ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
    }
};

class CairoPathSink final : public PathSink {
public:
    CairoPathSink(cairo_t* context, double scale) : m_context(context), m_scale(scale) {}

    void moveTo(sim::Vec2 point) override { cairo_move_to(m_context, x(point), y(point)); }
    void lineTo(sim::Vec2 point) override { cairo_line_to(m_context, x(point), y(point)); }
    void cubicTo(sim::Vec2 control1, sim::Vec2 control2, sim::Vec2 end) override
    {
        cairo_curve_to(m_context, x(control1), y(control1), x(control2), y(control2), x(end), y(end));
    }
    void closePath() override { cairo_close_path(m_context); }

private:
    double x(sim::Vec2 point) const { return point.x * m_scale; }
    double y(sim::Vec2 point) const { return point.y * m_scale; }

    cairo_t* m_context;
    double m_scale;
};

void setSource(cairo_t* context, const QColor& color)
{
    cairo_set_source_rgba(context, color.redF(), color.greenF(), color.blueF(), color.alphaF());
}

void draw(cairo_t* context, const model::Drawing& drawing, const ExportOptions& options)
{
    const Page page = pageFor(drawing, options);
    cairo_translate(context, page.left, page.top);
    if (options.background) {
        setSource(context, drawing.background);
        cairo_rectangle(context, 0, 0, drawing.width * page.pointsPerUnit, drawing.height * page.pointsPerUnit);
        cairo_fill(context);
    }
    cairo_set_fill_rule(context, CAIRO_FILL_RULE_EVEN_ODD);
    const PathStyle style = pathStyle(drawing, options);
    CairoPathSink sink(context, page.pointsPerUnit);
    for (const model::DrawnRegion& region : drawing.regions) {
        if (!region.visible)
            continue;
        cairo_new_path(context);
        emitRegion(region, style, sink);
        setSource(context, region.color);
        cairo_fill(context);
    }
}

// writeError: what the stream said when it failed (status CAIRO_STATUS_WRITE_ERROR).
QString describe(cairo_status_t status, const QString& writeError)
{
    if (status == CAIRO_STATUS_WRITE_ERROR)
        return writeError;
    return QStringLiteral("cairo: %1").arg(QString::fromUtf8(cairo_status_to_string(status)));
}

// Draws, then finishes the surface, which is when cairo writes (most of) the file.
QString render(cairo_surface_t* surface, const model::Drawing& drawing, const ExportOptions& options,
               const QString& writeError)
{
    if (const cairo_status_t status = cairo_surface_status(surface))
        return describe(status, writeError);
    {
        const ContextPtr context(cairo_create(surface));
        draw(context.get(), drawing, options);
        if (const cairo_status_t status = cairo_status(context.get()))
            return describe(status, writeError);
    }
    cairo_surface_finish(surface);
    if (const cairo_status_t status = cairo_surface_status(surface))
        return describe(status, writeError);
    return {};
}

} // namespace

QString writePdf(const model::Drawing& drawing, const ExportOptions& options, QIODevice& out)
{
    const Page page = pageFor(drawing, options);
    DeviceStream stream{out, {}};
    const SurfacePtr surface(cairo_pdf_surface_create_for_stream(DeviceStream::write, &stream, page.width, page.height));
    return render(surface.get(), drawing, options, stream.error);
}

QString writePdfPages(const Animation& animation, const ExportOptions& options, const AnimationProgress& progress,
                      QIODevice& out)
{
    DeviceStream stream{out, {}};
    SurfacePtr surface;
    const QString error = forEachFrame(animation, options, progress, [&](int index, const model::Drawing& frame) {
        if (index == 0) {
            const Page page = pageFor(frame, options);
            surface.reset(cairo_pdf_surface_create_for_stream(DeviceStream::write, &stream, page.width, page.height));
        }
        if (const cairo_status_t status = cairo_surface_status(surface.get()))
            return describe(status, stream.error);
        const ContextPtr context(cairo_create(surface.get()));
        draw(context.get(), frame, options);
        cairo_show_page(context.get());
        const cairo_status_t status = cairo_status(context.get());
        return status ? describe(status, stream.error) : QString();
    });
    if (!error.isEmpty())
        return error;
    cairo_surface_finish(surface.get());
    const cairo_status_t status = cairo_surface_status(surface.get());
    return status ? describe(status, stream.error) : QString();
}

QString writeEps(const model::Drawing& drawing, const ExportOptions& options, QIODevice& out)
{
    const Page page = pageFor(drawing, options);
    // Cairo's EPS places the page below a whole-point top edge (it flips y about ceil(height)), so
    // the box in whole points is the page rounded up.
    EpsBoundingBoxFilter filter(out, static_cast<int>(std::ceil(page.width)),
                                static_cast<int>(std::ceil(page.height)));
    const SurfacePtr surface(
        cairo_ps_surface_create_for_stream(EpsBoundingBoxFilter::write, &filter, page.width, page.height));
    cairo_ps_surface_set_eps(surface.get(), true);
    const QString error = render(surface.get(), drawing, options, filter.error());
    const QString filterError = filter.finish();
    return error.isEmpty() ? filterError : error;
}

} // namespace vf::render
