#pragma once
// Taking one region out of a simulation state, for deleting it: the contours of the others stay
// exactly as they are, so undoing the deletion (restoring the state from before) and redoing it
// (this again) give the same numbers.
#include "sim/SimulationState.h"

namespace vf::model {

// `state` without region `region`'s contours; regions above it move down one index, so the
// region indices stay 0 .. regionCount - 1. A region that does not exist changes nothing.
sim::SimulationState withoutRegion(sim::SimulationState state, int region);

} // namespace vf::model
