#pragma once
// A drag of a marbling tool on the canvas (Comb, Circular comb, Swirl), in canvas units. The comb
// is drawn from the press to the pointer. The circular comb and the swirl turn about the press as
// far as the pointer has swept round it, counted from where it first left the press (so a drag
// can go round more than once, and the ink turns the way the pointer went); the swirl reaches as
// far out as the pointer is. The drag gives the exact tool as dragged so far, the pens that push
// the water meanwhile when the tool acts in the water, and its preview.
#include "app/Tool.h"
#include "model/Scene.h"
#include "sim/Stylus.h"

#include <QPointF>

#include <optional>
#include <vector>

class QColor;
class QPainter;
class QTransform;

namespace vf::app {

class MarblingDrag {
public:
    // The options of one of the tools (a CombStroke, CircularCombStroke or SwirlStroke, as
    // MarblingToolBar::options gives them), kept for its next drags.
    void setOptions(const model::Stroke& options);

    // A drag of `tool` (Comb, CircularComb or Swirl) pressed at `at`; the pointer counts as moved
    // once it is more than `still` away from the press (closer, its direction means nothing).
    void begin(Tool tool, QPointF at, double still);
    void moveTo(QPointF at);
    // Whether the tool as dragged does anything: the pointer has left the press (a drag, not a
    // click) and, for the circular comb and the swirl, swept some way round it.
    bool acts() const { return m_moved && (m_tool == Tool::Comb || m_swept != 0.0); }
    bool inWater() const;

    // The exact tool as dragged so far: a CombStroke, CircularCombStroke or SwirlStroke. An exact
    // comb's stroke is shortened so that the ink at its tines moves as far as the pointer did.
    model::Stroke tool() const;
    // In the water: each pen's move since the pens last moved, taking `seconds`, the comb's tines
    // styluses of `radius` (a swirl's rings are as wide as their spacing). Empty while nothing moved.
    std::vector<sim::StylusSegment> pens(double seconds, double radius);

    // Each comb tine's path; or the circular comb's tines' circles (dashed) and the arcs they
    // sweep; or the swirl's circle (dashed) and an arrow along the arc swept at its edge.
    void paint(QPainter& painter, const QTransform& toWidget, const QColor& colour) const;

private:
    // The comb with its tines from the press to the pointer, as the preview and the pens have them.
    model::CombStroke combAsDragged() const;

    Tool m_tool = Tool::Comb;
    model::CombStroke m_comb;
    model::CircularCombStroke m_circularComb;
    model::SwirlStroke m_swirl;

    sim::Vec2 m_press{0.0}, m_at{0.0};
    double m_still = 0.0;
    bool m_moved = false;
    double m_start = 0.0;  // radians, the pointer's direction from the press when it first left it
    double m_swept = 0.0;  // radians about the press since then, from +x towards +y as the canvas's are
    std::optional<double> m_direction;  // the pointer's at its last move, while away from the press
    double m_sweptByPens = 0.0;         // as far as the pens have gone
    std::vector<sim::Vec2> m_combPens;  // where the comb's tines in the water are
};

} // namespace vf::app
