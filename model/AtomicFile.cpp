#include "model/AtomicFile.h"

#include <QSaveFile>

namespace vf::model {

QString saveAtomically(const QString& path, const std::function<QString(QIODevice&)>& write)
{
    auto failure = [&path](const QString& what) { return path + QStringLiteral(": ") + what.simplified(); };
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return failure(QStringLiteral("cannot write: %1").arg(file.errorString()));
    if (const QString error = write(file); !error.isEmpty()) {
        file.cancelWriting();
        return failure(error);
    }
    if (!file.commit())
        return failure(QStringLiteral("cannot save: %1").arg(file.errorString()));
    return {};
}

QString writeAll(QIODevice& device, const QByteArray& bytes)
{
    const qint64 written = device.write(bytes);
    if (written == bytes.size())
        return {};
    return written < 0 ? device.errorString()
                       : QStringLiteral("wrote only %1 of %2 bytes").arg(written).arg(bytes.size());
}

} // namespace vf::model
