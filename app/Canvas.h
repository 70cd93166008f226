#pragma once
// The canvas widget: draws the newest frame of the simulation with the document's region looks,
// lets the user zoom and pan, and turns pointer input into tool requests in canvas units (origin
// top-left, y down). It never touches the simulation: the main window connects its signals.
#include "app/MarblingDrag.h"
#include "app/RegionPaths.h"
#include "app/TextEntry.h"
#include "app/Tool.h"
#include "model/Frame.h"
#include "model/Regions.h"

#include <QColor>
#include <QElapsedTimer>
#include <QImage>
#include <QPainterPath>
#include <QPointF>
#include <QPolygonF>
#include <QTimer>
#include <QWidget>

#include <deque>
#include <memory>

class QGestureEvent;
class QPainter;
class QNativeGestureEvent;

namespace vf::app {

class Canvas : public QWidget {
    Q_OBJECT
    // The radius of a drop placed by a click (no drag), as a fraction of the canvas width.
    Q_PROPERTY(double clickDropRadius READ clickDropRadius WRITE setClickDropRadius)

public:
    explicit Canvas(QWidget* parent = nullptr);

    void setFrame(std::shared_ptr<const model::Frame> frame);
    void setRegions(model::RegionTable regions);
    void setBackground(QColor color);
    void setTool(Tool tool);
    Tool tool() const { return m_tool; }
    // The region outlined as selected, by simulation index; -1: none.
    void setSelectedRegion(int simIndex);
    int selectedRegion() const { return m_selected; }
    // The topmost shown region whose ink covers `canvasPos`, by simulation index; -1: none.
    int regionAt(QPointF canvasPos) const;

    // The stylus's radius in canvas units: the width of the trail a stroke leaves while drawn.
    void setStylusRadius(double radius);
    // The text being typed (the Text tool), and what its ink will be, in canvas units: the glyph
    // outlines (filled even-odd) and the letters' height, shown until Enter or Esc.
    const TextEntry& textEntry() const { return m_textEntry; }
    void setTextPreview(const QPainterPath& outlines, double letterHeight, const QColor& color);

    double clickDropRadius() const { return m_clickDropRadius; }
    // The options of the Comb, Circular comb or Swirl tool (MarblingToolBar::options), which its
    // drags preview and make.
    void setToolOptions(const model::Stroke& options) { m_marbling.setOptions(options); }
    void setClickDropRadius(double fractionOfWidth) { m_clickDropRadius = fractionOfWidth; }

    // Widget (logical pixel) position ↔ canvas units.
    QPointF mapToCanvas(QPointF widgetPos) const;
    QPointF mapFromCanvas(QPointF canvasPos) const;
    double zoom() const { return m_scale; }  // logical pixels per canvas unit

    // Frames painted over the last second.
    int displayFps() const;

    QSize sizeHint() const override { return {800, 600}; }

public slots:
    void zoomIn();
    void zoomOut();
    void fitToWindow();  // and keep fitting on resize until the user zooms or pans
    void actualSize();   // the canvas at the size of its exported page (render::ExportOptions)
    void setShowVertices(bool show);
    void setShowVelocity(bool show);
    void setShowGrid(bool show);

signals:
    void dropRequested(QPointF center, double radius);
    // The Spatter tool: drops within `spread` of `center` (dragged out as a drop's radius is).
    void spatterRequested(QPointF center, double spread);
    // The Comb, Circular comb or Swirl tool dragged, exact: the tool as dragged (MarblingDrag::tool).
    void toolApplied(const vf::model::Stroke& tool);
    // A stroke through the water: the Stylus tool's, or a marbling tool's in the water (its first
    // pens about to move).
    void strokeStarted(QPointF at);
    // The Stylus tool. `seconds`: between the two pointer events, so distance / seconds is the pen's speed.
    void strokeMoved(QPointF from, QPointF to, double seconds);
    // A marbling tool in the water: its pens' moves since the last pointer event.
    void pensMoved(const std::vector<vf::sim::StylusSegment>& pens);
    void strokeFinished();
    // The text being typed began or changed: textEntry() has it.
    void textEdited();
    void textCommitted(QPointF baselineStart, const QString& text);  // Enter (or a click elsewhere)
    // The Select tool clicked: the region there (regionAt), or -1 for bare water.
    void regionClicked(int simIndex);
    void displayFpsChanged(int fps);
    void zoomChanged(double zoom);

protected:
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;

private:
    enum class Drag { None, Pan, Drop, Stroke, Marbling };

    QSizeF canvasSize() const;
    PixelMapping toDevice(double dpr) const;
    QRectF visibleDeviceRect(double dpr) const;
    bool isShown(const model::RegionLook& look) const;
    void invalidateInk();
    void paintInk(QSize deviceSize, double dpr);
    void paintOverlays(QPainter& painter, double dpr);
    void paintSelection(QPainter& painter, double dpr);
    void paintTrail(QPainter& painter);
    void paintTextEntry(QPainter& painter);
    void movePens(qint64 time);
    void finishText(bool commit);
    void zoomAbout(QPointF widgetPos, double factor);
    void setView(double scale, QPointF offset);
    void updateCursor();
    void countPaintedFrame();
    void publishFps();
    bool handleGesture(QGestureEvent* event);

    std::shared_ptr<const model::Frame> m_frame;
    model::RegionTable m_regions;
    QColor m_background = Qt::white;
    RegionPaths m_paths;
    // The regions as last painted, device pixels: a repaint that changes none of what they depend
    // on (an overlay, the drop preview, an expose) only copies it.
    QImage m_ink;
    bool m_inkValid = false;

    // The view: widget position = canvas position · m_scale + m_offset (logical pixels).
    double m_scale = 1.0;
    QPointF m_offset;
    bool m_fitting = true;  // fit again on resize and when the canvas size changes

    bool m_showVertices = false;
    bool m_showVelocity = false;
    bool m_showGrid = false;

    Tool m_tool = Tool::Drop;
    int m_selected = -1;
    double m_clickDropRadius = 0.05;
    bool m_spaceHeld = false;
    Drag m_drag = Drag::None;
    QPointF m_pressPos;      // widget pixels
    QPointF m_lastPos;       // widget pixels: the pan's last point
    QPolygonF m_trail;       // canvas units: the stroke being drawn, from its start
    double m_stylusRadius = 0.03;
    TextEntry m_textEntry;
    QPainterPath m_textPreview;  // canvas units
    double m_textHeight = 0.1;
    QColor m_textColor;
    QPointF m_strokeLast;    // canvas units: where the stroke's last segment ended...
    qint64 m_lastTime = 0;   // ...and when (ms, the pointer event's timestamp)
    QPointF m_dropCenter;    // canvas units
    double m_dropPreview = 0.0;  // canvas units; 0 while the press has not become a drag
    MarblingDrag m_marbling;
    bool m_marblingInWater = false;  // its pens have begun a stroke

    std::deque<qint64> m_paintTimes;  // ms on m_clock, the last second's
    QElapsedTimer m_clock;
    QTimer m_fpsTimer;
    int m_publishedFps = 0;
};

} // namespace vf::app
