#include "app/KernelWarmUp.h"

#include "sim/opencl/Device.h"
#include "sim/opencl/WarmUp.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

namespace vf::app {

namespace {

struct Stamp {
    QString path;         // empty where the device cannot be opened
    QByteArray identity;  // what it holds: sim::opencl::kernelIdentity
};

Stamp stampFor(std::optional<int> device)
{
    try {
        Stamp stamp{{}, QByteArray::fromStdString(sim::opencl::kernelIdentity(device))};
        stamp.path = QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/kernels/") +
                     QString::fromLatin1(QCryptographicHash::hash(stamp.identity, QCryptographicHash::Sha1).toHex());
        return stamp;
    } catch (const sim::opencl::DeviceError&) {
        return {};
    }
}

} // namespace

KernelWarmUp::KernelWarmUp(QObject* parent)
    : QObject(parent)
{
}

KernelWarmUp::~KernelWarmUp()
{
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
}

bool KernelWarmUp::isReady(std::optional<int> device)
{
    const QString path = stampFor(device).path;
    return path.isEmpty() || QFile::exists(path);
}

QString KernelWarmUp::prepare(std::optional<int> device, const std::atomic<bool>& stop)
{
    try {
        sim::opencl::warmUpKernels(device, stop);
    } catch (const std::exception& e) {
        return QString::fromUtf8(e.what()).section('\n', 0, 0);
    }
    if (stop)
        return QStringLiteral("stopped");
    // Without a stamp (a read-only cache folder) the next launch compiles again: slower, not wrong.
    if (const Stamp stamp = stampFor(device); !stamp.path.isEmpty() && QDir().mkpath(QFileInfo(stamp.path).path())) {
        QFile file(stamp.path);
        if (file.open(QIODevice::WriteOnly))
            file.write(stamp.identity);
    }
    return {};
}

void KernelWarmUp::start(std::optional<int> device)
{
    if (isRunning())
        return;
    if (m_thread.joinable())
        m_thread.join();  // a finished one
    m_done = false;
    m_thread = std::thread([this, device] {
        const QString error = prepare(device, m_stop);
        m_done = true;
        emit finished(error);
    });
}

} // namespace vf::app
