#pragma once
// Ink on a lattice: how much of each cell the regions cover, for target-driven design (the ink and
// target densities of sim/TargetDrive.h) and for measuring how well ink fills a shape.
#include "sim/Geometry.h"

#include <vector>

namespace vf::sim {

// A cols x rows lattice of cells over a width x height canvas, row-major, row 0 at y = 0.
struct CellLattice {
    int cols = 0, rows = 0;
    double width = 1.0, height = 1.0;

    std::size_t size() const { return std::size_t(cols) * rows; }
};

// The share of each cell inside at least one of `shapes` (each a set of contours filled together,
// even-odd), from samples × samples points spread evenly over it.
std::vector<double> coverage(const std::vector<std::vector<Polygon>>& shapes, const CellLattice& lattice, int samples);

// A Gaussian blur of a field on the lattice with standard deviation `sigma` in canvas units; the
// canvas is surrounded by empty space (what leaves the lattice is lost). From σ of eight cells on,
// an almost-Gaussian one of three box blurs of about the same variance, whose cost does not grow
// with σ.
std::vector<double> gaussianBlur(const std::vector<double>& field, const CellLattice& lattice, double sigma);

// Intersection over union of the ink and a target, from one point per cell of `lattice` (cells
// counted inside or not): 1 when they cover the same cells, 0 when they share none or both are
// empty.
double intersectionOverUnion(const std::vector<std::vector<Polygon>>& ink, const std::vector<Polygon>& target,
                             const CellLattice& lattice);

} // namespace vf::sim
