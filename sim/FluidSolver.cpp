// Stable fluids (Stam 1999, "Stable Fluids") on a staggered MAC grid (Harlow & Welch 1965), in the
// form of Bridson, "Fluid Simulation for Computer Graphics" (2nd ed.): advection (semi-
// Lagrangian, or MacCormack after Selle et al. 2008), implicit viscosity, stylus forces, pressure
// projection.
//
// Walls: the canvas is a closed box. The normal velocity on the walls is zero (the first and last
// u columns, the first and last v rows), and the walls are free-slip: the tangential velocity
// has zero normal derivative there, so the fluid slides along the edge of the canvas instead of
// sticking to it. The canvas edge is only the edge of the picture, not a real wall of the bath, so
// a wall that does not brake the flow is the closer model; it also keeps the viscous operator of
// each component simple (Dirichlet across its normal axis, Neumann along the other).
//
// Pressure tolerance: the projection stops when the max over cells of |div u| of the projected
// velocity, in 1/s, is at most FluidSettings::pressureTolerance: an absolute bound, the quantity
// the contour areas depend on. What is measured is the max norm of the CG residual, which equals
// -div u of the projected velocity up to roundoff and the mean of div u* (the net flux through the
// closed walls, zero but for roundoff). For velocities so large that this absolute target falls
// below what double precision resolves, it is raised to 1e-13 * (max |div u| before the
// projection), so the solve ends on convergence, not on the iteration cap.
#include "sim/FluidSolver.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace vf::sim {
namespace {

// Viscosity solves stop at this max-norm residual relative to the max |u| being diffused: far
// below anything visible, and the projection that follows fixes the divergence anyway.
constexpr double kViscosityRelativeTolerance = 1e-8;
// Relative floor of the pressure target (see the top of this file).
constexpr double kPressureRoundoffFloor = 1e-13;
// Bounds the memory (~ 60 doubles per cell) and keeps every index within int.
constexpr int kMaxCellsPerSide = 4096;

// One velocity component on its lattice: point (i, j) sits at ((i + offsetX) hx, (j + offsetY) hy).
// The lattice lines across the component's own axis at both ends lie on the walls.
struct FaceGrid {
    int cols, rows;
    double offsetX, offsetY;
    double hx, hy;
    bool normalX;  // u (points along x) or v

