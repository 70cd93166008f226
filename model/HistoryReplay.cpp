#include "model/HistoryReplay.h"

#include "model/RegionRemoval.h"

#include <stdexcept>

namespace vf::model {

namespace {

bool isFedToAStep(const JournalEntry& entry)
{
    return std::holds_alternative<journal::Pen>(entry.action) || std::holds_alternative<journal::Drive>(entry.action);
}

} // namespace

HistoryReplay::HistoryReplay(Scene scene, std::vector<ReplaySpan> spans, const SimulationFactory& factory)
    : m_scene(std::move(scene)), m_script(m_scene), m_factory(factory), m_spans(std::move(spans))
{
    if (m_spans.empty())
        throw std::invalid_argument("the history holds no step that can be played again");
    begin(0);
}

std::vector<ReplaySpan> replaySpans(const Project& project, int* unrecorded)
{
    std::vector<ReplaySpan> spans;
    int left = 0;
    // From `from` (taken at `start`) to `end` with these looks and settings; whether the journal
    // holds it.
    const auto span = [&spans](const StatePtr& from, const JournalMark& start, const JournalMark& end,
                               const RegionTable& looks, const FlowSpec& flow, const TrackingSpec& tracking) {
        if (!from)
            return false;
        std::optional<std::vector<JournalEntry>> entries = entriesBetween(start, end);
        if (!entries)
            return false;
        if (end.step > start.step)  // a span without steps shows nothing: the next starts where it ends
            spans.push_back({from, std::move(*entries), end.step - start.step, looks, EngineSettings{flow, tracking}});
        return true;
    };
    StatePtr reached = project.origin;
    JournalMark reachedMark = project.originMark;
    for (int i = 0; i < project.historyIndex; ++i) {
        const HistoryEntry& e = project.history[std::size_t(i)];
        if (!e.before)  // a look edit
            continue;
        span(reached, reachedMark, e.beforeMark, e.regionsBefore, e.flowBefore, e.trackingBefore);  // the flow before it
        if (!span(e.before, e.beforeMark, e.afterMark, e.regionsAfter, e.flowBefore, e.trackingBefore))
            ++left;
        reached = e.after;
        reachedMark = e.afterMark;
    }
    span(reached, reachedMark, project.stateMark, project.regions, project.scene.flow, project.scene.tracking);
    if (unrecorded)
        *unrecorded = left;
    return spans;
}

double replayDuration(const std::vector<ReplaySpan>& spans, double dt)
{
    std::int64_t steps = 0;
    for (const ReplaySpan& span : spans)
        steps += span.steps;
    return double(steps) * dt;
}

void HistoryReplay::build(const EngineSettings& settings, const sim::SimulationState& state)
{
    Scene scene = m_scene;
    scene.flow = settings.flow;
    scene.tracking = settings.tracking;
    auto simulation = m_factory(simulationSettings(scene));
    simulation->restore(state);
    m_simulation = std::move(simulation);
    m_settings = settings;
}

void HistoryReplay::begin(std::size_t span)
{
    m_span = span;
    m_next = 0;
    m_spanSteps = 0;
    build(m_spans[span].settings, *m_spans[span].start);
}

void HistoryReplay::applyRequest(const JournalEntry& entry)
{
    sim::Simulation& simulation = *m_simulation;
    std::visit(
        [&](const auto& action) {
            using Action = std::decay_t<decltype(action)>;
            if constexpr (std::is_same_v<Action, journal::Drop>)
                simulation.drop(action.center, action.radius);
            else if constexpr (std::is_same_v<Action, journal::Map>)
                simulation.applyMap(*action.map);
            else if constexpr (std::is_same_v<Action, journal::AddRegion>)
                simulation.addRegion(action.contours);
            else if constexpr (std::is_same_v<Action, journal::RemoveRegion>)
                simulation.restore(withoutRegion(simulation.snapshot(), action.region));
            else if constexpr (std::is_same_v<Action, journal::Configure>) {
                if (action.settings->flow != m_settings.flow || action.settings->tracking != m_settings.tracking)
                    build(*action.settings, simulation.snapshot());
            }
        },
        entry.action);
}

sim::StepReport HistoryReplay::step()
{
    ++m_steps;
    while (m_spanSteps >= m_spans[m_span].steps) {
        if (m_span + 1 == m_spans.size())
            return {};  // the end: the picture holds
        begin(m_span + 1);
    }
    const std::vector<JournalEntry>& entries = m_spans[m_span].entries;
    // The requests made before this step, in order; then what the step itself was fed.
    const sim::TargetDrive* drive = nullptr;
    std::vector<sim::StylusSegment> pens;
    for (; m_next < entries.size() && entries[m_next].step <= m_spanSteps; ++m_next) {
        const JournalEntry& entry = entries[m_next];
        if (!isFedToAStep(entry))
            applyRequest(entry);
        else if (const auto* pen = std::get_if<journal::Pen>(&entry.action))
            pens.push_back(pen->part);
        else
            drive = std::get<journal::Drive>(entry.action).drive.get();
    }
    ++m_spanSteps;
    return m_script.step(*m_simulation, m_simulation->time(), dt(), {drive, pens});
}

Drawing HistoryReplay::drawing() const
{
    return drawingOf(m_scene.canvas, m_spans[m_span].looks, m_simulation->regions());
}

} // namespace vf::model
