#pragma once
// Exact Euclidean distances on a lattice of cells, for the gathering term of target-driven design
// (sim/TargetDrive.h): how deep each cell lies inside a shape, or how far outside it.
#include "sim/Coverage.h"

#include <vector>

namespace vf::sim {

// For every cell, the distance in canvas units from its centre to the nearest centre of a cell
// where `seed` is true; infinity where no cell is. Felzenszwalb and Huttenlocher, "Distance
// Transforms of Sampled Functions" (2012): one pass along the rows and one along the columns,
// linear in the cells.
std::vector<double> distanceToSeeds(const std::vector<bool>& seed, const CellLattice& lattice);

// Inside cells (covered at least half) count their distance to the nearest outside cell, outside
// cells minus their distance to the nearest inside one: a field that rises by one per canvas unit
// towards the shape and on into its core. Zero everywhere for a shape that covers every cell or
// none.
std::vector<double> signedDepth(const std::vector<double>& covered, const CellLattice& lattice);

} // namespace vf::sim
