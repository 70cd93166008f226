#pragma once
// The document's history played again, as it was made, for an animation of it (File ▸ Export
// Animation, "the history"): each done command that acted on the simulation, from its starting
// state, given again at the same steps what the live simulation was given over its span (its
// drops, maps, regions added or removed, settings, pen parts and gather drives: model/Journal.h),
// with the scene's own timed tools, on a simulation of its own. Each span starts from its
// command's recorded state, so where the replay's backend rounds differently from the live one the
// difference never carries into the next command.
#include "model/EngineSettings.h"
#include "model/Journal.h"
#include "model/Player.h"
#include "model/Project.h"
#include "model/Regions.h"
#include "model/SceneRunner.h"
#include "model/SceneScript.h"
#include "model/StateSlot.h"

#include <memory>
#include <vector>

namespace vf::model {

// One command's span: from its starting state, `steps` steps with `entries` (counted from it).
struct ReplaySpan {
    StatePtr start;
    std::vector<JournalEntry> entries;
    std::int64_t steps = 0;
    RegionTable looks;        // over the span: those at the command's end
    EngineSettings settings;  // at its start
};

// The line of work from the project's origin to its state through its done commands, as spans to
// play again, oldest first: each command's, and the flow between them. Commands whose span the
// journal does not hold (a project written without one) are left out and counted in `unrecorded`
// (when given).
std::vector<ReplaySpan> replaySpans(const Project& project, int* unrecorded = nullptr);

// Seconds of simulated time the spans take together, at `dt` a step.
double replayDuration(const std::vector<ReplaySpan>& spans, double dt);

class HistoryReplay final : public Player {
public:
    // `scene`: the document's (its canvas and timed tools). Throws std::invalid_argument (one line)
    // when there is no span or the backend refuses a span's settings.
    HistoryReplay(Scene scene, std::vector<ReplaySpan> spans,
                  const SimulationFactory& factory = sim::makeReferenceSimulation);

    double duration() const { return replayDuration(m_spans, dt()); }

    double dt() const override { return m_scene.time.dt; }
    std::int64_t stepsDone() const override { return m_steps; }
    // After the last span the picture holds.
    sim::StepReport step() override;
    Drawing drawing() const override;
    const sim::Simulation& simulation() const override { return *m_simulation; }

private:
    void begin(std::size_t span);
    // A simulation for `settings`, carrying `state`.
    void build(const EngineSettings& settings, const sim::SimulationState& state);
    void applyRequest(const JournalEntry& entry);

    Scene m_scene;
    SceneScript m_script;
    SimulationFactory m_factory;
    std::vector<ReplaySpan> m_spans;
    std::unique_ptr<sim::Simulation> m_simulation;
    EngineSettings m_settings;
    std::size_t m_span = 0;
    std::size_t m_next = 0;           // the span's first entry not yet applied
    std::int64_t m_spanSteps = 0;     // steps taken in the span
    std::int64_t m_steps = 0;
};

} // namespace vf::model
