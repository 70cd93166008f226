#pragma once
// Plays a scene: builds a simulation from it, feeds its regions, drops and stylus strokes in at
// their times, and hands out the picture. Used by the headless command line and the app.
#include "model/Drawing.h"
#include "model/Player.h"
#include "model/Scene.h"
#include "model/SceneScript.h"
#include "sim/Simulation.h"

#include <functional>
#include <memory>

namespace vf::model {

using SimulationFactory = std::function<std::unique_ptr<sim::Simulation>(const sim::SimulationSettings&)>;

sim::SimulationSettings simulationSettings(const Scene& scene);

class SceneRunner final : public Player {
public:
    // Throws std::invalid_argument (one line) when the backend refuses the scene's settings.
    explicit SceneRunner(Scene scene, const SimulationFactory& factory = sim::makeReferenceSimulation);

    const Scene& scene() const { return m_scene; }
    const sim::Simulation& simulation() const override { return *m_simulation; }
    std::int64_t stepsDone() const override { return m_steps; }
    double dt() const override { return m_scene.time.dt; }
    // Whether a drop or a step has taken the vertex count to tracking.max_vertices.
    bool vertexLimitReached() const { return m_vertexLimitReached; }

    // One step of the scene's dt (or `dt` when given): drops whose time has come land first, then
    // the exact maps due act, then the stylus strokes' share of this interval acts on the fluid,
    // and a gather under way drives it, then the simulation steps.
    sim::StepReport step(double dt);
    sim::StepReport step() override { return step(m_scene.time.dt); }

    Drawing drawing() const override;
    // The name of simulation region `index` (a scene region or a landed drop).
    QString regionName(int index) const;

private:
    Scene m_scene;
    SceneScript m_script;
    std::unique_ptr<sim::Simulation> m_simulation;
    std::int64_t m_steps = 0;
    double m_clock = 0.0;
    bool m_vertexLimitReached = false;
};

} // namespace vf::model
