#pragma once
// Maps that turn every point about a centre C by an angle θ(ρ) that depends only on its distance ρ
// from C: each circle about C turns rigidly, so areas are kept, no point leaves its circle, and
// the opposite angle undoes the map exactly (Lu, Jaffer et al., "Mathematical Marbling", IEEE
// CG&A 2012, circular tines and vortices).
#include "sim/Geometry.h"

#include <optional>

namespace vf::sim {

// Tines on concentric circles of radii r_k = radius + k·spacing (k = 0 … tines − 1), all turned by
// `angle` (radians, counter-clockwise) together: θ(ρ) = Σ_k angle·u/(|ρ − r_k| + u), u the
// sharpness. As the straight comb across its tines: a point on a tine's circle turns by at least
// the angle, and the pull halves u away from it.
struct CircularComb {
    Vec2 centre{0.0};
    double radius = 0.0;
    int tines = 1;
    double spacing = 0.0;
    double sharpness = 0.0;
    double angle = 0.0;

    Vec2 operator()(Vec2 p) const;
    CircularComb inverse() const { return {centre, radius, tines, spacing, sharpness, -angle}; }
    // Where the segment a–b crosses a tine's circle (θ has a corner there), the crossing nearest
    // its middle, as a fraction along it, with ρ taken as linear between a and b.
    std::optional<double> tineCrossing(Vec2 a, Vec2 b) const;
};

// A vortex: θ(ρ) = angle·exp(−(ρ/radius)²), the whole angle at the centre, fading out past the
// radius. Smooth everywhere.
struct Swirl {
    Vec2 centre{0.0};
    double radius = 0.0;
    double angle = 0.0;

    Vec2 operator()(Vec2 p) const;
    Swirl inverse() const { return {centre, radius, -angle}; }
    // How far (radians) the points at distance `rho` from the centre turn.
    double angleAt(double rho) const;
};

} // namespace vf::sim
