#include "sim/LinearSolve.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vf::sim {
namespace {

// Red-black Gauss-Seidel sweeps before and after each coarse-grid correction.
constexpr int kSmoothingSweeps = 2;
// Coarsening stops at this many unknowns, where kCoarsestSweeps sweeps all but solve the system.
constexpr std::size_t kCoarsestSize = 16;
constexpr int kCoarsestSweeps = 20;

double dot(const std::vector<double>& a, const std::vector<double>& b)
{
    // Plain sequential sum: deterministic, and the reference the OpenCL port is checked against.
    return std::inner_product(a.begin(), a.end(), b.begin(), 0.0);
}

} // namespace

double maxAbs(const std::vector<double>& values)
{
    double m = 0.0;
    for (const double value : values) {
        const double magnitude = std::fabs(value);
        m = magnitude > m ? magnitude : m;  // one maxsd; std::fmax is a library call
    }
    return m;
}

void PcgSolver::setStencil(const Stencil5& stencil)
{
    if (stencil == m_stencil && !m_levels.empty())
        return;
    m_stencil = stencil;
    m_levels.clear();
    m_levels.push_back(fineLevel(stencil));
    while (m_levels.back().cells() > kCoarsestSize)
        m_levels.push_back(coarsen(m_levels.back()));
    const std::size_t n = m_levels.front().ownDiagonal.size();
    for (std::vector<double>* v : {&m_x, &m_b, &m_r, &m_z, &m_d, &m_q})
        v->assign(n, 0.0);
}

void PcgSolver::allocate(Level& level)
{
    const std::size_t n = level.stride() * (std::size_t(level.my) + 2);
    for (std::vector<double>* v : {&level.ownDiagonal, &level.east, &level.south,
                                   &level.inverseDiagonal, &level.x, &level.b, &level.r})
        v->assign(n, 0.0);
}

PcgSolver::Level PcgSolver::fineLevel(const Stencil5& s)
{
    Level level;
    level.mx = s.mx;
    level.my = s.my;
    level.strengthX = s.ax;
    level.strengthY = s.ay;
    allocate(level);
    for (int j = 0; j < s.my; ++j) {
        for (int i = 0; i < s.mx; ++i) {
            const std::size_t k = level.index(i, j);
            level.east[k] = i + 1 < s.mx ? s.ax : 0.0;
            level.south[k] = j + 1 < s.my ? s.ay : 0.0;
            const int wallsX = s.dirichletX ? (i == 0) + (i == s.mx - 1) : 0;
            const int wallsY = s.dirichletY ? (j == 0) + (j == s.my - 1) : 0;
            level.ownDiagonal[k] = s.center + s.ax * wallsX + s.ay * wallsY;
        }
    }
    finish(level);
    return level;
}

// Cells are grouped 2 x 2 (at an odd end a group is one cell wide), with piecewise-constant
// interpolation P and restriction P^T. The coarse matrix is the Galerkin product P^T A P with the
// couplings along a coarsened axis halved: for the Laplacian that is exactly the 5-point
// rediscretisation at twice the spacing, while plain Galerkin with constant interpolation is twice
// too stiff there and would make every coarse correction half as large as it should be.
// Long thin cells (a non-square canvas on a square grid, say) couple far more strongly along one
// axis; point smoothing then leaves error that is smooth only along that axis, so only that axis is
// coarsened (semi-coarsening, Trottenberg et al., "Multigrid", §5.1) until the couplings are
// within a factor of two of each other.
PcgSolver::Level PcgSolver::coarsen(const Level& fine)
{
    const bool alongX = fine.mx > 1 && (2.0 * fine.strengthX >= fine.strengthY || fine.my == 1);
    const bool alongY = fine.my > 1 && (2.0 * fine.strengthY >= fine.strengthX || fine.mx == 1);
    const int groupX = alongX ? 2 : 1, groupY = alongY ? 2 : 1;
    const double scaleX = alongX ? 0.5 : 1.0, scaleY = alongY ? 0.5 : 1.0;
    Level coarse;
    coarse.mx = (fine.mx + groupX - 1) / groupX;
    coarse.my = (fine.my + groupY - 1) / groupY;
    coarse.strengthX = fine.strengthX * scaleX * groupY;
    coarse.strengthY = fine.strengthY * scaleY * groupX;
    allocate(coarse);
    for (int j = 0; j < fine.my; ++j) {
        for (int i = 0; i < fine.mx; ++i) {
            const std::size_t k = fine.index(i, j);
            const std::size_t group = coarse.index(i / groupX, j / groupY);
            coarse.ownDiagonal[group] += fine.ownDiagonal[k];
            // Couplings inside a group cancel in P^T A P; those leaving it to the next group add.
            if (i % groupX == groupX - 1)
                coarse.east[group] += scaleX * fine.east[k];
            if (j % groupY == groupY - 1)
                coarse.south[group] += scaleY * fine.south[k];
        }
    }
    finish(coarse);
    return coarse;
}

