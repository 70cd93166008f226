#include "sim/DistanceField.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vf::sim {
namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();

// The squared distance transform of one line of n samples h apart, in place: f[q] becomes
// min_p (f[p] + ((q − p)·h)²), the lower envelope of parabolas rooted at the finite samples.
void squaredDistances(std::vector<double>& f, std::vector<double>& out, std::size_t n, double h)
{
    std::vector<std::size_t> root;  // the parabolas of the envelope, left to right
    std::vector<double> from;       // where each one starts to be the lowest
    for (std::size_t q = 0; q < n; ++q) {
        if (f[q] == kFar)
            continue;
        double start = -kFar;
        while (!root.empty()) {
            const std::size_t p = root.back();
            // Where the parabolas of p and q meet (in units of h).
            start = ((f[q] / (h * h) + double(q) * double(q)) - (f[p] / (h * h) + double(p) * double(p))) /
                    (2.0 * double(q - p));
            if (start > from.back())
                break;
            root.pop_back();
            from.pop_back();
            start = -kFar;
        }
        root.push_back(q);
        from.push_back(start);
    }
    std::size_t k = 0;
    for (std::size_t q = 0; q < n; ++q) {
        if (root.empty()) {
            out[q] = kFar;
            continue;
        }
        while (k + 1 < root.size() && from[k + 1] <= double(q))
            ++k;
        const double d = (double(q) - double(root[k])) * h;
        out[q] = f[root[k]] + d * d;
    }
}

} // namespace

std::vector<double> distanceToSeeds(const std::vector<bool>& seed, const CellLattice& lattice)
{
    const auto cols = std::size_t(lattice.cols), rows = std::size_t(lattice.rows);
    const double hx = lattice.width / lattice.cols, hy = lattice.height / lattice.rows;
    std::vector<double> squared(lattice.size());
    for (std::size_t k = 0; k < squared.size(); ++k)
        squared[k] = seed[k] ? 0.0 : kFar;
    std::vector<double> line(std::max(cols, rows)), done(line.size());
    for (std::size_t j = 0; j < rows; ++j) {
        std::copy_n(squared.begin() + std::ptrdiff_t(j * cols), cols, line.begin());
        squaredDistances(line, done, cols, hx);
        std::copy_n(done.begin(), cols, squared.begin() + std::ptrdiff_t(j * cols));
    }
    for (std::size_t i = 0; i < cols; ++i) {
        for (std::size_t j = 0; j < rows; ++j)
            line[j] = squared[j * cols + i];
        squaredDistances(line, done, rows, hy);
        for (std::size_t j = 0; j < rows; ++j)
            squared[j * cols + i] = std::sqrt(done[j]);
    }
    return squared;
}

std::vector<double> signedDepth(const std::vector<double>& covered, const CellLattice& lattice)
{
    std::vector<bool> inside(covered.size()), outside(covered.size());
    for (std::size_t k = 0; k < covered.size(); ++k) {
        inside[k] = covered[k] >= 0.5;
        outside[k] = !inside[k];
    }
    const std::vector<double> toOutside = distanceToSeeds(outside, lattice);
    const std::vector<double> toInside = distanceToSeeds(inside, lattice);
    // A shape that covers every cell, or none, has no edge to measure from: flat there.
    const auto finite = [](double d) { return d == kFar ? 0.0 : d; };
    std::vector<double> depth(covered.size());
    for (std::size_t k = 0; k < covered.size(); ++k)
        depth[k] = inside[k] ? finite(toOutside[k]) : -finite(toInside[k]);
    return depth;
}

} // namespace vf::sim
