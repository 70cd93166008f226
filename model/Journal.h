#pragma once
// What was done to the live simulation between its states, so that the history can be played again
// as an animation (model/HistoryReplay.h). The simulation's thread writes it: every request it
// carries out and every pen part and drive it feeds a step is an entry, numbered by the steps taken
// before it. A snapshot seals the entries since the previous one into an immutable segment that
// points back to the one before, and its state slot keeps a mark of where it was taken. The inputs
// between two states of one line of work are the segments from the later mark back to the earlier.
#include "model/EngineSettings.h"
#include "sim/ExactMap.h"
#include "sim/Geometry.h"
#include "sim/Stylus.h"
#include "sim/TargetDrive.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

namespace vf::model {

namespace journal {
struct Drop {
    sim::Vec2 center;
    double radius;
};
// The large ones are shared, so that an entry (a pen part every step while a stroke is drawn)
// stays small.
struct Map {
    std::shared_ptr<const sim::ExactMap> map;
};
struct AddRegion {
    std::vector<sim::Polygon> contours;
};
struct RemoveRegion {
    int region;
};
struct Configure {
    std::shared_ptr<const EngineSettings> settings;
};
// Fed to one step, not requests between steps.
struct Pen {
    sim::StylusSegment part;
};
struct Drive {
    std::shared_ptr<const sim::TargetDrive> drive;
};
} // namespace journal

struct JournalEntry {
    std::int64_t step;  // steps taken on this line of work before it
    std::variant<journal::Drop, journal::Map, journal::AddRegion, journal::RemoveRegion, journal::Configure,
                 journal::Pen, journal::Drive> action;
};

struct JournalSegment {
    std::vector<JournalEntry> entries;
    std::shared_ptr<const JournalSegment> previous;
};

// Where a state was taken on its line of work: the newest segment then (never null for a state the
// simulation's thread took: a load starts a line with an empty segment), and the steps taken. A
// state read from a project file has no mark (a null head).
struct JournalMark {
    std::shared_ptr<const JournalSegment> head;
    std::int64_t step = 0;
};

// The entries from `from` to `to`, oldest first, with steps counted from `from`; nothing when `to`
// was not reached from `from` (a load or another line of work lies between) or either has no mark.
std::optional<std::vector<JournalEntry>> entriesBetween(const JournalMark& from, const JournalMark& to);

} // namespace vf::model
