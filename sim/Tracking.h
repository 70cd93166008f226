#pragma once
// Settings and per-contour state of the contour tracker (paper §3.1, §3.3).
#include "sim/Geometry.h"

#include <cstddef>
#include <vector>

namespace vf::sim {

struct TrackingSettings {
    double maxSpacing = 0.004;  // d_max of eq. 3, canvas units
    bool adaptive = true;       // false: every edge in [maxSpacing/2, maxSpacing]
    bool proximity = true;      // eq. 7
    bool areaCorrection = false;
    std::size_t maxVertices = 4'000'000;
    int maxSubsteps = 16;
    // Eq. 2: a split vertex is the edge's midpoint at the start of the step, advected. false uses
    // the plain midpoint of the advected edge (kept to measure what rewinding buys).
    bool timeRewinding = true;
    // How far a chord may stray from the curve of an exact map (a drop, a comb: ExactMotion in
    // sim/ContourTracker.h), canvas units; 0 depicts it by the spacing alone. A comb drawn back
    // returns within about seven times this (across its tines, where it shears most): 1e-6. The
    // device holds positions in float and depicts no finer than two roundings of them.
    double chordTolerance = 1e-7;

    // Reference scales that make the exponentials of eqs. 4, 5 and 7 unit-free. All are relative
    // to d_max so that a finer tracking resolution refines the same features proportionally.
    double curvatureLength() const { return 2.0 * maxSpacing; }  // |κ| is multiplied by this
    double vorticityScale = 20.0;                                 // |ω| is divided by this (1/s)
    double proximityLength() const { return maxSpacing; }        // distance is divided by this
    double proximityRadius() const { return 2.0 * proximityLength(); }  // search radius; c = 0.86 there
    // The proximity grid's cells: half the radius, searched ring by ring outward.
    double proximityCell() const { return proximityRadius() / 2.0; }
    double minSpacing() const { return maxSpacing / 16.0; }      // ε of eq. 3
    // The area correction leaves a vertex where it is when another part of any contour lies within
    // d_max of it, and moves the others by at most ε/4 a step. No edge is longer than d_max, so a
    // moved vertex's other ink is at least √3/2·d_max away, far beyond two such moves: the
    // correction cannot carry one contour across another (docs/method.md, "Area correction").
    double areaHoldDistance() const { return maxSpacing; }
    double areaCorrectionStep() const { return minSpacing() / 4.0; }

    int smoothingRadius = 4;  // w of eq. 6, in vertices; σ = w / 2

    // A step is split so that no vertex moves further *relative to its neighbour* than this many
    // local spacings per substep. Relative motion is what bends and stretches edges, and what
    // time rewinding and collision-free refinement need kept small; a contour carried along as a
    // whole needs no substeps, however fast.
    double substepStrain = 0.5;
};

// One closed contour. Positions and spacing are parallel arrays; `previous` holds each vertex's
// position at the start of the current motion, which the time-rewinding split (eq. 2) needs.
struct Contour {
    int region = 0;
    std::vector<Vec2> positions;
    std::vector<Vec2> previous;
    std::vector<double> spacing;  // d_i of eq. 3 after smoothing (eq. 6)
    double targetArea = 0.0;      // for the optional area correction

    friend bool operator==(const Contour&, const Contour&) = default;
};

} // namespace vf::sim
