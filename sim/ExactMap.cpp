#include "sim/ExactMap.h"

namespace vf::sim {

Vec2 mapped(const ExactMap& map, Vec2 p)
{
    return std::visit([p](const auto& m) { return m(p); }, map);
}

ExactMap inverse(const ExactMap& map)
{
    return std::visit([](const auto& m) { return ExactMap(m.inverse()); }, map);
}

std::optional<double> creaseCrossing(const ExactMap& map, Vec2 a, Vec2 b)
{
    if (const auto* comb = std::get_if<Comb>(&map))
        return comb->tineCrossing(a, b);
    if (const auto* circular = std::get_if<CircularComb>(&map))
        return circular->tineCrossing(a, b);
    return std::nullopt;
}

} // namespace vf::sim
