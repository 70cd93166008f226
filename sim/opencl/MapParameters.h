#pragma once
// A tool's exact map (sim/ExactMap.h) as the contour kernels take it (MOTION_ARGS in contours.cl):
// its motion kind and up to three vectors of parameters, in the accumulation type (double on fp64
// devices, else float).
#include "sim/ExactMap.h"
#include "sim/opencl/OpenCl.h"

#include <array>
#include <optional>

namespace vf::sim::opencl {

using Parameters = std::array<double, 4>;

struct MapParameters {
    cl_int kind;
    Parameters a{}, b{}, c{};
};

// None for a map that moves nothing.
std::optional<MapParameters> mapParameters(const ExactMap& map);

} // namespace vf::sim::opencl
