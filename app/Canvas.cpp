// The canvas widget: the view (zoom, pan, fit), the newest frame painted with level of detail and
// cached paths, and the pointer's tools (drop, spatter, stylus, text, select, pan, and the
// marbling tools: comb, circular comb, swirl) with the previews they draw (drop or spatter circle,
// trail, text, selection). One file because the tools and the painting share the view's mapping
// and the paint caches they invalidate; the overlays with state of their own are in
// CanvasOverlays, the marbling tools' drags (their geometry, pens and previews) in MarblingDrag.
// The seam for a split is the tools' input handling (the mouse and key events, text entry,
// picking), which could become a controller that calls the view's public mapping.
#include "app/Canvas.h"

#include "app/CanvasOverlays.h"
#include "render/Exporter.h"

#include <QAction>
#include <QApplication>
#include <QGestureEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QNativeGestureEvent>
#include <QPainter>
#include <QPinchGesture>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace vf::app {
namespace {

constexpr double kFitMargin = 16.0;         // logical pixels around the fitted canvas
constexpr double kWheelStepFactor = 1.189;  // 2^(1/4): four wheel notches double the zoom
constexpr double kButtonStepFactor = 1.414; // zoomIn/zoomOut: two steps double it
// Zoom limits in pixels across the canvas's longer side: never smaller than a thumbnail, never so
// large that device coordinates leave the range the raster engine handles exactly.
constexpr double kMinPixelsAcross = 16.0;
constexpr double kMaxPixelsAcross = 1e6;
constexpr std::size_t kMaxVertexDots = 20000;
constexpr double kClickSpatterSpread = 0.15;  // of the canvas width, for a click of the Spatter tool  // more dots than this merge into the contour line
constexpr double kPointsPerInch = 72.0;
constexpr qint64 kFpsWindowMs = 1000;

QCursor stylusCursor()
{
    // A ring with a light halo, readable on dark and light ink alike.
    QPixmap ring(17, 17);
    ring.fill(Qt::transparent);
    QPainter painter(&ring);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(Qt::white, 3.0));
    painter.drawEllipse(QPointF(8.5, 8.5), 5.0, 5.0);
    painter.setPen(QPen(Qt::black, 1.2));
    painter.drawEllipse(QPointF(8.5, 8.5), 5.0, 5.0);
    painter.end();
    return QCursor(ring, 8, 8);
}

double length(QPointF v) { return std::hypot(v.x(), v.y()); }

} // namespace

Canvas::Canvas(QWidget* parent) : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);  // paintEvent covers every pixel
    setFocusPolicy(Qt::StrongFocus);         // for space+drag and the zoom shortcuts
#ifndef Q_OS_MACOS
    // macOS delivers trackpad pinches as native zoom gestures (handled in event()); grabbing the
    // pinch gesture there as well would apply each pinch twice.
    grabGesture(Qt::PinchGesture);
#endif
    const auto addViewAction = [this](const QString& text, const QKeySequence& keys, void (Canvas::*slot)()) {
        auto* action = new QAction(text, this);
        action->setShortcut(keys);
        action->setShortcutContext(Qt::WidgetShortcut);
        connect(action, &QAction::triggered, this, slot);
        addAction(action);
    };
    addViewAction(tr("Zoom In"), QKeySequence::ZoomIn, &Canvas::zoomIn);
    addViewAction(tr("Zoom Out"), QKeySequence::ZoomOut, &Canvas::zoomOut);
    addViewAction(tr("Fit to Window"), QKeySequence(Qt::CTRL | Qt::Key_0), &Canvas::fitToWindow);
    addViewAction(tr("Actual Size"), QKeySequence(Qt::CTRL | Qt::Key_1), &Canvas::actualSize);

    m_clock.start();
    m_fpsTimer.setInterval(int(kFpsWindowMs));
    connect(&m_fpsTimer, &QTimer::timeout, this, &Canvas::publishFps);
    m_fpsTimer.start();
    updateCursor();
}

// ---- Content ------------------------------------------------------------------------------------

void Canvas::setFrame(std::shared_ptr<const model::Frame> frame)
{
    const QSizeF before = canvasSize();
    const bool first = !m_frame;
    m_frame = std::move(frame);
    if (m_fitting && (first || canvasSize() != before))
        fitToWindow();
    invalidateInk();
}

