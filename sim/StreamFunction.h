#pragma once
// The velocity that carries the contours: the curl of a stream function ψ, a cubic B-spline over
// ψ at the cell corners of the MAC grid.
//
// Why not the MAC field's own bilinear interpolation: its gradient jumps across every line through
// the cell centres, so the image of a short straight edge under one step of the flow bends there
// by about dt·|jump of ∇u|·(edge length), a few micrometres of a unit canvas. Where the two sides
// of a thin filament are closer than that, the edges between advected vertices cross although the
// true curves never do. The cubic B-spline makes ψ twice continuously differentiable, so the
// velocity is C¹ and a short edge's image deviates from its chord only to second order; and a
// velocity that is the curl of ψ has zero divergence everywhere, not only at cell centres, so
// the flow itself keeps every region's area (up to RK4's error).
//
// ψ at the corners comes from the discretely divergence-free MAC field by summing fluxes:
// ψ(i, j) − ψ(i, j − 1) = u(i, j − ½)·hy up each column from the bottom wall, along which
// ψ(i, 0) − ψ(i − 1, 0) = −v(i − ½, 0)·hx; then u = ∂ψ/∂y, v = −∂ψ/∂x at every face (to the
// projection's tolerance; ψ takes one value along the top wall, so nothing flows through it). ψ is extended one corner past each wall by odd reflection about its wall
// value, ψ(−k) = 2ψ(0) − ψ(k), so the spline keeps ψ constant along the wall (no flow through it)
// with zero second normal derivative (free slip, as the solver's walls). Outside the canvas the
// stream function is that odd reflection damped to the walls' value, ψ̃ = φ·ψ with
// φ = m(o_x/b_x)·m(o_y/b_y), o the distance outside along each axis, b two cells, and
// m(s) = 1 − (6s⁵ − 15s⁴ + 10s³) falling from 1 at the wall to 0 at s = 1, its first two
// derivatives zero at both ends. So the flow continues smoothly (C¹) across the wall, stays
// divergence-free, and stops two cells out. Ink outside the canvas never comes back in (no flow
// crosses a wall) and is never seen; drops push it there. Left moving, it was squeezed against the
// walls' extensions into layers thinner than a float resolves, and crossed; at rest it costs
// nothing. The vorticity outside is the damped reflection's, φ·ω (it only sets spacing).
#include "sim/FluidSolver.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace vf::sim {

struct StreamField {
    static constexpr double dampingCells = 2.0;  // the band b outside the walls, in cells
    int nx = 0, ny = 0;
    double hx = 1.0, hy = 1.0;
    std::vector<double> psi;  // (nx + 3) × (ny + 3), row-major: corner (i, j) at (j + 1)(nx + 3) + i + 1

    static StreamField of(const MacVelocity& field);
    // (a + b) / 2, the field halfway between two (ψ is linear in the velocity).
    static StreamField average(const StreamField& a, const StreamField& b);

    Vec2 velocity(Vec2 p) const;
    // φ of the damping outside the canvas and its gradient (1 and 0 inside).
    struct Damping {
        double factor = 1.0;
        Vec2 gradient{0.0};
    };
    Damping dampingAt(Vec2 p) const;
    // ∂v/∂x − ∂u/∂y = −∇²ψ (eq. 5's vorticity), continuous.
    double vorticity(Vec2 p) const;

private:
    struct Stencil;
    Stencil stencilAt(Vec2 p) const;
};

// The cubic B-spline weights of the four lattice points around a position t ∈ [0, 1] past the
// second of them, and of the spline's first and second derivatives.
struct SplineWeights {
    double w[4], dw[4], ddw[4];
};

