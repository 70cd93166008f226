#pragma once
// Lagrangian contour tracking (paper §3.1, §3.3): RK4 advection (eq. 1), refinement by the
// time-rewinding split (eq. 2) and collapse, adaptive spacing, optional area correction.
#include "sim/Drop.h"
#include "sim/ExactMap.h"
#include "sim/Flow.h"
#include "sim/PhaseClock.h"
#include "sim/Pinches.h"
#include "sim/Separation.h"
#include "sim/ProximityGrid.h"
#include "sim/Tracking.h"
#include "sim/VertexGrid.h"

#include <functional>
#include <optional>
#include <vector>

namespace vf::sim {

// Where a point that sat at `p` when the current motion began is now. For advection this is the
// RK4 flow map over the step, for an ink drop the drop's push; splitting an edge evaluates it at
// the midpoint of the edge's *previous* endpoints (eq. 2), so new vertices land on the true curve.
using MotionMap = std::function<Vec2(Vec2 p)>;

// A motion as refinement takes it. An instantaneous one given as an exact map (a drop's push, a
// tool's) is depicted exactly: besides the spacing, refinement splits an edge where its chord
// strays from the mapped curve by more than `chordTolerance` (at its middle, or at a crease of the
// map: a line along which it bends sharply and is not smooth, such as a comb's tine), and
// collapses no vertex whose removal would leave a chord straying that far. `crease(a, b)` is where
// the segment a–b of positions before the motion crosses a crease, as a fraction along it (the
// crossing nearest its middle), if it does. The flow's step has neither (tolerance 0). A tool's
// map keeps areas (`keepsAreas`), and its inverse undoes it: refinement then holds it to the
// tolerance pulled back as well (Ring::chordTolerances).
struct ExactMotion {
    MotionMap map;
    std::function<std::optional<double>(Vec2 a, Vec2 b)> crease;
    double chordTolerance = 0.0;
    bool keepsAreas = false;
};

// A tool's map as an exact motion, for refinement within `chordTolerance`; it keeps areas.
ExactMotion exactMotion(const ExactMap& map, double chordTolerance);
// A drop's push as an exact motion: smooth (no crease), and it adds the drop's area.
ExactMotion exactMotion(const DropPush& push, double chordTolerance);

class ContourTracker {
public:
    explicit ContourTracker(const TrackingSettings& settings);

    const TrackingSettings& settings() const { return m_settings; }
    const std::vector<Contour>& contours() const { return m_contours; }
    std::size_t vertexCount() const { return m_vertexCount; }

    // Adds a closed contour for `region`, resampled so no edge exceeds d_max. Its area at this
    // moment becomes the target of the area correction.
    void addContour(int region, const Polygon& polygon);

    // Largest |u(v_{i+1}, t) − u(v_i, t)|·dt / d_e over all edges: how many local spacings a step
    // would move a vertex relative to its neighbour.
    double strainInSpacings(const Flow& flow, double t, double dt) const;

    // Moves every vertex through `flow` from t to t + dt (RK4, eq. 1) and refines.
    // The flow must be valid over [t, t + dt]. Returns false when refinement stopped at
    // max_vertices; the contours are then valid but may have edges longer than d_i.
    bool advect(const Flow& flow, double t, double dt);

    // Moves every vertex by an ink drop's push or a tool's map, depicted exactly (ExactMotion,
    // within the settings' chord tolerance), and refines; `flow` and `t` feed the spacing's
    // vorticity term.
    bool drop(const DropPush& push, const Flow& flow, double t);
    bool applyMap(const ExactMap& map, const Flow& flow, double t);

    // Raises the area-correction target of every contour winding around `p` by `area` per turn:
    // an ink drop landing inside a contour makes it enclose the drop as well.
    void growTargetAreasAround(Vec2 p, double area);

    // Cuts every contour where it pinches (sim/Pinches.h); returns how many cuts were made.
    std::size_t cutPinches();
    std::size_t separateLayers(std::optional<Window> within) { return sim::separateLayers(m_contours, within); }

    // Replaces all contours (snapshot restore); counts are recomputed.
    void setContours(std::vector<Contour> contours);

    // Charges the phases of every later motion to `clock` (Simulation::enablePhaseTiming).
    void setPhaseClock(PhaseClock* clock) { m_clock = clock; }

private:
    bool applyMotion(const ExactMotion& motion, const Flow& flow, double t, bool cutFirst = false);
    bool refineAll(const ExactMotion& motion, const Flow& flow, double t);
    // The area correction of every contour (docs/method.md, "Area correction"): a vertex with
    // another part of any contour within areaHoldDistance stays where it is.
    void correctAreas();
    bool refine(Contour& contour, const ExactMotion& motion, std::size_t budget);

    TrackingSettings m_settings;
    std::vector<Contour> m_contours;
    std::size_t m_vertexCount = 0;
    ProximityGrid m_grid;
    VertexGrid m_vertexGrid;
    EdgeGrid::Storage m_pinchGrid;
    PhaseClock* m_clock = nullptr;
};

// Recentring (collapse): the rewound point at fraction s along an edge landed toA and toB from the
// edge's moved ends, and must lie needA and needB from them. The fraction to try instead: s moved
// by how far the landing point's place between the ends, toA / (toA + toB), is from the nearest
// place that leaves both needs met (the middle when it can), in [0, 1].
double recentredFraction(double s, double toA, double toB, double needA, double needB);
inline constexpr int recentreCorrections = 3;  // at most (the device's kernels are built with it)
// A needle tip: a vertex where the contour turns back on itself (by 90° or more, or onto a
// neighbour it coincides with), whose neighbours are no farther apart than their spacing allows,
// and whose triangle with them is at most tipWidth times the vertex's spacing high over its
// longest side. Such a tip is removed (collapse): a needle thinner
// than that is below any picture's resolution, and, left to thin on, its two sides would come
// closer than the positions can tell apart (single precision on the device) and cross.
inline constexpr double tipWidth = 0.01;
bool isThinTip(Vec2 before, Vec2 at, Vec2 after, double spacingBefore, double spacing, double spacingAfter);

// One classic fourth-order Runge–Kutta step through `flow` (eq. 1).
Vec2 rungeKutta4(const Flow& flow, Vec2 p, double t, double dt);

} // namespace vf::sim
