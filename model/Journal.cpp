#include "model/Journal.h"

namespace vf::model {

std::optional<std::vector<JournalEntry>> entriesBetween(const JournalMark& from, const JournalMark& to)
{
    if (!from.head || !to.head || to.step < from.step)
        return std::nullopt;
    std::vector<const JournalSegment*> segments;  // newest first
    const JournalSegment* segment = to.head.get();
    for (; segment && segment != from.head.get(); segment = segment->previous.get())
        segments.push_back(segment);
    if (!segment)
        return std::nullopt;
    std::vector<JournalEntry> entries;
    for (auto s = segments.rbegin(); s != segments.rend(); ++s)
        for (JournalEntry entry : (*s)->entries) {
            entry.step -= from.step;
            entries.push_back(std::move(entry));
        }
    return entries;
}

} // namespace vf::model
