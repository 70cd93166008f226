#include "app/SimulationWorker.h"

#include "app/Backend.h"
#include "model/RegionRemoval.h"
#include "model/SceneRunner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vf::app {

namespace {

QString firstLine(const char* what)
{
    return QString::fromUtf8(what).section('\n', 0, 0);
}

} // namespace

SimulationWorker::SimulationWorker(QObject* parent)
    : QObject(parent)
    , m_stepTimer(this)  // children, so that they move to the worker's thread with it
    , m_warmUp(this)
{
    m_stepTimer.setSingleShot(true);
    connect(&m_stepTimer, &QTimer::timeout, this, &SimulationWorker::step);
    connect(&m_warmUp, &KernelWarmUp::finished, this, &SimulationWorker::kernelsCompiled);
    m_clock.start();
}

SimulationWorker::~SimulationWorker() = default;

void SimulationWorker::build(const model::EngineSettings& settings, const sim::SimulationState* state)
{
    model::Scene scene = m_scene;
    scene.flow = settings.flow;
    scene.tracking = settings.tracking;
    const sim::SimulationSettings simulationSettings = model::simulationSettings(scene);
    const std::optional<int> device = settings.device >= 0 ? std::optional<int>(settings.device) : std::nullopt;
    // A device whose kernels are not compiled yet: the reference backend runs until they are.
    const bool compiling = settings.backend != QLatin1String("reference") && !m_warmUpFailed &&
                           (m_warmUp.isRunning() || !KernelWarmUp::isReady(device));
    if (compiling)
        m_warmUp.start(device);
    QString fallback;
    std::unique_ptr<sim::Simulation> simulation =
        makeBackend(simulationSettings, compiling ? QStringLiteral("reference") : settings.backend, device, fallback);
    if (state) {
        try {
            simulation->restore(*state);
        } catch (const std::exception& e) {
            // The device cannot hold it (say, more vertices than its memory): the reference
            // backend can, so the work goes on there.
            if (simulation->backendName() == "reference")
                throw;
            fallback = tr("%1 cannot take this state (%2); using the reference backend")
                           .arg(backendLabel(*simulation), QString::fromUtf8(e.what()).section('\n', 0, 0));
            simulation = sim::makeReferenceSimulation(simulationSettings);
            simulation->restore(*state);
        }
    }
    m_simulation = std::move(simulation);
    m_copying.reset();
    m_settings = settings;
    m_backendLabel = backendLabel(*m_simulation);
    if (compiling)
        m_backendLabel += tr(", until the OpenCL kernels are compiled (first launch)");
    if (!fallback.isEmpty())
        emit notice(fallback.section('\n', 0, 0));
}

void SimulationWorker::kernelsCompiled(const QString& error)
{
    if (!m_simulation || m_settings.backend == QLatin1String("reference"))
        return;  // chosen meanwhile: it runs already
    // After a failed warm-up the backend is made without one: where the device cannot run,
    // build() says why as it falls back, and that is the one message.
    m_warmUpFailed = !error.isEmpty();
    configure(m_settings);
    if (m_simulation && m_simulation->backendName() != "reference")
        emit notice(error.isEmpty() ? tr("OpenCL kernels compiled: running on %1").arg(m_backendLabel)
                                    : tr("OpenCL warm-up failed (%1); running on %2").arg(error, m_backendLabel));
    {
        std::lock_guard lock(m_frameMutex);
        m_dirty = true;
    }
    offerFrame();
}