    int firstCol() const { return normalX ? 1 : 0; }
    int firstRow() const { return normalX ? 0 : 1; }
    int interiorCols() const { return cols - 2 * firstCol(); }
    int interiorRows() const { return rows - 2 * firstRow(); }
    Vec2 positionInCells(int i, int j) const { return {i + offsetX, j + offsetY}; }
    Vec2 position(int i, int j) const { return positionInCells(i, j) * Vec2{hx, hy}; }
    detail::LatticePoint locateCells(Vec2 g) const
    {
        return detail::locate(cols, rows, g.x - offsetX, g.y - offsetY);
    }
};

// Half-open index ranges [i0, i1) x [j0, j1) on a FaceGrid.
struct FaceRange {
    int i0, i1, j0, j1;
};

std::array<FaceGrid, 2> faceGrids(const MacVelocity& m)
{
    return {FaceGrid{m.nx + 1, m.ny, 0.0, 0.5, m.hx, m.hy, true},
            FaceGrid{m.nx, m.ny + 1, 0.5, 0.0, m.hx, m.hy, false}};
}

std::array<std::vector<double>*, 2> components(MacVelocity& m) { return {&m.u, &m.v}; }

FaceRange interior(const FaceGrid& g)
{
    return {g.firstCol(), g.cols - g.firstCol(), g.firstRow(), g.rows - g.firstRow()};
}

// The interior faces whose positions can lie in the box [lo, hi].
FaceRange interiorWithin(const FaceGrid& g, Vec2 lo, Vec2 hi)
{
    const FaceRange all = interior(g);
    // Clamped in floating point before the conversion, so huge coordinates cannot overflow int.
    const auto index = [](double x, int first, int end) {
        return int(std::clamp(x, double(first), double(end)));
    };
    return {index(std::ceil(lo.x / g.hx - g.offsetX), all.i0, all.i1),
            index(std::floor(hi.x / g.hx - g.offsetX) + 1.0, all.i0, all.i1),
            index(std::ceil(lo.y / g.hy - g.offsetY), all.j0, all.j1),
            index(std::floor(hi.y / g.hy - g.offsetY) + 1.0, all.j0, all.j1)};
}

// Calls f(flat index, i, j) for every face of the range, row by row: a fixed order, so results
// are deterministic.
template <class F>
void forEachFace(const FaceGrid& g, const FaceRange& r, F&& f)
{
    for (int j = r.j0; j < r.j1; ++j)
        for (int i = r.i0; i < r.i1; ++i)
            f(std::size_t(j) * g.cols + i, i, j);
}

void gatherInterior(const FaceGrid& g, const std::vector<double>& values, std::vector<double>& out)
{
    out.resize(std::size_t(g.interiorCols()) * g.interiorRows());
    auto it = out.begin();
    forEachFace(g, interior(g), [&](std::size_t k, int, int) { *it++ = values[k]; });
}

void scatterInterior(const FaceGrid& g, const std::vector<double>& in, std::vector<double>& values)
{
    auto it = in.begin();
    forEachFace(g, interior(g), [&](std::size_t k, int, int) { values[k] = *it++; });
}

double cellDivergence(const MacVelocity& m, int i, int j)
{
    const double* u = m.u.data() + std::size_t(j) * (m.nx + 1) + i;
    const double* v = m.v.data() + std::size_t(j) * m.nx + i;
    return (u[1] - u[0]) / m.hx + (v[m.nx] - v[0]) / m.hy;
}

Vec2 cellCenterVelocity(const MacVelocity& m, int i, int j)
{
    const double* u = m.u.data() + std::size_t(j) * (m.nx + 1) + i;
    const double* v = m.v.data() + std::size_t(j) * m.nx + i;
    return {0.5 * (u[0] + u[1]), 0.5 * (v[0] + v[m.nx])};
}

// Generous: multigrid-preconditioned CG converges in 5 to 15 iterations on any grid we allow; the
// cap only guards against garbage input (CG in exact arithmetic would need at most n).
int iterationCap(int cols, int rows) { return 4 * (cols + rows) + 100; }

// Where the fluid at g came from over a time step, in cell units (g = (x / hx, y / hy)); `step` is
// (dt / hx, dt / hy), negated to trace forward instead. Midpoint rule (RK2), which Bridson (§3.1)
// recommends over forward Euler for the backtrace. Cell units spare the divisions of sample().
Vec2 trace(const MacVelocity& m, Vec2 g, Vec2 step)
{
    const Vec2 mid = g - 0.5 * step * detail::sampleCells(m, g.x, g.y);
    return g - step * detail::sampleCells(m, mid.x, mid.y);
}

bool isFinite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

void validate(const FluidSettings& s)
{
    const auto fail = [](const std::string& what) {
        throw std::invalid_argument("FluidSettings: " + what);
    };
    if (s.nx < 4 || s.ny < 4 || s.nx > kMaxCellsPerSide || s.ny > kMaxCellsPerSide)
        fail("grid " + std::to_string(s.nx) + " x " + std::to_string(s.ny) + " must have 4 to "
             + std::to_string(kMaxCellsPerSide) + " cells per side");
    if (!(s.width > 0.0) || !(s.height > 0.0) || !std::isfinite(s.width)
        || !std::isfinite(s.height))
        fail("canvas size must be positive and finite");
    if (!(s.viscosity >= 0.0) || !std::isfinite(s.viscosity))
        fail("viscosity must be zero or positive and finite");
    if (!(s.stylusResponse >= 0.0) || !std::isfinite(s.stylusResponse))
        fail("stylus response must be zero or positive and finite");
    if (!(s.pressureTolerance > 0.0) || !std::isfinite(s.pressureTolerance))
        fail("pressure tolerance must be positive and finite");
}

} // namespace

FluidSolver::FluidSolver(const FluidSettings& settings)
    : m_settings(settings)
{
    validate(settings);
    m_velocity = atRest(settings);
    m_advected = m_velocity;
    m_pressure.assign(std::size_t(settings.nx) * settings.ny, 0.0);
}

