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
                         {{comb.from.x, comb.from.y, along.x, along.y}},
                         {{length, comb.sharpness, comb.spacing, double(comb.tines)}},
                         {{comb.amplitude, waveNumber, phase, 0.0}}};
}

std::optional<MapParameters> parametersOf(const CircularComb& comb)
{
    if (comb.angle == 0.0 || comb.tines < 1)
        return std::nullopt;
    return MapParameters{motionCircularComb,
                         {{comb.centre.x, comb.centre.y, comb.radius, comb.spacing}},
                         {{comb.angle, comb.sharpness, double(comb.tines), 0.0}}};
}

std::optional<MapParameters> parametersOf(const Swirl& swirl)
{
    if (swirl.angle == 0.0)
        return std::nullopt;
    return MapParameters{motionSwirl,
                         {{swirl.centre.x, swirl.centre.y, swirl.radius, swirl.angle}}};
}

} // namespace

std::optional<MapParameters> mapParameters(const ExactMap& map)
{
    return std::visit([](const auto& m) { return parametersOf(m); }, map);
}

} // namespace vf::sim::opencl