void Canvas::setRegions(model::RegionTable regions)
{
    m_regions = std::move(regions);
    invalidateInk();
}

void Canvas::setBackground(QColor color)
{
    m_background = color;
    invalidateInk();
}

QSizeF Canvas::canvasSize() const
{
    // A degenerate size would make every view transform infinite; show a unit canvas instead.
    const bool usable = m_frame && m_frame->width > 0.0 && m_frame->height > 0.0
                     && std::isfinite(m_frame->width) && std::isfinite(m_frame->height);
    return usable ? QSizeF(m_frame->width, m_frame->height) : QSizeF(1.0, 1.0);
}

// ---- View ---------------------------------------------------------------------------------------

QPointF Canvas::mapToCanvas(QPointF widgetPos) const
{
    return (widgetPos - m_offset) / m_scale;
}

QPointF Canvas::mapFromCanvas(QPointF canvasPos) const
{
    return canvasPos * m_scale + m_offset;
}

void Canvas::setView(double scale, QPointF offset)
{
    const QSizeF canvas = canvasSize();
    const double across = std::max(canvas.width(), canvas.height());
    scale = std::clamp(scale, kMinPixelsAcross / across, kMaxPixelsAcross / across);
    const bool zoomed = scale != m_scale;
    m_scale = scale;
    m_offset = offset;
    invalidateInk();
    if (zoomed)
        emit zoomChanged(m_scale);
}

void Canvas::zoomAbout(QPointF widgetPos, double factor)
{
    const QPointF fixed = mapToCanvas(widgetPos);
    m_fitting = false;
    setView(m_scale * factor, m_offset);
    // Wherever the clamped scale landed, the canvas point under the cursor stays under it.
    setView(m_scale, widgetPos - fixed * m_scale);
}

void Canvas::zoomIn() { zoomAbout(QRectF(rect()).center(), kButtonStepFactor); }
void Canvas::zoomOut() { zoomAbout(QRectF(rect()).center(), 1.0 / kButtonStepFactor); }

void Canvas::fitToWindow()
{
    m_fitting = true;
    const QSizeF canvas = canvasSize();
    const double margin = std::min(kFitMargin, 0.05 * std::min(width(), height()));
    const double scale = std::min((width() - 2 * margin) / canvas.width(), (height() - 2 * margin) / canvas.height());
    if (scale <= 0.0)
        return;  // not laid out yet: the resize will fit
    const QPointF centre = QRectF(rect()).center();
    setView(scale, centre - QPointF(canvas.width(), canvas.height()) * scale / 2);
}

void Canvas::actualSize()
{
    // The exported page's size (its points per canvas width) at the screen's logical resolution.
    const double pixelsPerUnit = render::ExportOptions{}.pageWidth / canvasSize().width()
                               * logicalDpiX() / kPointsPerInch;
    zoomAbout(QRectF(rect()).center(), pixelsPerUnit / m_scale);
}

void Canvas::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    if (m_fitting)
        fitToWindow();
}

void Canvas::wheelEvent(QWheelEvent* event)
{
    const QPoint delta = event->angleDelta();
    const int notches120 = delta.y() != 0 ? delta.y() : delta.x();
    if (notches120 == 0) {
        event->ignore();
        return;
    }
    zoomAbout(event->position(), std::pow(kWheelStepFactor, notches120 / 120.0));
    event->accept();
}

bool Canvas::event(QEvent* event)
{
    // Typed text takes its keys before the window's shortcuts (T, S, Space...) would.
    if (event->type() == QEvent::ShortcutOverride && m_textEntry.takes(*static_cast<QKeyEvent*>(event))) {
        event->accept();
        return true;
    }
    if (event->type() == QEvent::NativeGesture) {
        const auto* gesture = static_cast<QNativeGestureEvent*>(event);
        if (gesture->gestureType() == Qt::ZoomNativeGesture) {
            zoomAbout(gesture->position(), 1.0 + gesture->value());
            return true;
        }
    }
    if (event->type() == QEvent::Gesture && handleGesture(static_cast<QGestureEvent*>(event)))
        return true;
    return QWidget::event(event);
}