void SimulationWorker::load(const model::Scene& scene, const model::EngineSettings& settings, const model::StateSlotPtr& start)
{
    m_scene = scene;
    m_script.emplace(scene);
    m_steps = 0;
    m_pen.clear();
    m_gather.reset();
    startJournal(start ? start->waitForMark() : model::JournalMark{});  // a project's state carries its line on
    try {
        if (start) {
            build(settings, start->wait().get());
            return;
        }
        // The starting picture (the scene's regions and its drops at t = 0) is made on the
        // reference backend and handed over as a state, so that build() can keep it there when the
        // chosen device cannot hold it.
        model::EngineSettings reference = settings;
        reference.backend = QStringLiteral("reference");
        build(reference, nullptr);
        for (const model::RegionSpec& r : scene.regions)
            for (const model::StartingRegion& start : model::startingRegions(r, settings.tracking.maxSpacing))
                m_simulation->addRegion(start.contours);
        m_script->applyTools(*m_simulation, -INFINITY, 0.0);  // those at t = 0 make the starting picture
        if (settings.backend != reference.backend) {
            const sim::SimulationState picture = m_simulation->snapshot();
            build(settings, &picture);
        }
    } catch (const std::exception& e) {
        m_simulation.reset();
        m_copying.reset();
        stopWith(firstLine(e.what()));
    }
}

void SimulationWorker::configure(const model::EngineSettings& settings)
{
    if (!m_simulation)
        return;
    // The new simulation takes the old one's state; build() replaces the old one only once it
    // has, so on a failure the old one carries on.
    const sim::SimulationState state = m_simulation->snapshot();
    try {
        build(settings, &state);
        record(model::journal::Configure{std::make_shared<const model::EngineSettings>(settings)});
    } catch (const std::exception& e) {
        stopWith(firstLine(e.what()));
    }
}

void SimulationWorker::snapshot(const model::StateSlotPtr& into)
{
    // The slot is filled whatever happens, for someone may wait on it. Without a simulation (its
    // load failed) the state is empty, and a project holding it fails the writer's checks (its
    // regions would point past the state's), so no file is overwritten with it.
    sim::SimulationState state;
    try {
        if (m_simulation)
            state = m_simulation->snapshot();
    } catch (...) {
        into->fill(std::make_shared<const sim::SimulationState>());
        throw;
    }
    m_journalHead = std::make_shared<const model::JournalSegment>(model::JournalSegment{std::move(m_entries), m_journalHead});
    m_entries.clear();
    into->fill(std::make_shared<const sim::SimulationState>(std::move(state)), {m_journalHead, m_journalStep});
}

void SimulationWorker::startJournal(const model::JournalMark& mark)
{
    m_entries.clear();
    m_journalHead = mark.head ? mark.head : std::make_shared<const model::JournalSegment>();
    m_journalStep = mark.head ? mark.step : 0;
}

void SimulationWorker::record(decltype(model::JournalEntry::action) action)
{
    m_entries.push_back({m_journalStep, std::move(action)});
}

void SimulationWorker::restore(const model::StateSlotPtr& from)
{
    const model::StatePtr state = from->wait();
    m_pen.clear();  // the pen and a gather acted on the state being replaced
    m_gather.reset();
    startJournal(from->waitForMark());
    if (!m_simulation) {  // its load failed: the state brings the work back
        build(m_settings, state.get());
        return;
    }
    try {
        m_simulation->restore(*state);
        m_copying.reset();  // restore() dropped the copy
    } catch (const std::exception&) {
        // The device cannot hold it, or has failed: a new simulation takes the state, on the
        // reference backend if need be (build()).
        build(m_settings, state.get());
    }
}

void SimulationWorker::addRegion(const std::vector<sim::Polygon>& contours)
{
    if (!m_simulation)
        return;
    m_simulation->addRegion(contours);
    record(model::journal::AddRegion{contours});
}

void SimulationWorker::removeRegion(int region)
{
    if (!m_simulation)
        return;
    m_simulation->restore(model::withoutRegion(m_simulation->snapshot(), region));
    m_copying.reset();  // restore() dropped the copy
    record(model::journal::RemoveRegion{region});
}

void SimulationWorker::drop(sim::Vec2 center, double radius)
{
    if (!m_simulation)
        return;
    record(model::journal::Drop{center, radius});
    if (m_simulation->drop(center, radius).vertexLimitReached)
        stopWith(tr("vertex limit reached (%1 vertices)").arg(m_simulation->vertexCount()));
}