void PcgSolver::finish(Level& level)
{
    const std::size_t s = level.stride();
    for (int j = 0; j < level.my; ++j) {
        for (int i = 0; i < level.mx; ++i) {
            const std::size_t k = level.index(i, j);
            const double couplings =
                level.east[k] + level.east[k - 1] + level.south[k] + level.south[k - s];
            level.inverseDiagonal[k] = 1.0 / (level.ownDiagonal[k] + couplings);
        }
    }
}

void PcgSolver::multiply(const Level& level, const std::vector<double>& x, std::vector<double>& y)
{
    const std::size_t s = level.stride();
    const double* own = level.ownDiagonal.data();
    const double* e = level.east.data();
    const double* so = level.south.data();
    for (int j = 0; j < level.my; ++j) {
        const std::size_t begin = level.index(0, j), end = begin + level.mx;
        for (std::size_t k = begin; k < end; ++k) {
            y[k] = own[k] * x[k] + e[k] * (x[k] - x[k + 1]) + e[k - 1] * (x[k] - x[k - 1])
                 + so[k] * (x[k] - x[k + s]) + so[k - s] * (x[k] - x[k - s]);
        }
    }
}

// One Gauss-Seidel half-sweep over the cells of one colour ((i + j) % 2 == colour). Cells of one
// colour only couple to the other colour, so each half-sweep is fully data-parallel.
void PcgSolver::relax(const Level& level, const std::vector<double>& b, std::vector<double>& x,
                      int colour)
{
    const std::size_t s = level.stride();
    const double* e = level.east.data();
    const double* so = level.south.data();
    const double* inverse = level.inverseDiagonal.data();
    for (int j = 0; j < level.my; ++j) {
        const std::size_t end = level.index(level.mx, j);
        for (std::size_t k = level.index((colour + j) % 2, j); k < end; k += 2) {
            x[k] = (b[k] + e[k] * x[k + 1] + e[k - 1] * x[k - 1] + so[k] * x[k + s]
                    + so[k - s] * x[k - s])
                 * inverse[k];
        }
    }
}

// x = V-cycle applied to b, from x = 0. The half-sweeps run in palindromic colour order around the
// coarse correction (red-black before, black-red after; red, then black-red pairs on the coarsest
// level), which makes the cycle a symmetric operator, as CG requires of its preconditioner.
void PcgSolver::cycle(std::size_t l, const std::vector<double>& b, std::vector<double>& x)
{
    Level& level = m_levels[l];
    std::fill(x.begin(), x.end(), 0.0);
    if (l + 1 == m_levels.size()) {
        relax(level, b, x, 0);
        for (int s = 0; s < kCoarsestSweeps; ++s) {
            relax(level, b, x, 1);
            relax(level, b, x, 0);
        }
        return;
    }
    for (int s = 0; s < kSmoothingSweeps; ++s) {
        relax(level, b, x, 0);
        relax(level, b, x, 1);
    }
    multiply(level, x, level.r);
    Level& coarse = m_levels[l + 1];
    const int groupX = level.mx == coarse.mx ? 1 : 2, groupY = level.my == coarse.my ? 1 : 2;
    std::fill(coarse.b.begin(), coarse.b.end(), 0.0);
    for (int j = 0; j < level.my; ++j)
        for (int i = 0; i < level.mx; ++i) {
            const std::size_t k = level.index(i, j);
            coarse.b[coarse.index(i / groupX, j / groupY)] += b[k] - level.r[k];
        }
    cycle(l + 1, coarse.b, coarse.x);
    for (int j = 0; j < level.my; ++j)
        for (int i = 0; i < level.mx; ++i)
            x[level.index(i, j)] += coarse.x[coarse.index(i / groupX, j / groupY)];
    for (int s = 0; s < kSmoothingSweeps; ++s) {
        relax(level, b, x, 1);
        relax(level, b, x, 0);
    }
}

