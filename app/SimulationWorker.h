#pragma once
// The live simulation, on its own thread (docs/ARCHITECTURE.md, "Threads"): it owns the Simulation (and so its OpenCL
// context, created on this thread), steps it while playing, runs the requests the GUI queues
// between steps, and hands out immutable frames. Frames do not queue: a new frame is made only
// once the GUI has taken the previous one. (Qt's mandelbrot example coalesces requests instead,
// through its `restart` flag.)
#include "app/KernelWarmUp.h"
#include "model/EngineSettings.h"
#include "model/Frame.h"
#include "model/Journal.h"
#include "model/SceneScript.h"
#include "model/StateSlot.h"
#include "sim/Simulation.h"
#include "sim/Stylus.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <deque>
#include <memory>
#include <mutex>
#include <optional>

namespace vf::app {

class SimulationWorker final : public QObject {
    Q_OBJECT

public:
    explicit SimulationWorker(QObject* parent = nullptr);
    ~SimulationWorker() override;

    // ---- Requests: called on the worker's thread, in the order the GUI made them. ------------
    void load(const model::Scene& scene, const model::EngineSettings& settings, const model::StateSlotPtr& start);
    void configure(const model::EngineSettings& settings);
    void snapshot(const model::StateSlotPtr& into);
    void restore(const model::StateSlotPtr& from);
    void addRegion(const std::vector<sim::Polygon>& contours);
    void removeRegion(int region);
    void drop(sim::Vec2 center, double radius);
    void applyMap(const sim::ExactMap& map);
    // The pens' motion is fed to the simulation over the steps its duration covers, one step's
    // worth a step: handed over whole, a pointer event's 20 ms would push during one step of 5 ms
    // and leave the water idle for three, and a viscous fluid would barely follow the pen. Pens
    // given together (a comb's tines) push in the same steps; later ones after them.
    void stylus(const std::vector<sim::StylusSegment>& pens);
    // SimulationPort::gather: each step until then drives the fluid from the ink as it is.
    void gather(const std::shared_ptr<const sim::TargetDrive>& drive, double duration);
    void setPlaying(bool playing);
    // While a stylus stroke is drawn the simulation runs even when paused, so that the water
    // answers the pen; it stops again with the stroke unless playing.
    void setStroking(bool stroking);
    void stepOnce();
    // Frames carry the velocity field only while the canvas shows it (a grid readback each).
    void setVelocityWanted(bool wanted) { m_velocityWanted = wanted; }
    // After each request: counts it (Frame::serial) and offers a frame showing its effect.
    void requestDone();
    // A request threw: stop playing and say why in one line.
    void fail(const std::exception& error);

    // ---- Any thread. --------------------------------------------------------------------------
    // The newest frame, once (null when there is none new). Taking it lets the next one be made.
    std::shared_ptr<const model::Frame> takeFrame();

signals:
    void frameReady();                           // takeFrame() has a new frame
    void failed(const QString& message);         // one line; playing stopped
    void notice(const QString& message);         // one line, e.g. a backend fallback
    void playingChanged(bool playing);

private:
    // A new simulation with these settings, carrying `state` when given (on the reference backend
    // if the chosen one cannot hold it); replaces the live one only on success. Throws otherwise.
    void build(const model::EngineSettings& settings, const sim::SimulationState* state);
    // The warm-up build() started is over: the simulation moves to the device (on an error, build()
    // falls back and says why).
    void kernelsCompiled(const QString& error);
    bool running() const { return m_playing || m_stroking; }
    // The app's gather's drive, if one is under way; null once it is over.
    std::shared_ptr<const sim::TargetDrive> activeDrive();
    // Adds to the journal (model/Journal.h) at the steps taken on this line of work.
    void record(decltype(model::JournalEntry::action) action);
    // A new line of work in the journal, or the line of `mark` carried on (a restored state's).
    void startJournal(const model::JournalMark& mark = {});
    void onRunningChanged(bool wasRunning);
    void step();
    void scheduleStep();
    void offerFrame();
    void startFrame();
    void stopWith(const QString& message);

    std::unique_ptr<sim::Simulation> m_simulation;
    model::Scene m_scene;
    std::optional<model::SceneScript> m_script;
    model::EngineSettings m_settings;
    QString m_backendLabel;
    QTimer m_stepTimer;
    KernelWarmUp m_warmUp;
    bool m_warmUpFailed = false;
    QElapsedTimer m_clock;         // paces playing to real time: one dt of simulated time per dt
    qint64 m_nextStepAt = 0;       // ms on m_clock
    bool m_playing = false;
    bool m_stroking = false;
    // Pen input not yet fed: for each step to come, the parts of the pens' moves it takes.
    std::deque<std::vector<sim::StylusSegment>> m_pen;
    // The journal: entries since the last snapshot, the newest sealed segment, steps on this line.
    std::vector<model::JournalEntry> m_entries;
    std::shared_ptr<const model::JournalSegment> m_journalHead;
    std::int64_t m_journalStep = 0;
    // The app's gather under way (SimulationPort::gather), until the simulated time `until`.
    struct Gather {
        std::shared_ptr<const sim::TargetDrive> drive;
        double until;
    };
    std::optional<Gather> m_gather;
    bool m_velocityWanted = false;
    std::uint64_t m_handled = 0;   // requests done
    std::int64_t m_steps = 0;
    double m_stepsPerSecond = 0.0;
    int m_stepsInWindow = 0;
    qint64 m_windowStart = 0;

    // The frame whose geometry is being copied (offerFrame), and the copy's request number.
    std::shared_ptr<model::Frame> m_copying;
    std::uint64_t m_copyRequest = 0;

    std::mutex m_frameMutex;       // guards the three below
    std::shared_ptr<const model::Frame> m_frame;  // made, not yet taken
    bool m_frameOut = false;       // a frame was signalled and not taken yet
    bool m_dirty = false;          // the state changed since the last frame
};

} // namespace vf::app