void SimulationWorker::applyMap(const sim::ExactMap& map)
{
    if (!m_simulation)
        return;
    record(model::journal::Map{std::make_shared<const sim::ExactMap>(map)});
    if (!m_simulation->applyMap(map))
        stopWith(tr("vertex limit reached (%1 vertices)").arg(m_simulation->vertexCount()));
}

void SimulationWorker::gather(const std::shared_ptr<const sim::TargetDrive>& drive, double duration)
{
    if (m_simulation)
        m_gather = Gather{drive, m_simulation->time() + duration};
}

std::shared_ptr<const sim::TargetDrive> SimulationWorker::activeDrive()
{
    if (m_gather && m_simulation->time() < m_gather->until)
        return m_gather->drive;
    m_gather.reset();
    return nullptr;
}

void SimulationWorker::stylus(const std::vector<sim::StylusSegment>& pens)
{
    if (!m_simulation)
        return;
    const std::size_t first = m_pen.size();
    for (const sim::StylusSegment& pen : pens) {
        const int parts = std::max(1, int(std::lround(pen.duration / m_scene.time.dt)));
        if (m_pen.size() < first + std::size_t(parts))
            m_pen.resize(first + std::size_t(parts));
        for (int k = 0; k < parts; ++k)
            m_pen[first + std::size_t(k)].push_back(pen.part(k, parts));
    }
}

void SimulationWorker::setPlaying(bool playing)
{
    if (playing == m_playing || (playing && !m_simulation))
        return;
    const bool wasRunning = running();
    m_playing = playing;
    emit playingChanged(m_playing);
    onRunningChanged(wasRunning);
}

void SimulationWorker::setStroking(bool stroking)
{
    if (stroking == m_stroking || (stroking && !m_simulation))
        return;
    const bool wasRunning = running();
    m_stroking = stroking;
    onRunningChanged(wasRunning);
}

// After playing or stroking changed: a start counts real time and the steps per second from now;
// a stop stops the step timer.
void SimulationWorker::onRunningChanged(bool wasRunning)
{
    if (!wasRunning) {
        m_nextStepAt = m_clock.elapsed();
        m_stepsInWindow = 0;
        m_windowStart = m_clock.elapsed();
        m_stepsPerSecond = 0.0;
    }
    scheduleStep();
}

void SimulationWorker::stepOnce()
{
    if (!running())
        step();
}

void SimulationWorker::scheduleStep()
{
    if (!running())
        m_stepTimer.stop();
    else if (!m_stepTimer.isActive())
        m_stepTimer.start(int(std::max<qint64>(0, m_nextStepAt - m_clock.elapsed())));
}

void SimulationWorker::step()
{
    if (!m_simulation)
        return;
    const double dt = m_scene.time.dt;
    const double t = m_simulation->time();
    try {
        // One part of each pen a step: each covers about one step's time.
        std::vector<sim::StylusSegment> pens;
        if (!m_pen.empty()) {
            pens = std::move(m_pen.front());
            m_pen.pop_front();
        }
        const std::shared_ptr<const sim::TargetDrive> drive = activeDrive();
        if (drive)
            record(model::journal::Drive{drive});
        for (const sim::StylusSegment& part : pens)
            record(model::journal::Pen{part});
        const bool limit = m_script->step(*m_simulation, t, dt, {drive.get(), pens}).vertexLimitReached;
        ++m_steps;
        ++m_journalStep;
        if (limit)
            stopWith(tr("vertex limit reached (%1 vertices); paused").arg(m_simulation->vertexCount()));
    } catch (const std::exception& e) {
        stopWith(firstLine(e.what()));
    }
    // Real time: one dt of simulated time per dt of wall time, or slower when steps take longer.
    const qint64 now = m_clock.elapsed();
    m_nextStepAt = std::max(now, m_nextStepAt + qint64(std::lround(dt * 1000.0)));
    ++m_stepsInWindow;
    if (now - m_windowStart >= 1000) {
        m_stepsPerSecond = 1000.0 * m_stepsInWindow / double(now - m_windowStart);
        m_stepsInWindow = 0;
        m_windowStart = now;
    }
    {
        std::lock_guard lock(m_frameMutex);
        m_dirty = true;
    }
    offerFrame();
    scheduleStep();
}

