#pragma once
// Stable-fluids solver on a staggered (MAC) grid over the canvas, closed walls.
// Public API is used by FluidFlow and the tests; internals belong to FluidSolver.cpp.
#include "sim/Geometry.h"
#include "sim/LinearSolve.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace vf::sim {

enum class Advection { SemiLagrangian, MacCormack };

struct FluidSettings {
    int nx = 64;              // cells across the canvas width
    int ny = 64;              // cells down the canvas height
    double width = 1.0;       // canvas size in canvas units
    double height = 1.0;
    double viscosity = 5e-4;  // kinematic, canvas units^2 / s; 0 allowed
    // How fast the stylus drags the fluid under it to its own velocity (s, see addStylus): short
    // enough that the pen acts almost at once; 0 sets the fluid under the pen to its velocity.
    double stylusResponse = 0.02;
    Advection advection = Advection::MacCormack;
    double pressureTolerance = 1e-8;  // see FluidSolver.cpp for the norm it is measured in
};

// The staggered velocity at one instant: u on vertical cell faces, v on horizontal ones.
// Copyable, so the caller can keep the field of the previous step and interpolate in time.
struct MacVelocity {
    int nx = 0, ny = 0;
    double hx = 1.0, hy = 1.0;
    std::vector<double> u;  // (nx + 1) * ny
    std::vector<double> v;  // nx * (ny + 1)

    Vec2 sample(Vec2 p) const;  // bilinear, clamped to the canvas (the solver's own; contours
                                // move through sim/StreamFunction)

    friend bool operator==(const MacVelocity&, const MacVelocity&) = default;
};

// A force over the whole grid for one step, as target-driven design steers the ink (sim/TargetDrive.h):
// every interior face gains `acceleration` (on the faces, laid out as MacVelocity) times dt, and
// the fluid's own velocity there decays at `damping` (1/s): u = u e^(-damping dt) + a dt.
struct BodyForce {
    MacVelocity acceleration;
    double damping = 0.0;
};

// Throws std::invalid_argument (one line) for a force FluidSolver::addForce refuses on an nx x ny grid.
void validateForce(const BodyForce& force, int nx, int ny);

// The share of the way from the fluid's velocity to the pen's that one step of dt covers under the
// pen's centre (both solvers use it).
double stylusStrength(const FluidSettings& settings, double dt);

class FluidSolver {
public:
    explicit FluidSolver(const FluidSettings& settings);

    const FluidSettings& settings() const { return m_settings; }

    // A stylus moved from `from` to `to` during `duration` seconds with radius `radius`. Its force
    // is applied in the next step(): the fluid within the radius relaxes toward the pen's velocity
    // with time constant settings().stylusResponse.
    void addStylus(Vec2 from, Vec2 to, double radius, double duration);

    // A body force for the next step() only, replacing any given before it. Throws
    // std::invalid_argument for a field on another grid, a non-finite value or a negative damping.
    void addForce(const BodyForce& force);

    // One step: advection, implicit viscosity, stylus and body forces, pressure projection.
    void step(double dt);

    // The field at rest on the grid of `settings`.
    static MacVelocity atRest(const FluidSettings& settings);

    const MacVelocity& velocity() const { return m_velocity; }
    void setVelocity(const MacVelocity& velocity);  // same dimensions; for snapshots and tests
    // The last projection's pressure (nx * ny, cell centres), the next one's first guess. Restoring
    // it after setVelocity() makes a snapshot step on exactly as the original did.
    const std::vector<double>& pressure() const { return m_pressure; }
    void setPressure(const std::vector<double>& pressure);  // same size

    double maxDivergence() const;   // max |div u| over cells, 1/s
    double kineticEnergy() const;   // 0.5 * integral of |u|^2 over the canvas
    double maxSpeed() const;
    int lastPressureIterations() const { return m_lastPressureIterations; }

private:
    struct StylusSegment {
        Vec2 from, to;
        double radius;
        Vec2 velocity;  // of the pen, canvas units / s
    };

    void applyStylus(const StylusSegment& segment, double dt);
    void applyForce(const BodyForce& force, double dt);
    void advect(double dt);
    void advectComponent(int component, double dt);
    void diffuse(double dt);
    void project();

    FluidSettings m_settings;
    MacVelocity m_velocity;
    int m_lastPressureIterations = 0;

    std::vector<StylusSegment> m_pendingStylus;
    std::optional<BodyForce> m_pendingForce;
    MacVelocity m_advected;                  // advection target, swapped with m_velocity
    std::vector<double> m_backward;          // MacCormack: the forward result traced back
    std::vector<double> m_low, m_high;       // MacCormack limiter bounds per face
    std::vector<double> m_rhs, m_solution;   // right-hand side / unknowns of the linear solves
    std::vector<double> m_pressure;          // kept between steps to warm-start the projection
    PcgSolver m_pressureSolver;
    std::array<PcgSolver, 2> m_viscositySolvers;  // u and v faces have different stencils
};

// ---- Hot-path sampling, inline: called several times per contour vertex per step. -----------

namespace detail {

// A position on a row-major cols x rows lattice (cols, rows >= 2): the lattice point (i, j) at
// the low corner of the square holding it and the fractions across. Positions outside are clamped
// onto the lattice, NaN to the low end, so no position, however bad, indexes out of bounds.
struct LatticePoint {
    int i, j;
    double fx, fy;
};

inline LatticePoint locate(int cols, int rows, double gx, double gy)
{
    // Branch-free clamps (maxsd/minsd); std::fmax/fmin would be library calls. The operand order
    // matters: a NaN fails `0 < g` and becomes 0.
    gx = std::min(0.0 < gx ? gx : 0.0, double(cols - 1));
    gy = std::min(0.0 < gy ? gy : 0.0, double(rows - 1));
    const int i = std::min(int(gx), cols - 2);
    const int j = std::min(int(gy), rows - 2);
    return {i, j, gx - i, gy - j};
}

inline double bilinear(const double* f, int cols, const LatticePoint& q)
{
    const double* r0 = f + std::ptrdiff_t(q.j) * cols + q.i;
    const double* r1 = r0 + cols;
    return (1.0 - q.fy) * ((1.0 - q.fx) * r0[0] + q.fx * r0[1])
         + q.fy * ((1.0 - q.fx) * r1[0] + q.fx * r1[1]);
}

// The velocity at (gx, gy) in cell units (x / hx, y / hy): u lives at (i, j + 1/2), v at
// (i + 1/2, j).
inline Vec2 sampleCells(const MacVelocity& m, double gx, double gy)
{
    return {bilinear(m.u.data(), m.nx + 1, locate(m.nx + 1, m.ny, gx, gy - 0.5)),
            bilinear(m.v.data(), m.nx, locate(m.nx, m.ny + 1, gx - 0.5, gy))};
}

} // namespace detail

inline Vec2 MacVelocity::sample(Vec2 p) const
{
    return detail::sampleCells(*this, p.x / hx, p.y / hy);
}

} // namespace vf::sim