bool Canvas::handleGesture(QGestureEvent* event)
{
    auto* pinch = static_cast<QPinchGesture*>(event->gesture(Qt::PinchGesture));
    if (!pinch)
        return false;
    if (pinch->changeFlags() & QPinchGesture::ScaleFactorChanged)
        zoomAbout(mapFromGlobal(pinch->centerPoint()), pinch->scaleFactor());
    event->accept(pinch);
    return true;
}

// ---- Painting -----------------------------------------------------------------------------------

void Canvas::paintEvent(QPaintEvent*)
{
    const double dpr = devicePixelRatioF();
    const QSize deviceSize = (QSizeF(size()) * dpr).toSize();
    if (!m_inkValid || m_ink.size() != deviceSize || m_ink.devicePixelRatio() != dpr)
        paintInk(deviceSize, dpr);
    QPainter painter(this);
    painter.drawImage(QPointF(0, 0), m_ink);
    if (m_frame)
        paintOverlays(painter, dpr);
    countPaintedFrame();
}

void Canvas::invalidateInk()
{
    m_inkValid = false;
    update();
}

void Canvas::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::PaletteChange)
        invalidateInk();  // the surround's colour
    QWidget::changeEvent(event);
}

PixelMapping Canvas::toDevice(double dpr) const
{
    return {m_scale * dpr, m_offset.x() * dpr, m_offset.y() * dpr};
}

void Canvas::paintInk(QSize deviceSize, double dpr)
{
    if (m_ink.size() != deviceSize)
        m_ink = QImage(deviceSize, QImage::Format_RGB32);  // opaque: blitted as a plain copy
    m_ink.setDevicePixelRatio(dpr);
    m_inkValid = true;
    QPainter painter(&m_ink);
    painter.fillRect(rect(), palette().color(QPalette::Mid));
    if (!m_frame)
        return;
    const QRectF page(mapFromCanvas({0.0, 0.0}), mapFromCanvas({canvasSize().width(), canvasSize().height()}));
    painter.fillRect(page, m_background);
    painter.setClipRect(page);  // as exported: nothing outside the canvas

    // From here on in device pixels, the unit of the level of detail.
    m_paths.setView(m_frame, toDevice(dpr), visibleDeviceRect(dpr));
    painter.setTransform(QTransform::fromScale(1.0 / dpr, 1.0 / dpr).translate(m_paths.shift().x(), m_paths.shift().y()));
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(Qt::NoPen);
    for (const model::RegionLook& look : m_regions)
        if (isShown(look))
            painter.fillPath(m_paths.region(std::size_t(look.simIndex)), look.color);
}

QRectF Canvas::visibleDeviceRect(double dpr) const
{
    // One pixel more on each side: antialiasing reaches half a pixel out.
    return QRectF(0, 0, width() * dpr, height() * dpr).adjusted(-1, -1, 1, 1);
}

bool Canvas::isShown(const model::RegionLook& look) const
{
    return look.visible && look.simIndex >= 0 && std::size_t(look.simIndex) < m_frame->regions.size();
}