void SimulationWorker::fail(const std::exception& error)
{
    stopWith(firstLine(error.what()));
}

void SimulationWorker::stopWith(const QString& message)
{
    m_stroking = false;
    m_pen.clear();
    m_gather.reset();
    if (m_playing) {
        m_playing = false;
        emit playingChanged(false);
    }
    m_stepTimer.stop();
    emit failed(message);
}

void SimulationWorker::requestDone()
{
    ++m_handled;
    {
        std::lock_guard lock(m_frameMutex);
        m_dirty = true;
    }
    offerFrame();
}

// A frame is made in two halves. The first takes everything but the geometry as it is now and
// asks the simulation for a copy of the geometry (Simulation::requestRegions); the second, once
// the copy is complete, adds it and hands the frame out. While running (playing, or during a
// stroke), the next step is enqueued in between, so this thread does not wait for the copy (on
// OpenCL the device makes it before the step's kernels); stopped, nothing would come in between,
// so the second half waits for it at once.
void SimulationWorker::offerFrame()
{
    {
        std::lock_guard lock(m_frameMutex);
        if (m_frameOut || (!m_copying && !m_dirty))
            return;
    }
    try {
        if (!m_copying)
            startFrame();
        if (m_simulation) {
            std::optional<sim::RegionsCopy> copy = m_simulation->takeRegions(!running());
            if (!copy && !running()) {  // the copy was dropped (a restore that failed): take the present
                startFrame();
                copy = m_simulation->takeRegions(true);
            }
            if (!copy)
                return;  // still copying: the next step offers again
            if (copy->request != m_copyRequest) {  // not the copy this frame asked for: start over
                m_copying.reset();
                return;
            }
            m_copying->regions = std::move(copy->regions);
        }
    } catch (const std::exception& e) {  // a device that failed cannot be read back either
        m_copying.reset();
        stopWith(firstLine(e.what()));
        return;
    }
    {
        std::lock_guard lock(m_frameMutex);
        m_frame = std::move(m_copying);
        m_frameOut = true;
    }
    emit frameReady();
}

void SimulationWorker::startFrame()
{
    auto frame = std::make_shared<model::Frame>();
    frame->serial = m_handled;
    frame->steps = m_steps;
    frame->width = m_scene.canvas.width;
    frame->height = m_scene.canvas.height;
    frame->stepsPerSecond = m_playing ? m_stepsPerSecond : 0.0;
    frame->backend = m_backendLabel.toStdString();
    frame->playing = m_playing;
    {
        std::lock_guard lock(m_frameMutex);
        m_dirty = false;
    }
    if (m_simulation) {
        frame->time = m_simulation->time();
        frame->vertexCount = m_simulation->vertexCount();
        if (m_velocityWanted)
            frame->velocity = m_simulation->velocity();
        m_copyRequest = m_simulation->requestRegions();
    }
    m_copying = std::move(frame);
}

std::shared_ptr<const model::Frame> SimulationWorker::takeFrame()
{
    std::shared_ptr<const model::Frame> frame;
    bool again = false;
    {
        std::lock_guard lock(m_frameMutex);
        frame = std::move(m_frame);
        m_frame.reset();
        m_frameOut = false;
        again = m_dirty;
    }
    if (again)  // changed while the GUI held on to the last one: make the next now
        QMetaObject::invokeMethod(this, &SimulationWorker::offerFrame, Qt::QueuedConnection);
    return frame;
}

} // namespace vf::app