// Ghost cells are zero and stay zero: the mean is over the real cells only.
void PcgSolver::removeMeanIfSingular(std::vector<double>& x) const
{
    if (!m_stencil.singular())
        return;
    const Level& fine = m_levels.front();
    const double mean = std::accumulate(x.begin(), x.end(), 0.0) / double(fine.cells());
    for (int j = 0; j < fine.my; ++j)
        for (int i = 0; i < fine.mx; ++i)
            x[fine.index(i, j)] -= mean;
}

void PcgSolver::pad(const std::vector<double>& in, std::vector<double>& out) const
{
    const Level& fine = m_levels.front();
    for (int j = 0; j < fine.my; ++j)
        std::copy_n(in.begin() + std::ptrdiff_t(j) * fine.mx, fine.mx,
                    out.begin() + std::ptrdiff_t(fine.index(0, j)));
}

void PcgSolver::unpad(const std::vector<double>& in, std::vector<double>& out) const
{
    const Level& fine = m_levels.front();
    for (int j = 0; j < fine.my; ++j)
        std::copy_n(in.begin() + std::ptrdiff_t(fine.index(0, j)), fine.mx,
                    out.begin() + std::ptrdiff_t(j) * fine.mx);
}

// Preconditioned CG (Bridson, "Fluid Simulation for Computer Graphics", 2nd ed., Fig. 5.1),
// stopping on the max norm of the recursively updated residual. For a singular matrix only the
// initial residual needs its mean removed: every later update is A times something, which has
// zero mean, and the constant part the preconditioner adds to x is removed at the end. The loop
// also stops when r.z or d.Ad is not positive, which only happens on breakdown (NaN input, or
// roundoff at an already converged solution).
int PcgSolver::solve(std::vector<double>& x, const std::vector<double>& b, double tolerance,
                     int maxIterations)
{
    const Level& fine = m_levels.front();
    const std::size_t n = m_x.size();
    pad(x, m_x);
    pad(b, m_b);
    multiply(fine, m_x, m_q);
    for (std::size_t k = 0; k < n; ++k)
        m_r[k] = m_b[k] - m_q[k];
    removeMeanIfSingular(m_r);

    int iterations = 0;
    if (!(maxAbs(m_r) <= tolerance)) {
        cycle(0, m_r, m_z);
        m_d = m_z;
        double rho = dot(m_r, m_z);
        while (iterations < maxIterations && rho > 0.0) {
            ++iterations;
            multiply(fine, m_d, m_q);
            const double curvature = dot(m_d, m_q);
            if (!(curvature > 0.0))
                break;
            const double alpha = rho / curvature;
            double residual = 0.0;
            for (std::size_t k = 0; k < n; ++k) {
                m_x[k] += alpha * m_d[k];
                m_r[k] -= alpha * m_q[k];
                const double magnitude = std::fabs(m_r[k]);
                residual = magnitude > residual ? magnitude : residual;
            }
            if (residual <= tolerance)
                break;
            cycle(0, m_r, m_z);
            const double rhoNext = dot(m_r, m_z);
            const double beta = rhoNext / rho;
            rho = rhoNext;
            for (std::size_t k = 0; k < n; ++k)
                m_d[k] = m_z[k] + beta * m_d[k];
        }
    }
    removeMeanIfSingular(m_x);
    unpad(m_x, x);
    return iterations;
}

} // namespace vf::sim