inline SplineWeights splineWeights(double t)
{
    const double s = 1.0 - t, t2 = t * t, t3 = t2 * t;
    return {{s * s * s / 6.0, (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0, (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0, t3 / 6.0},
            {-0.5 * s * s, 0.5 * (3.0 * t2 - 4.0 * t), 0.5 * (-3.0 * t2 + 2.0 * t + 1.0), 0.5 * t2},
            {s, 3.0 * t - 2.0, 1.0 - 3.0 * t, t}};
}

namespace detail {

// Reflects a lattice coordinate in [−n, 2n] into [0, n] (outside it: clamped, NaN to 0); `sign`
// becomes −1 where it was reflected.
inline double reflectInto(double g, int n, double& sign)
{
    sign = (g < 0.0 || g > n) ? -1.0 : 1.0;
    g = g < 0.0 ? -g : g > n ? 2.0 * n - g : g;
    return std::min(0.0 < g ? g : 0.0, double(n));
}

} // namespace detail

// The 4 × 4 corners around a point (reflected into the canvas) and the spline's weights there.
struct StreamField::Stencil {
    const double* corner;  // corner (i − 1, j − 1); rows nx + 3 apart
    int stride;
    SplineWeights x, y;
    double flipX, flipY;   // −1 where the point was reflected across a wall

    std::pair<double, double> sums(const double (&wxA)[4], const double (&wyA)[4], const double (&wxB)[4],
                                   const double (&wyB)[4]) const;
};

inline StreamField::Stencil StreamField::stencilAt(Vec2 p) const
{
    Stencil s;
    const double gx = detail::reflectInto(p.x / hx, nx, s.flipX);
    const double gy = detail::reflectInto(p.y / hy, ny, s.flipY);
    const int i = std::min(int(gx), nx - 1), j = std::min(int(gy), ny - 1);
    s.x = splineWeights(gx - i);
    s.y = splineWeights(gy - j);
    s.stride = nx + 3;
    s.corner = psi.data() + std::ptrdiff_t(j) * s.stride + i;
    return s;
}

// Two sums Σ_b wy[b] · Σ_a wx[a] · ψ(i − 1 + a, j − 1 + b) over the stencil's 4 × 4 corners, with
// the weights A and B, from one pass over the corners.
inline std::pair<double, double> StreamField::Stencil::sums(const double (&wxA)[4], const double (&wyA)[4],
                                                            const double (&wxB)[4], const double (&wyB)[4]) const
{
    double a = 0.0, b = 0.0;
    const double* row = corner;
    for (int r = 0; r < 4; ++r, row += stride) {
        a += wyA[r] * (wxA[0] * row[0] + wxA[1] * row[1] + wxA[2] * row[2] + wxA[3] * row[3]);
        b += wyB[r] * (wxB[0] * row[0] + wxB[1] * row[1] + wxB[2] * row[2] + wxB[3] * row[3]);
    }
    return {a, b};
}

namespace detail {

// m(o / band) of the damping and its derivative along the axis, for a coordinate g in [0, extent]
// inside.
inline std::pair<double, double> dampingAlong(double g, double extent, double band)
{
    const double outside = g < 0.0 ? -g : g - extent;
    if (!(outside > 0.0))
        return {1.0, 0.0};
    const double s = std::min(outside / band, 1.0);
    const double m = 1.0 - s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
    const double slope = -30.0 * s * s * (1.0 - s) * (1.0 - s) / band;  // dm/d(outside)
    return {m, g < 0.0 ? -slope : slope};
}

} // namespace detail

inline StreamField::Damping StreamField::dampingAt(Vec2 p) const
{
    const auto [mx, dmx] = detail::dampingAlong(p.x, nx * hx, dampingCells * hx);
    const auto [my, dmy] = detail::dampingAlong(p.y, ny * hy, dampingCells * hy);
    return {mx * my, {dmx * my, mx * dmy}};
}

inline Vec2 StreamField::velocity(Vec2 p) const
{
    const Damping damping = dampingAt(p);
    if (damping.factor == 0.0)
        return Vec2(0.0);
    const Stencil s = stencilAt(p);
    const auto [dPsiDy, dPsiDx] = s.sums(s.x.w, s.y.dw, s.x.dw, s.y.w);
    const Vec2 mirrored(s.flipX * dPsiDy / hy, -s.flipY * dPsiDx / hx);
    if (damping.factor == 1.0)
        return mirrored;
    // curl(φ·ψ) = φ·curl ψ + ψ·(∂φ/∂y, −∂φ/∂x), ψ the reflection's value here.
    const double psi = s.flipX * s.flipY * s.sums(s.x.w, s.y.w, s.x.w, s.y.w).first;
    return damping.factor * mirrored + psi * Vec2(damping.gradient.y, -damping.gradient.x);
}

inline double StreamField::vorticity(Vec2 p) const
{
    const Stencil s = stencilAt(p);
    const auto [psiXX, psiYY] = s.sums(s.x.ddw, s.y.w, s.x.w, s.y.ddw);
    return -dampingAt(p).factor * s.flipX * s.flipY * (psiXX / (hx * hx) + psiYY / (hy * hy));
}

} // namespace vf::sim
