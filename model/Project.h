#pragma once
// A project (*.vfproj, docs/project-format.md): everything needed to reopen a piece of work
// exactly — its settings, the regions as they are now, the simulation state, and the undo history
// with the states it restores.
#include "model/Journal.h"
#include "model/Regions.h"
#include "model/Scene.h"
#include "sim/SimulationState.h"

#include <QString>

#include <memory>
#include <vector>

namespace vf::model {

// One undoable user action. `before`/`after` are the simulation states at its start and end;
// both are null for a command that leaves the simulation alone (a recolour, a rename, a reorder).
// Consecutive commands usually share a state (one's end is the next one's start): the writer
// stores each distinct state once.
struct HistoryEntry {
    QString text;  // as shown in the History dock
    RegionTable regionsBefore;
    RegionTable regionsAfter;
    std::shared_ptr<const sim::SimulationState> before;
    std::shared_ptr<const sim::SimulationState> after;
    // The flow and tracking settings at the start and end (they differ for a settings change).
    FlowSpec flowBefore, flowAfter;
    TrackingSpec trackingBefore, trackingAfter;
    // Where in the journal `before` and `after` were taken (model/Journal.h); null heads where it
    // is not known.
    JournalMark beforeMark, afterMark;
};

struct Project {
    // Canvas, flow, time and tracking settings in use, and the regions and scripted strokes of the
    // scene the work started from.
    Scene scene;
    RegionTable regions;          // as they are now
    sim::SimulationState state;   // as it is now
    std::int64_t steps = 0;       // steps taken so far
    std::vector<HistoryEntry> history;
    int historyIndex = 0;         // entries [0, historyIndex) are done, the rest undone (redoable)
    // The journal's marks of `state` and `origin`: what was done to the simulation between the
    // states, so that the history can be played again (model/HistoryReplay.h).
    JournalMark stateMark;
    // The state the work was opened at, where a replay of the history starts; null where unknown.
    std::shared_ptr<const sim::SimulationState> origin;
    JournalMark originMark;
};

} // namespace vf::model