MacVelocity FluidSolver::atRest(const FluidSettings& settings)
{
    const int nx = settings.nx, ny = settings.ny;
    return {nx, ny, settings.width / nx, settings.height / ny, std::vector<double>(std::size_t(nx + 1) * ny, 0.0),
            std::vector<double>(std::size_t(nx) * (ny + 1), 0.0)};
}

void FluidSolver::setVelocity(const MacVelocity& velocity)
{
    if (velocity.nx != m_velocity.nx || velocity.ny != m_velocity.ny
        || velocity.u.size() != m_velocity.u.size() || velocity.v.size() != m_velocity.v.size())
        throw std::invalid_argument("FluidSolver::setVelocity: expected a "
                                    + std::to_string(m_velocity.nx) + " x "
                                    + std::to_string(m_velocity.ny) + " grid");
    m_velocity.u = velocity.u;
    m_velocity.v = velocity.v;
    // The warm-start pressure belongs to the old history; dropping it makes every later step a
    // function of this velocity alone (a restored snapshot replays bit for bit).
    std::fill(m_pressure.begin(), m_pressure.end(), 0.0);
}

void FluidSolver::setPressure(const std::vector<double>& pressure)
{
    if (pressure.size() != m_pressure.size())
        throw std::invalid_argument("FluidSolver::setPressure: expected " + std::to_string(m_pressure.size())
                                    + " cells");
    m_pressure = pressure;
}

double stylusStrength(const FluidSettings& settings, double dt)
{
    return 1.0 - std::exp(-dt / settings.stylusResponse);  // 1 for a response of 0
}

void validateForce(const BodyForce& force, int nx, int ny)
{
    const MacVelocity& a = force.acceleration;
    if (a.nx != nx || a.ny != ny || a.u.size() != std::size_t(nx + 1) * ny || a.v.size() != std::size_t(nx) * (ny + 1))
        throw std::invalid_argument("body force: expected a " + std::to_string(nx) + " x " + std::to_string(ny)
                                    + " grid");
    const auto finite = [](const std::vector<double>& values) {
        return std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); });
    };
    if (!finite(a.u) || !finite(a.v) || !(force.damping >= 0.0) || !std::isfinite(force.damping))
        throw std::invalid_argument("body force: values must be finite and the damping zero or positive");
}

void FluidSolver::addForce(const BodyForce& force)
{
    validateForce(force, m_velocity.nx, m_velocity.ny);
    m_pendingForce = force;
}

void FluidSolver::applyForce(const BodyForce& force, double dt)
{
    const double decay = std::exp(-force.damping * dt);
    const auto grids = faceGrids(m_velocity);
    const auto values = components(m_velocity);
    const std::array<const std::vector<double>*, 2> accelerations = {&force.acceleration.u, &force.acceleration.v};
    for (int c = 0; c < 2; ++c) {
        std::vector<double>& component = *values[c];
        const std::vector<double>& a = *accelerations[c];
        forEachFace(grids[c], interior(grids[c]), [&](std::size_t k, int, int) {
            component[k] = component[k] * decay + a[k] * dt;
        });
    }
}

void FluidSolver::addStylus(Vec2 from, Vec2 to, double radius, double duration)
{
    // A pen that takes no time (or a NaN time) to move jumped: it carries no velocity, so no force.
    if (!(duration > 0.0) || !(radius > 0.0) || !std::isfinite(radius))
        return;
    const Vec2 velocity = (to - from) / duration;
    if (!isFinite(from) || !isFinite(to) || !isFinite(velocity))
        return;
    m_pendingStylus.push_back({from, to, radius, velocity});
}

void FluidSolver::step(double dt)
{
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw std::invalid_argument("FluidSolver::step: dt must be positive and finite");
    advect(dt);
    if (m_settings.viscosity > 0.0)
        diffuse(dt);
    // The pen acts after diffusion so that its push survives into this step's flow even in the
    // shape-design regime, where diffusion would otherwise spread it over the canvas at once
    // (paper §5.2: the motion is noticeable just after the user agitates the fluid).
    for (const StylusSegment& segment : m_pendingStylus)
        applyStylus(segment, dt);
    m_pendingStylus.clear();
    if (m_pendingForce)
        applyForce(*std::exchange(m_pendingForce, std::nullopt), dt);
    project();
}

