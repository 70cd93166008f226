#include "sim/StreamFunction.h"

namespace vf::sim {

StreamField StreamField::of(const MacVelocity& field)
{
    StreamField s;
    s.nx = field.nx;
    s.ny = field.ny;
    s.hx = field.hx;
    s.hy = field.hy;
    const int stride = s.nx + 3, rows = s.ny + 3;
    s.psi.assign(std::size_t(stride) * rows, 0.0);
    auto at = [&s, stride](int i, int j) -> double& { return s.psi[std::size_t(j + 1) * stride + i + 1]; };

    for (int i = 1; i <= s.nx; ++i)
        at(i, 0) = at(i - 1, 0) - field.v[std::size_t(i - 1)] * s.hx;
    for (int i = 0; i <= s.nx; ++i)
        for (int j = 1; j <= s.ny; ++j)
            at(i, j) = at(i, j - 1) + field.u[std::size_t(j - 1) * (s.nx + 1) + i] * s.hy;
    // The top wall: the projection leaves up to its tolerance of flux through each cell, which the
    // sums up the columns carry there; the wall's one value makes that flux exactly zero.
    for (int i = 1; i <= s.nx; ++i)
        at(i, s.ny) = at(0, s.ny);

    // Odd reflection about the walls, x first, then y over the full padded width.
    for (int j = 0; j <= s.ny; ++j) {
        at(-1, j) = 2.0 * at(0, j) - at(1, j);
        at(s.nx + 1, j) = 2.0 * at(s.nx, j) - at(s.nx - 1, j);
    }
    for (int i = -1; i <= s.nx + 1; ++i) {
        at(i, -1) = 2.0 * at(i, 0) - at(i, 1);
        at(i, s.ny + 1) = 2.0 * at(i, s.ny) - at(i, s.ny - 1);
    }
    return s;
}

StreamField StreamField::average(const StreamField& a, const StreamField& b)
{
    StreamField mean = a;
    for (std::size_t k = 0; k < mean.psi.size(); ++k)
        mean.psi[k] = 0.5 * (a.psi[k] + b.psi[k]);
    return mean;
}

} // namespace vf::sim
