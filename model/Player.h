#pragma once
// A simulation played forward a step at a time, and its picture: a scene from its start
// (model/SceneRunner.h) or the document's history again (model/HistoryReplay.h). An animation's
// frames are taken from one (app/SceneFrames.h).
#include "model/Drawing.h"
#include "sim/Simulation.h"

#include <cstdint>

namespace vf::model {

class Player {
public:
    virtual ~Player() = default;

    virtual double dt() const = 0;  // seconds a step plays
    virtual std::int64_t stepsDone() const = 0;
    virtual sim::StepReport step() = 0;
    virtual Drawing drawing() const = 0;
    virtual const sim::Simulation& simulation() const = 0;
};

} // namespace vf::model
