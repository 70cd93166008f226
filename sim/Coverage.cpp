#include "sim/Coverage.h"

#include <algorithm>
#include <cmath>

namespace vf::sim {
namespace {

// The samples of one row of points (x = (k + 0.5) · step, k < count) inside the spans between
// sorted crossings [x0, x1), [x2, x3), ..., marked.
void markSpans(const std::vector<double>& crossings, double step, char* inside, int count)
{
    for (std::size_t s = 0; s + 1 < crossings.size(); s += 2) {
        const int first = std::max(0, int(std::ceil(crossings[s] / step - 0.5)));
        const int end = std::min(count, int(std::ceil(crossings[s + 1] / step - 0.5)));
        for (int k = first; k < end; ++k)
            inside[k] = 1;
    }
}

// Calls f(row, inside) for each row of a (cols · samples) x (rows · samples) raster of points, with
// inside[k] set where point k lies in some shape (each even-odd). Each edge is visited once, and
// adds its crossing to the rows of points it spans: the work is the edges and the crossings, not
// the edges times the rows.
template <class F>
void rasterise(const std::vector<std::vector<Polygon>>& shapes, const CellLattice& lattice, int samples, F&& f)
{
    const int columns = lattice.cols * samples, rows = lattice.rows * samples;
    const double stepX = lattice.width / columns, stepY = lattice.height / rows;
    std::vector<char> inside(std::size_t(columns) * rows, 0);
    std::vector<std::vector<double>> crossings(rows);
    for (const std::vector<Polygon>& shape : shapes) {
        for (const Polygon& p : shape)
            for (std::size_t i = 0, n = p.size(); i < n; ++i) {
                const Vec2 a = p[i], b = p[(i + 1) % n];
                // Rows at y with exactly one end above: y in [min, max) of the ends' heights.
                const double lo = std::min(a.y, b.y) / stepY - 0.5, hi = std::max(a.y, b.y) / stepY - 0.5;
                const int first = int(std::clamp(std::ceil(lo), 0.0, double(rows)));
                const int end = int(std::clamp(std::ceil(hi), 0.0, double(rows)));
                for (int row = first; row < end; ++row) {
                    const double y = (row + 0.5) * stepY;
                    crossings[row].push_back(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
                }
            }
        for (int row = 0; row < rows; ++row) {
            std::sort(crossings[row].begin(), crossings[row].end());
            markSpans(crossings[row], stepX, inside.data() + std::size_t(row) * columns, columns);
            crossings[row].clear();
        }
    }
    for (int row = 0; row < rows; ++row)
        f(row, inside.data() + std::size_t(row) * columns, columns);
}

std::vector<double> gaussianWeights(double sigmaInCells)
{
    const int reach = std::max(1, int(std::ceil(4.0 * sigmaInCells)));
    std::vector<double> w(2 * reach + 1);
    double sum = 0.0;
    for (int k = -reach; k <= reach; ++k)
        sum += w[k + reach] = std::exp(-0.5 * k * k / (sigmaInCells * sigmaInCells));
    for (double& x : w)
        x /= sum;
    return w;
}

// One pass of a separable blur: along rows (stride 1) or columns (stride cols).
std::vector<double> blurAlong(const std::vector<double>& in, int length, int lines, std::size_t stride,
                              std::size_t lineStride, const std::vector<double>& weights)
{
    std::vector<double> out(in.size(), 0.0);
    const int reach = int(weights.size() / 2);
    for (int line = 0; line < lines; ++line)
        for (int i = 0; i < length; ++i) {
            double sum = 0.0;
            for (int k = std::max(-reach, -i); k <= std::min(reach, length - 1 - i); ++k)
                sum += weights[k + reach] * in[line * lineStride + (i + k) * stride];
            out[line * lineStride + i * stride] = sum;
        }
    return out;
}

} // namespace

std::vector<double> coverage(const std::vector<std::vector<Polygon>>& shapes, const CellLattice& lattice, int samples)
{
    std::vector<double> cells(lattice.size(), 0.0);
    const double share = 1.0 / (samples * samples);
    rasterise(shapes, lattice, samples, [&](int row, const char* inside, int count) {
        double* line = cells.data() + std::size_t(row / samples) * lattice.cols;
        for (int k = 0; k < count; ++k)
            line[k / samples] += inside[k] * share;
    });
    return cells;
}

std::vector<double> gaussianBlur(const std::vector<double>& field, const CellLattice& lattice, double sigma)
{
    const std::size_t cols = lattice.cols;
    const std::vector<double> across = blurAlong(field, lattice.cols, lattice.rows, 1, cols,
                                                 gaussianWeights(sigma * lattice.cols / lattice.width));
    return blurAlong(across, lattice.rows, lattice.cols, cols, 1, gaussianWeights(sigma * lattice.rows / lattice.height));
}

double intersectionOverUnion(const std::vector<std::vector<Polygon>>& ink, const std::vector<Polygon>& target,
                             const CellLattice& lattice)
{
    std::vector<std::vector<char>> inked(lattice.rows);
    rasterise(ink, lattice, 1, [&](int row, const char* inside, int count) { inked[row].assign(inside, inside + count); });
    std::size_t both = 0, either = 0;
    rasterise({target}, lattice, 1, [&](int row, const char* inside, int count) {
        for (int k = 0; k < count; ++k) {
            both += inked[row][k] && inside[k];
            either += inked[row][k] || inside[k];
        }
    });
    return either == 0 ? 0.0 : double(both) / double(either);
}

} // namespace vf::sim