// The pen drags the fluid within `radius` of its path toward its own velocity, relaxing with time
// constant tau = stylusResponse: u += w (v_pen - u) (1 - exp(-dt / tau)), w = (1 - (d/r)^2)^2. The
// force therefore scales with how fast the pen moves, and a slow pen barely stirs; the exponential
// form stays bounded (never past v_pen) for any dt and any tau, 0 included.
void FluidSolver::applyStylus(const StylusSegment& segment, double dt)
{
    const double strength = stylusStrength(m_settings, dt);
    const double r2 = segment.radius * segment.radius;
    const Vec2 lo = glm::min(segment.from, segment.to) - segment.radius;
    const Vec2 hi = glm::max(segment.from, segment.to) + segment.radius;
    const auto grids = faceGrids(m_velocity);
    const auto values = components(m_velocity);
    for (int c = 0; c < 2; ++c) {
        const FaceGrid& g = grids[c];
        std::vector<double>& component = *values[c];
        const double pen = segment.velocity[c];
        forEachFace(g, interiorWithin(g, lo, hi), [&](std::size_t k, int i, int j) {
            const double d2 = squaredDistanceToSegment(g.position(i, j), segment.from, segment.to);
            if (d2 < r2) {
                const double w = (1.0 - d2 / r2) * (1.0 - d2 / r2);
                component[k] += w * strength * (pen - component[k]);
            }
        });
    }
}

void FluidSolver::advect(double dt)
{
    for (int c = 0; c < 2; ++c)
        advectComponent(c, dt);
    std::swap(m_velocity.u, m_advected.u);
    std::swap(m_velocity.v, m_advected.v);
}

// Semi-Lagrangian (Stam 1999): each face takes the old value found where its fluid came from.
// MacCormack (Selle et al. 2008, "An Unconditionally Stable MacCormack Method"): trace that result
// forward again, and correct by half the round-trip error, which cancels the leading error term
// (second order in smooth flow). The limiter clamps the result to the range of the four old values
// the semi-Lagrangian step interpolated from, so it cannot create new extrema and stays stable.
// Wall faces stay zero. Tracing uses the velocity of the start of the step throughout.
void FluidSolver::advectComponent(int component, double dt)
{
    const bool macCormack = m_settings.advection == Advection::MacCormack;
    const FaceGrid g = faceGrids(m_velocity)[component];
    const Vec2 step{dt / g.hx, dt / g.hy};
    const std::vector<double>& old = *components(m_velocity)[component];
    std::vector<double>& next = *components(m_advected)[component];
    next.assign(old.size(), 0.0);
    if (macCormack) {
        m_low.resize(old.size());
        m_high.resize(old.size());
    }
    forEachFace(g, interior(g), [&](std::size_t k, int i, int j) {
        const Vec2 from = trace(m_velocity, g.positionInCells(i, j), step);
        const detail::LatticePoint q = g.locateCells(from);
        next[k] = detail::bilinear(old.data(), g.cols, q);
        if (macCormack) {
            const double* r0 = old.data() + std::size_t(q.j) * g.cols + q.i;
            const double* r1 = r0 + g.cols;
            m_low[k] = std::min({r0[0], r0[1], r1[0], r1[1]});
            m_high[k] = std::max({r0[0], r0[1], r1[0], r1[1]});
        }
    });
    if (!macCormack)
        return;
    m_backward.assign(old.size(), 0.0);
    forEachFace(g, interior(g), [&](std::size_t k, int i, int j) {
        const Vec2 to = trace(m_velocity, g.positionInCells(i, j), -step);
        const detail::LatticePoint q = g.locateCells(to);
        const double roundTrip = detail::bilinear(next.data(), g.cols, q);
        m_backward[k] = std::clamp(next[k] + 0.5 * (old[k] - roundTrip), m_low[k], m_high[k]);
    });
    next.swap(m_backward);
}

