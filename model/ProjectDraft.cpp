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
    p.stateMark = m_now->waitForMark();
    if (m_origin) {
        p.origin = m_origin->wait();
        p.originMark = m_origin->waitForMark();
    }
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
        if (r.before) {
            e.before = r.before->wait();
            e.beforeMark = r.before->waitForMark();
        }
        if (r.after) {
            e.after = r.after->wait();
            e.afterMark = r.after->waitForMark();
        }
        p.history.push_back(std::move(e));
    }
    return p;
}

std::vector<ReplaySpan> ProjectDraft::replaySpans(int* unrecorded) const
{
    return model::replaySpans(finish(), unrecorded);
}

} // namespace vf::model
