#pragma once
// Preconditioned conjugate gradient for the symmetric positive (semi-)definite 5-point systems
// of the fluid solver: implicit viscosity and the pressure Poisson equation.
#include <cstddef>
#include <vector>

namespace vf::sim {

double maxAbs(const std::vector<double>& values);  // 0 for an empty vector

// The matrix  center * I + ax * Lx + ay * Ly  on an mx x my lattice of unknowns (row-major, x
// fastest), with Lx, Ly the negated 1D second differences (2, -1 stencils, unscaled). At the ends
// of a Dirichlet axis the missing neighbour is a fixed zero, so the end cell keeps the full
// diagonal; at the ends of a Neumann axis there is no flux, so that neighbour drops out of the
// diagonal too.
struct Stencil5 {
    int mx = 0, my = 0;
    double center = 0.0;
    double ax = 0.0, ay = 0.0;  // >= 0
    bool dirichletX = false, dirichletY = false;

    bool operator==(const Stencil5&) const = default;
    // Pure Neumann with no identity part: constants form the null space.
    bool singular() const { return center == 0.0 && !dirichletX && !dirichletY; }
};

// CG preconditioned with one multigrid V-cycle (MGPCG, McAdams, Sifakis & Teran 2010): the
// iteration count stays nearly flat from 64^2 to 512^2 cells, where incomplete Cholesky needs
// hundreds. Every part of the cycle (red-black Gauss-Seidel, restriction, prolongation) is
// data-parallel, for the OpenCL port.
class PcgSolver {
public:
    // Rebuilds the multigrid hierarchy only when the stencil differs from the current one.
    void setStencil(const Stencil5& stencil);

    // After setStencil: improves x (the initial guess, mx * my values) until
    // max_k |(b - A x)_k| <= tolerance, or maxIterations.
    // Returns the number of iterations (0 when the guess already satisfies the tolerance).
    // For a singular stencil the mean of the residual is projected out (the component of b that
    // no x can reach), and x is returned with zero mean.
    int solve(std::vector<double>& x, const std::vector<double>& b, double tolerance,
              int maxIterations);

private:
    // One level of the hierarchy: a symmetric 5-point matrix with per-cell coefficients,
    // (A x)_k = diagonal_k x_k - sum over the 4 neighbours of coupling * x_neighbour.
    // Every array has a ring of ghost cells (stride mx + 2) whose couplings and values stay zero,
    // so the loops need no edge cases.
    struct Level {
        int mx = 0, my = 0;
        double strengthX = 0.0, strengthY = 0.0;  // interior couplings along x and along y
        std::vector<double> ownDiagonal;  // diagonal minus couplings: identity, Dirichlet ends
        std::vector<double> east, south;  // coupling of cell k to k + 1 and to k + stride
        std::vector<double> inverseDiagonal;
        std::vector<double> x, b, r;      // V-cycle scratch (coarse levels)

        std::size_t stride() const { return std::size_t(mx) + 2; }
        std::size_t index(int i, int j) const { return (std::size_t(j) + 1) * stride() + i + 1; }
        std::size_t cells() const { return std::size_t(mx) * std::size_t(my); }
    };

    static Level fineLevel(const Stencil5& stencil);
    static Level coarsen(const Level& fine);
    static void allocate(Level& level);
    static void finish(Level& level);
    static void multiply(const Level& level, const std::vector<double>& x, std::vector<double>& y);
    static void relax(const Level& level, const std::vector<double>& b, std::vector<double>& x,
                      int colour);
    void cycle(std::size_t l, const std::vector<double>& b, std::vector<double>& x);
    void removeMeanIfSingular(std::vector<double>& x) const;
    void pad(const std::vector<double>& in, std::vector<double>& out) const;
    void unpad(const std::vector<double>& in, std::vector<double>& out) const;

    Stencil5 m_stencil;
    std::vector<Level> m_levels;
    // Fine-level CG vectors, padded like the levels: unknowns, right-hand side, residual,
    // preconditioned residual, search direction, A times the direction.
    std::vector<double> m_x, m_b, m_r, m_z, m_d, m_q;
};

} // namespace vf::sim
