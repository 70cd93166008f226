#include "model/RegionRemoval.h"

#include <algorithm>

namespace vf::model {

sim::SimulationState withoutRegion(sim::SimulationState state, int region)
{
    if (region < 0 || region >= state.regionCount)
        return state;
    std::erase_if(state.contours, [region](const sim::Contour& c) { return c.region == region; });
    for (sim::Contour& c : state.contours)
        if (c.region > region)
            --c.region;
    --state.regionCount;
    return state;
}

} // namespace vf::model