// Implicit viscosity (Stam 1999 §2.3; Bridson ch. 10): solve (I - nu dt Laplacian) u = u* for each
// component, unconditionally stable for any nu dt. The matrix is SPD, so the same preconditioned CG
// as the projection applies; u* is the first guess, already close when nu dt / h^2 is small.
void FluidSolver::diffuse(double dt)
{
    const double nuDt = m_settings.viscosity * dt;
    const auto grids = faceGrids(m_velocity);
    const auto values = components(m_velocity);
    for (int c = 0; c < 2; ++c) {
        const FaceGrid& g = grids[c];
        PcgSolver& solver = m_viscositySolvers[c];
        solver.setStencil({g.interiorCols(), g.interiorRows(), 1.0, nuDt / (g.hx * g.hx),
                           nuDt / (g.hy * g.hy), g.normalX, !g.normalX});
        gatherInterior(g, *values[c], m_rhs);
        m_solution = m_rhs;
        solver.solve(m_solution, m_rhs, kViscosityRelativeTolerance * maxAbs(m_rhs),
                     iterationCap(g.cols, g.rows));
        scatterInterior(g, m_solution, *values[c]);
    }
}

// Pressure projection (Bridson ch. 5): solve -L p = -div u* with L the Neumann Laplacian of the
// cells (walls: zero normal flux), then u = u* - grad p on the interior faces, so that the
// discrete div u = 0. The time step and density are folded into p. Constants are the null space of
// this pure Neumann problem; the solver projects them out (the mean of div u* is the net flux
// through the walls, zero up to roundoff). The pressure of the previous step is the first guess.
void FluidSolver::project()
{
    const int nx = m_settings.nx, ny = m_settings.ny;
    const double hx = m_velocity.hx, hy = m_velocity.hy;
    m_rhs.resize(std::size_t(nx) * ny);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            m_rhs[std::size_t(j) * nx + i] = -cellDivergence(m_velocity, i, j);
    const double tolerance =
        std::max(m_settings.pressureTolerance, kPressureRoundoffFloor * maxAbs(m_rhs));
    m_pressureSolver.setStencil({nx, ny, 0.0, 1.0 / (hx * hx), 1.0 / (hy * hy), false, false});
    m_lastPressureIterations =
        m_pressureSolver.solve(m_pressure, m_rhs, tolerance, iterationCap(nx, ny));

    const auto grids = faceGrids(m_velocity);
    const auto values = components(m_velocity);
    for (int c = 0; c < 2; ++c) {
        const FaceGrid& g = grids[c];
        std::vector<double>& component = *values[c];
        // The face (i, j) separates cell (i, j) from the cell before it along the normal axis.
        const std::size_t previous = g.normalX ? 1 : std::size_t(nx);
        const double h = g.normalX ? hx : hy;
        forEachFace(g, interior(g), [&](std::size_t k, int i, int j) {
            const std::size_t cell = std::size_t(j) * nx + i;
            component[k] -= (m_pressure[cell] - m_pressure[cell - previous]) / h;
        });
    }
}

double FluidSolver::maxDivergence() const
{
    double m = 0.0;
    for (int j = 0; j < m_velocity.ny; ++j)
        for (int i = 0; i < m_velocity.nx; ++i)
            m = std::fmax(m, std::fabs(cellDivergence(m_velocity, i, j)));
    return m;
}

// The MAC-grid energy: each face carries a control volume hx * hy. In this inner product the
// gradient is minus the transpose of the divergence, so the projection is orthogonal and can only
// remove energy.
double FluidSolver::kineticEnergy() const
{
    double sum = 0.0;
    for (const std::vector<double>* values : {&m_velocity.u, &m_velocity.v})
        for (const double value : *values)
            sum += value * value;
    return 0.5 * sum * m_velocity.hx * m_velocity.hy;
}

// Largest speed of the cell-centre velocities (the average of each cell's two faces per axis).
double FluidSolver::maxSpeed() const
{
    double m = 0.0;
    for (int j = 0; j < m_velocity.ny; ++j)
        for (int i = 0; i < m_velocity.nx; ++i)
            m = std::fmax(m, glm::length(cellCenterVelocity(m_velocity, i, j)));
    return m;
}

} // namespace vf::sim
