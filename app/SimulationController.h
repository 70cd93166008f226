#pragma once
// The GUI thread's handle on the simulation worker: starts its thread, queues requests to it
// (model::SimulationPort), and receives its frames. Nothing here touches simulation memory.
#include "app/SimulationWorker.h"
#include "model/SimulationPort.h"

#include <QObject>
#include <QThread>

#include <functional>

namespace vf::app {

class SimulationController final : public QObject, public model::SimulationPort {
    Q_OBJECT

public:
    explicit SimulationController(QObject* parent = nullptr);
    ~SimulationController() override;

    void load(const model::Scene& scene, const model::EngineSettings& settings, const model::StateSlotPtr& start) override;
    void configure(const model::EngineSettings& settings) override;
    void snapshot(const model::StateSlotPtr& into) override;
    void restore(const model::StateSlotPtr& from) override;
    void addRegion(const std::vector<sim::Polygon>& contours) override;
    void removeRegion(int region) override;
    void drop(sim::Vec2 center, double radius) override;
    void applyMap(const sim::ExactMap& map) override;
    void stylus(const std::vector<sim::StylusSegment>& pens) override;
    void gather(const std::shared_ptr<const sim::TargetDrive>& drive, double duration) override;
    std::uint64_t requestCount() const override { return m_requests; }

    void setPlaying(bool playing);
    bool isPlaying() const { return m_playing; }
    void setStroking(bool stroking);  // SimulationWorker::setStroking
    void stepOnce();
    void setVelocityWanted(bool wanted);

    // The newest frame received (null before the first).
    std::shared_ptr<const model::Frame> frame() const { return m_frame; }
    // Blocks until the worker has done every request made so far and a frame showing them has
    // arrived. For tests and benchmarks; the app itself never waits on the worker like this.
    void sync();

signals:
    void frameArrived();
    void failed(const QString& message);
    void notice(const QString& message);
    void playingChanged(bool playing);

private:
    void post(std::function<void(SimulationWorker&)> request);
    void receiveFrame();

    QThread m_thread;
    SimulationWorker* m_worker;  // lives on m_thread, deleted when it finishes
    std::uint64_t m_requests = 0;
    std::shared_ptr<const model::Frame> m_frame;
    bool m_playing = false;
};

} // namespace vf::app
