#include "sim/Coverage.h"

#include <algorithm>
#include <array>
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

// Blurs at least this wide (σ in cells) are three box blurs of about the same variance (within
// 5 %: odd widths come in steps), at a cost that does not grow with σ; a Gaussian's taps do, and
// the widest blurs of a target drive span the grid.
constexpr double kBoxesFrom = 8.0;

// The widths (odd) of three boxes whose blurs in turn have a variance nearest σ² (after Kovesi,
// "Fast almost-Gaussian filtering", 2010): m of width w, the rest w + 2, a box of width w adding
// (w² − 1)/12.
std::array<int, 3> boxWidths(double sigmaInCells)
{
    const double variance = sigmaInCells * sigmaInCells;
    int w = int(std::floor(std::sqrt(4.0 * variance + 1.0)));
    if (w % 2 == 0)
        --w;
    const auto of = [](int width) { return (double(width) * width - 1.0) / 12.0; };
    int best = 0;
    for (int m = 1; m <= 3; ++m)
        if (std::abs(m * of(w) + (3 - m) * of(w + 2) - variance) < std::abs(best * of(w) + (3 - best) * of(w + 2) - variance))
            best = m;
    return {0 < best ? w : w + 2, 1 < best ? w : w + 2, 2 < best ? w : w + 2};
}

// One box blur along every line: the mean of the `width` values about each (zero off the lattice).
void boxAlong(std::vector<double>& values, int length, int lines, std::size_t stride, std::size_t lineStride, int width)
{
    const int reach = width / 2;
    std::vector<double> line(std::size_t(length) + 2 * reach, 0.0);
    for (int l = 0; l < lines; ++l) {
        double* first = values.data() + l * lineStride;
        for (int i = 0; i < length; ++i)
            line[std::size_t(i + reach)] = first[i * stride];
        double sum = 0.0;
        for (int k = 0; k < width - 1; ++k)
            sum += line[std::size_t(k)];
        for (int i = 0; i < length; ++i) {
            sum += line[std::size_t(i + width - 1)];
            first[i * stride] = sum / width;
            sum -= line[std::size_t(i)];
        }
    }
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
    std::vector<double> out = field;
    // Along the rows (length cols, `rows` lines), then down the columns.
    const auto pass = [&](double sigmaInCells, int length, int lines, std::size_t stride, std::size_t lineStride) {
        if (sigmaInCells < kBoxesFrom) {
            out = blurAlong(out, length, lines, stride, lineStride, gaussianWeights(sigmaInCells));
            return;
        }
        for (const int width : boxWidths(sigmaInCells))
            boxAlong(out, length, lines, stride, lineStride, width);
    };
    pass(sigma * lattice.cols / lattice.width, lattice.cols, lattice.rows, 1, cols);
    pass(sigma * lattice.rows / lattice.height, lattice.rows, lattice.cols, cols, 1);
    return out;
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
