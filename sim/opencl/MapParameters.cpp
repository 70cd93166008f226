#include "sim/opencl/MapParameters.h"

#include "sim/opencl/ContourCodes.h"

#include <glm/geometric.hpp>

#include <numbers>

namespace vf::sim::opencl {

namespace {

std::optional<MapParameters> parametersOf(const Comb& comb)
{
    const Vec2 stroke = comb.to - comb.from;
    const double length = glm::length(stroke);
    if (!(length > 0.0) || comb.tines < 1)
        return std::nullopt;
    const Vec2 along = stroke / length;
    // The wave's phase at the origin: t is measured from the stroke's middle.
    const double waveNumber = 2.0 * std::numbers::pi / comb.wavelength;
    const double phase = comb.phase - waveNumber * glm::dot(0.5 * (comb.from + comb.to), along);
    return MapParameters{motionComb,
                         {{cl_float(comb.from.x), cl_float(comb.from.y), cl_float(along.x), cl_float(along.y)}},
                         {{cl_float(length), cl_float(comb.sharpness), cl_float(comb.spacing), cl_float(comb.tines)}},
                         {{cl_float(comb.amplitude), cl_float(waveNumber), cl_float(phase), 0.0f}}};
}

std::optional<MapParameters> parametersOf(const CircularComb& comb)
{
    if (comb.angle == 0.0 || comb.tines < 1)
        return std::nullopt;
    return MapParameters{motionCircularComb,
                         {{cl_float(comb.centre.x), cl_float(comb.centre.y), cl_float(comb.radius), cl_float(comb.spacing)}},
                         {{cl_float(comb.angle), cl_float(comb.sharpness), cl_float(comb.tines), 0.0f}}};
}

std::optional<MapParameters> parametersOf(const Swirl& swirl)
{
    if (swirl.angle == 0.0)
        return std::nullopt;
    return MapParameters{motionSwirl,
                         {{cl_float(swirl.centre.x), cl_float(swirl.centre.y), cl_float(swirl.radius), cl_float(swirl.angle)}}};
}

} // namespace

std::optional<MapParameters> mapParameters(const ExactMap& map)
{
    return std::visit([](const auto& m) { return parametersOf(m); }, map);
}

} // namespace vf::sim::opencl