void Canvas::paintOverlays(QPainter& painter, double dpr)
{
    const PixelMapping mapping = toDevice(dpr);
    const QRectF visible = visibleDeviceRect(dpr);
    m_paths.setView(m_frame, mapping, visible);
    painter.setTransform(QTransform::fromScale(1.0 / dpr, 1.0 / dpr));
    painter.setRenderHint(QPainter::Antialiasing);
    if (m_showGrid && m_frame->velocity)
        paintGrid(painter, *m_frame->velocity, mapping, visible, dpr);
    if (m_showVelocity && m_frame->velocity)
        paintVelocity(painter, *m_frame->velocity, mapping, visible, dpr);
    if (m_showVertices) {
        std::vector<const QPolygonF*> dots;
        std::size_t count = 0;
        for (const model::RegionLook& look : m_regions) {
            if (!isShown(look))
                continue;
            const std::optional<QPolygonF>& region = m_paths.vertices(std::size_t(look.simIndex), kMaxVertexDots);
            count += region ? std::size_t(region->size()) : kMaxVertexDots + 1;
            dots.push_back(region ? &*region : nullptr);
        }
        if (count <= kMaxVertexDots)
            for (const QPolygonF* region : dots)
                paintVertexDots(painter, *region, dpr);
    }
    paintSelection(painter, dpr);
    paintTrail(painter);
    paintTextEntry(painter);
    if (m_drag == Drag::Marbling) {
        painter.resetTransform();
        m_marbling.paint(painter, QTransform(m_scale, 0.0, 0.0, m_scale, m_offset.x(), m_offset.y()),
                         palette().color(QPalette::Highlight));
    }
    if (m_drag == Drag::Drop && m_dropPreview > 0.0) {
        painter.resetTransform();
        painter.setPen(QPen(palette().color(QPalette::Highlight), 1.5, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(mapFromCanvas(m_dropCenter), m_dropPreview * m_scale, m_dropPreview * m_scale);
    }
}

// The stroke being drawn, as wide as the stylus reaches: a translucent band, so that the ink it
// pushes shows through it, with the pen's own path along its middle.
void Canvas::paintTrail(QPainter& painter)
{
    if (m_trail.size() < 2)
        return;
    painter.resetTransform();
    QPolygonF path;
    for (const QPointF& p : m_trail)
        path << mapFromCanvas(p);
    QColor band = palette().color(QPalette::Highlight);
    band.setAlphaF(0.25);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(band, 2.0 * m_stylusRadius * m_scale, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.drawPolyline(path);
    painter.setPen(QPen(palette().color(QPalette::Highlight), 1.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.drawPolyline(path);
}

// The text being typed: its ink to come, translucent, with a caret after it as tall as its letters.
void Canvas::paintTextEntry(QPainter& painter)
{
    if (!m_textEntry.isActive())
        return;
    painter.resetTransform();
    const QTransform toWidget(m_scale, 0.0, 0.0, m_scale, m_offset.x(), m_offset.y());
    QColor fill = m_textColor;
    fill.setAlphaF(0.6 * fill.alphaF());
    const QColor highlight = palette().color(QPalette::Highlight);
    painter.setPen(QPen(highlight, 1.0));
    painter.setBrush(fill);
    painter.drawPath(toWidget.map(m_textPreview));
    const QPointF start = m_textEntry.baselineStart();
    const double caretX = m_textPreview.isEmpty() ? start.x() : std::max(start.x(), m_textPreview.boundingRect().right());
    painter.setPen(QPen(highlight, 2.0));
    painter.drawLine(mapFromCanvas({caretX, start.y()}), mapFromCanvas({caretX, start.y() - m_textHeight}));
}

void Canvas::setTextPreview(const QPainterPath& outlines, double letterHeight, const QColor& color)
{
    m_textPreview = outlines;
    m_textHeight = letterHeight;
    m_textColor = color;
    update();
}

void Canvas::finishText(bool commit)
{
    if (!m_textEntry.isActive())
        return;
    const QPointF at = m_textEntry.baselineStart();
    const QString text = m_textEntry.text();
    m_textEntry.end();
    m_textPreview.clear();
    update();
    if (commit)
        emit textCommitted(at, text);
}

// The selected region's outline: a light line under a dark one, so that it shows on any ink and
// any background.
void Canvas::paintSelection(QPainter& painter, double dpr)
{
    const auto selected = std::find_if(m_regions.begin(), m_regions.end(),
                                       [this](const model::RegionLook& look) { return look.simIndex == m_selected; });
    if (selected == m_regions.end() || !isShown(*selected))
        return;
    const QPainterPath& outline = m_paths.region(std::size_t(m_selected));
    painter.save();
    painter.translate(m_paths.shift());
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(Qt::white, 3.0 * dpr));
    painter.drawPath(outline);
    painter.setPen(QPen(palette().color(QPalette::Highlight).darker(130), 1.5 * dpr));
    painter.drawPath(outline);
    painter.restore();
}

void Canvas::setSelectedRegion(int simIndex)
{
    if (simIndex == m_selected)
        return;
    m_selected = simIndex;
    update();
}

int Canvas::regionAt(QPointF canvasPos) const
{
    if (!m_frame)
        return -1;
    const sim::Vec2 p(canvasPos.x(), canvasPos.y());
    for (auto look = m_regions.rbegin(); look != m_regions.rend(); ++look) {
        if (!isShown(*look))
            continue;
        // Even-odd, as the region is filled: inside an odd number of its contours.
        bool inside = false;
        for (const sim::Polygon& contour : m_frame->regions[std::size_t(look->simIndex)])
            inside ^= sim::windingNumber(contour, p) != 0;
        if (inside)
            return look->simIndex;
    }
    return -1;
}

void Canvas::setShowVertices(bool show)
{
    m_showVertices = show;
    update();
}

void Canvas::setShowVelocity(bool show)
{
    m_showVelocity = show;
    update();
}

void Canvas::setShowGrid(bool show)
{
    m_showGrid = show;
    update();
}

// ---- Display FPS --------------------------------------------------------------------------------

void Canvas::countPaintedFrame()
{
    const qint64 now = m_clock.elapsed();
    m_paintTimes.push_back(now);
    while (m_paintTimes.front() <= now - kFpsWindowMs)
        m_paintTimes.pop_front();
}

int Canvas::displayFps() const
{
    const qint64 since = m_clock.elapsed() - kFpsWindowMs;
    return int(m_paintTimes.end() - std::upper_bound(m_paintTimes.begin(), m_paintTimes.end(), since));
}

void Canvas::publishFps()
{
    const int fps = displayFps();
    if (fps == m_publishedFps)
        return;
    m_publishedFps = fps;
    emit displayFpsChanged(fps);
}

// ---- Tools --------------------------------------------------------------------------------------

void Canvas::setStylusRadius(double radius)
{
    m_stylusRadius = radius;
}

void Canvas::setTool(Tool tool)
{
    if (tool != m_tool)
        finishText(true);
    m_tool = tool;
    updateCursor();
}

void Canvas::updateCursor()
{
    if (m_drag == Drag::Pan)
        setCursor(Qt::ClosedHandCursor);
    else if (m_spaceHeld || m_tool == Tool::Pan)
        setCursor(Qt::OpenHandCursor);
    else if (m_tool == Tool::Stylus)
        setCursor(stylusCursor());
    else if (m_tool == Tool::Text)
        setCursor(Qt::IBeamCursor);
    else if (m_tool == Tool::Select)
        setCursor(Qt::PointingHandCursor);
    else
        setCursor(Qt::CrossCursor);
}

void Canvas::mousePressEvent(QMouseEvent* event)
{
    if (m_drag != Drag::None)
        return;  // another button during a drag: the drag goes on
    const QPointF pos = event->position();
    m_pressPos = m_lastPos = pos;
    if (event->button() == Qt::MiddleButton
        || (event->button() == Qt::LeftButton && (m_spaceHeld || m_tool == Tool::Pan))) {
        m_drag = Drag::Pan;
        updateCursor();
        return;
    }
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    const QPointF at = mapToCanvas(pos);
    switch (m_tool) {
    case Tool::Select:
        emit regionClicked(regionAt(at));
        break;
    case Tool::Drop:
    case Tool::Spatter:
        m_drag = Drag::Drop;
        m_dropCenter = at;
        m_dropPreview = 0.0;
        break;
    case Tool::Comb:
    case Tool::CircularComb:
    case Tool::Swirl:
        m_drag = Drag::Marbling;
        m_marbling.begin(m_tool, at, QApplication::startDragDistance() / m_scale);
        m_marblingInWater = false;
        m_lastTime = qint64(event->timestamp());
        break;
    case Tool::Stylus:
        m_drag = Drag::Stroke;
        m_trail = {at};
        m_strokeLast = at;
        m_lastTime = qint64(event->timestamp());
        emit strokeStarted(at);
        break;
    case Tool::Text:
        finishText(true);  // a click elsewhere sets what was typed, and starts anew there
        m_textEntry.begin(at);
        update();
        emit textEdited();
        break;
    case Tool::Pan:
        break;  // handled above
    }
}

void Canvas::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF pos = event->position();
    switch (m_drag) {
    case Drag::None:
        return;
    case Drag::Pan:
        m_fitting = false;
        setView(m_scale, m_offset + (pos - m_lastPos));
        m_lastPos = pos;
        return;
    case Drag::Drop:
        // A press that has not moved past the drag distance is still a click.
        m_dropPreview = length(pos - m_pressPos) >= QApplication::startDragDistance()
                          ? length(mapToCanvas(pos) - m_dropCenter) : 0.0;
        update();
        return;
    case Drag::Marbling:
        m_marbling.moveTo(mapToCanvas(pos));
        if (m_marbling.inWater())
            movePens(qint64(event->timestamp()));
        update();
        return;
    case Drag::Stroke: {
        const qint64 time = qint64(event->timestamp());
        // Events within the same millisecond merge into the next segment: a zero duration would
        // make the pen infinitely fast.
        if (time <= m_lastTime)
            return;
        const QPointF at = mapToCanvas(pos);
        emit strokeMoved(m_strokeLast, at, double(time - m_lastTime) / 1000.0);
        m_strokeLast = at;
        m_lastTime = time;
        m_trail << at;
        update();
        return;
    }
    }
}

void Canvas::mouseReleaseEvent(QMouseEvent* event)
{
    const QPointF pos = event->position();
    const Drag drag = m_drag;
    m_drag = Drag::None;
    switch (drag) {
    case Drag::None:
        return;
    case Drag::Pan:
        updateCursor();
        return;
    case Drag::Drop: {
        const bool dragged = length(pos - m_pressPos) >= QApplication::startDragDistance();
        const double clicked = (m_tool == Tool::Spatter ? kClickSpatterSpread : m_clickDropRadius) * canvasSize().width();
        const double radius = dragged ? length(mapToCanvas(pos) - m_dropCenter) : clicked;
        m_dropPreview = 0.0;
        update();
        if (m_tool == Tool::Spatter)
            emit spatterRequested(m_dropCenter, radius);
        else
            emit dropRequested(m_dropCenter, radius);
        return;
    }
    case Drag::Marbling:
        m_marbling.moveTo(mapToCanvas(pos));
        update();
        if (!m_marbling.inWater()) {
            if (m_marbling.acts())
                emit toolApplied(m_marbling.tool());
            return;
        }
        movePens(std::max(m_lastTime + 1, qint64(event->timestamp())));
        if (m_marblingInWater)
            emit strokeFinished();
        return;
    case Drag::Stroke: {
        const QPointF at = mapToCanvas(pos);
        if (at != m_strokeLast) {
            const qint64 elapsed = std::max<qint64>(1, qint64(event->timestamp()) - m_lastTime);
            emit strokeMoved(m_strokeLast, at, double(elapsed) / 1000.0);
        }
        m_trail.clear();
        update();
        emit strokeFinished();
        return;
    }
    }
}

// A marbling tool in the water: its pens move as far as the drag has gone, over the time since
// they last moved (events within the same millisecond wait for the next, as the stylus's do).
void Canvas::movePens(qint64 time)
{
    if (time <= m_lastTime)
        return;
    const std::vector<sim::StylusSegment> pens = m_marbling.pens(double(time - m_lastTime) / 1000.0, m_stylusRadius);
    if (pens.empty())
        return;
    m_lastTime = time;
    if (!m_marblingInWater) {
        m_marblingInWater = true;
        emit strokeStarted(mapToCanvas(m_pressPos));
    }
    emit pensMoved(pens);
}

void Canvas::keyPressEvent(QKeyEvent* event)
{
    switch (m_textEntry.press(*event)) {
    case TextEntry::Outcome::Edited:
        update();
        emit textEdited();
        return;
    case TextEntry::Outcome::Committed:
        finishText(true);
        return;
    case TextEntry::Outcome::Cancelled:
        finishText(false);
        return;
    case TextEntry::Outcome::Ignored:
        break;
    }
    if (event->key() == Qt::Key_Space) {
        if (!event->isAutoRepeat()) {
            m_spaceHeld = true;
            updateCursor();
        }
        return;
    }
    QWidget::keyPressEvent(event);
}

void Canvas::keyReleaseEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Space) {
        if (!event->isAutoRepeat()) {
            m_spaceHeld = false;
            updateCursor();
        }
        return;
    }
    QWidget::keyReleaseEvent(event);
}

} // namespace vf::app
