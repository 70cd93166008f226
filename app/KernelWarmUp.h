#pragma once
// A device's OpenCL kernels compiled before the app runs on it. PoCL compiles each kernel at its
// first launch (sim/opencl/WarmUp.h): run straight on the device, a first launch would freeze for
// some twenty seconds with nothing drawn. So where the kernels are not known to be compiled, the
// simulation worker runs the reference backend while this compiles them on a thread of its own; a
// stamp in the cache folder, named after what the kernels depend on, says so to later launches.
#include <QObject>
#include <QString>

#include <atomic>
#include <optional>
#include <thread>

namespace vf::app {

class KernelWarmUp final : public QObject {
    Q_OBJECT
public:
    explicit KernelWarmUp(QObject* parent = nullptr);
    // Asks a warm-up under way to stop (it does between the parts of its session) and waits.
    ~KernelWarmUp() override;

    // Whether the kernels for this device are compiled (its stamp exists). A device that cannot be
    // opened counts as ready: there is nothing to compile, and making the backend says why.
    static bool isReady(std::optional<int> device);
    // Compiles them on the calling thread and leaves the stamp; returns the error's first line, or
    // an empty string.
    static QString prepare(std::optional<int> device, const std::atomic<bool>& stop = std::atomic<bool>(false));

    // prepare() on a thread of its own, unless one is under way; finished() when it is done.
    void start(std::optional<int> device);
    bool isRunning() const { return m_thread.joinable() && !m_done; }

signals:
    void finished(const QString& error);  // from the warm-up's thread; empty on success

private:
    std::thread m_thread;
    std::atomic<bool> m_stop{false}, m_done{false};
};

} // namespace vf::app
