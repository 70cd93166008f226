// What a draft of the document (model/Document.h, ProjectDraft) gives once its states are taken:
// the project to save, and the spans of the history to play again.
#include "model/Document.h"

namespace vf::model {

Project ProjectDraft::finish() const
{
    Project p;
    p.scene = m_scene;
    p.regions = m_regions;
    p.steps = m_steps;
    p.state = *m_now->wait();
    p.historyIndex = m_index;
    for (const CommandRecord& r : m_records) {
        HistoryEntry e;
        e.text = r.text;
        e.regionsBefore = r.regionsBefore;
        e.regionsAfter = r.regionsAfter;
        e.flowBefore = r.settingsBefore.flow;
        e.trackingBefore = r.settingsBefore.tracking;
        e.flowAfter = r.settingsAfter.flow;
        e.trackingAfter = r.settingsAfter.tracking;
        e.before = r.before ? r.before->wait() : nullptr;
        e.after = r.after ? r.after->wait() : nullptr;
        p.history.push_back(std::move(e));
    }
    return p;
}

std::vector<ReplaySpan> ProjectDraft::replaySpans(int* unrecorded) const
{
    std::vector<ReplaySpan> spans;
    int left = 0;
    // From `from` to `to` with these looks and settings; whether the journal holds it.
    const auto span = [&spans](const StateSlotPtr& from, const StateSlotPtr& to, const RegionTable& looks,
                               const EngineSettings& settings) {
        if (!from || !to)
            return false;
        const JournalMark start = from->waitForMark(), end = to->waitForMark();
        std::optional<std::vector<JournalEntry>> entries = entriesBetween(start, end);
        if (!entries)
            return false;
        if (end.step > start.step)  // a span without steps shows nothing: the next starts where it ends
            spans.push_back({from->wait(), std::move(*entries), end.step - start.step, looks, settings});
        return true;
    };
    StateSlotPtr reached = m_origin;
    for (int i = 0; i < m_index; ++i) {
        const CommandRecord& r = m_records[std::size_t(i)];
        if (!r.touchesSimulation())
            continue;
        span(reached, r.before, r.regionsBefore, r.settingsBefore);  // the flow before it, if any
        if (!span(r.before, r.after, r.regionsAfter, r.settingsBefore))
            ++left;
        reached = r.after;
    }
    span(reached, m_now, m_regions, m_settings);
    if (unrecorded)
        *unrecorded = left;
    return spans;
}

} // namespace vf::model
