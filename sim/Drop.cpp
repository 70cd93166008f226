#include "sim/Drop.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace vf::sim {

Vec2 DropPush::operator()(Vec2 p) const
{
    const Vec2 d = p - centre;
    const double l2 = glm::dot(d, d);
    if (l2 == 0.0)
        return centre + Vec2(radius, 0.0);  // the centre itself: any direction is as good
    return centre + d * std::sqrt(1.0 + radius * radius / l2);
}

} // namespace vf::sim
