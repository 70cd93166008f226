#pragma once
// The closed-form, area-preserving maps a marbler's tools apply to the ink at once (a drop's push
// is applied with its drop): combs straight or wavy, circular combs and swirls. Each is a
// bijection of the plane with an exact inverse, so it cannot change topology.
#include "sim/Comb.h"
#include "sim/Whirl.h"

#include <variant>

namespace vf::sim {

using ExactMap = std::variant<Comb, CircularComb, Swirl>;

// Where the map takes p.
Vec2 mapped(const ExactMap& map, Vec2 p);
ExactMap inverse(const ExactMap& map);
// Where the segment a–b crosses a crease of the map (a line or circle where it is not smooth), as
// a fraction along it; none for a smooth map.
std::optional<double> creaseCrossing(const ExactMap& map, Vec2 a, Vec2 b);

} // namespace vf::sim
