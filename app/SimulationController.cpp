#include "app/SimulationController.h"

#include <QCoreApplication>

#include <future>
#include <stdexcept>

namespace vf::app {

SimulationController::SimulationController(QObject* parent)
    : QObject(parent)
    , m_worker(new SimulationWorker)
{
    m_thread.setObjectName(QStringLiteral("simulation"));
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &SimulationWorker::frameReady, this, &SimulationController::receiveFrame, Qt::QueuedConnection);
    connect(m_worker, &SimulationWorker::failed, this, &SimulationController::failed, Qt::QueuedConnection);
    connect(m_worker, &SimulationWorker::notice, this, &SimulationController::notice, Qt::QueuedConnection);
    connect(m_worker, &SimulationWorker::playingChanged, this, [this](bool playing) {
        m_playing = playing;
        emit playingChanged(playing);
    }, Qt::QueuedConnection);
    m_thread.start();
}

SimulationController::~SimulationController()
{
    m_thread.quit();
    m_thread.wait();
}

void SimulationController::post(std::function<void(SimulationWorker&)> request)
{
    ++m_requests;
    QMetaObject::invokeMethod(m_worker, [worker = m_worker, request = std::move(request)] {
        try {
            request(*worker);
        } catch (const std::exception& e) {  // e.g. the OpenCL device failed: never past the event loop
            worker->fail(e);
        } catch (...) {
            worker->fail(std::runtime_error("unexpected failure in the simulation"));
        }
        worker->requestDone();
    }, Qt::QueuedConnection);
}

void SimulationController::load(const model::Scene& scene, const model::EngineSettings& settings, const model::StateSlotPtr& start)
{
    post([scene, settings, start](SimulationWorker& w) { w.load(scene, settings, start); });
}

void SimulationController::configure(const model::EngineSettings& settings)
{
    post([settings](SimulationWorker& w) { w.configure(settings); });
}

void SimulationController::snapshot(const model::StateSlotPtr& into)
{
    post([into](SimulationWorker& w) { w.snapshot(into); });
}

void SimulationController::restore(const model::StateSlotPtr& from)
{
    post([from](SimulationWorker& w) { w.restore(from); });
}

void SimulationController::addRegion(const std::vector<sim::Polygon>& contours)
{
    post([contours](SimulationWorker& w) { w.addRegion(contours); });
}

void SimulationController::removeRegion(int region)
{
    post([region](SimulationWorker& w) { w.removeRegion(region); });
}

void SimulationController::drop(sim::Vec2 center, double radius)
{
    post([center, radius](SimulationWorker& w) { w.drop(center, radius); });
}

void SimulationController::applyMap(const sim::ExactMap& map)
{
    post([map](SimulationWorker& w) { w.applyMap(map); });
}

void SimulationController::stylus(const std::vector<sim::StylusSegment>& pens)
{
    post([pens](SimulationWorker& w) { w.stylus(pens); });
}

void SimulationController::gather(const std::shared_ptr<const sim::TargetDrive>& drive, double duration)
{
    post([drive, duration](SimulationWorker& w) { w.gather(drive, duration); });
}

void SimulationController::setPlaying(bool playing)
{
    m_playing = playing;
    post([playing](SimulationWorker& w) { w.setPlaying(playing); });
}

void SimulationController::setStroking(bool stroking)
{
    post([stroking](SimulationWorker& w) { w.setStroking(stroking); });
}

void SimulationController::stepOnce()
{
    post([](SimulationWorker& w) { w.stepOnce(); });
}

void SimulationController::setVelocityWanted(bool wanted)
{
    post([wanted](SimulationWorker& w) { w.setVelocityWanted(wanted); });
}

void SimulationController::receiveFrame()
{
    if (auto frame = m_worker->takeFrame()) {
        m_frame = std::move(frame);
        emit frameArrived();
    }
}

void SimulationController::sync()
{
    // A request of its own: once it has run, every earlier one has too.
    std::promise<void> done;
    post([&done](SimulationWorker&) { done.set_value(); });
    done.get_future().wait();
    // Its frame follows through the event queue; take it directly rather than spin the loop.
    receiveFrame();
    while (!m_frame || m_frame->serial < m_requests) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        receiveFrame();
    }
}

} // namespace vf::app
