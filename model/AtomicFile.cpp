#include "model/AtomicFile.h"

#include <QSaveFile>

#include <cerrno>
#include <unistd.h>

namespace vf::model {

namespace {

QString failure(const QString& path, const QString& what) { return path + QStringLiteral(": ") + what.simplified(); }

QString cannotWrite(const QSaveFile& file)
{
    return failure(file.fileName(), QStringLiteral("cannot write: %1").arg(file.errorString()));
}

// What a failed write says: "disk full" for a full file system (errno `error`), else the
// system's own words.
QString writeFailure(int error, const QString& words)
{
    if (error == ENOSPC)
        return QStringLiteral("write failed: disk full");
    return QStringLiteral("write failed: %1").arg(words);
}

// QSaveFile::commit() syncs too, but ignores a failure there; a disk that fills or fails only
// when the data is written back (thin-provisioned, network, EIO) would then lose the file after
// the rename. Syncing here reports it while the old file is still in place.
QString sync(QSaveFile& file)
{
    if (::fsync(file.handle()) == 0)
        return {};
    const int error = errno;
    return writeFailure(error, qt_error_string(error));
}

} // namespace

FileBatch::FileBatch() = default;
FileBatch::~FileBatch() = default;  // a QSaveFile not committed removes its temporary

QString FileBatch::write(const QString& path, const FileContent& content)
{
    auto file = std::make_unique<QSaveFile>(path);
    if (!file->open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return cannotWrite(*file);
    QString error = content(*file);
    if (error.isEmpty())
        error = sync(*file);
    if (!error.isEmpty()) {
        file->cancelWriting();
        return failure(path, error);
    }
    m_files.push_back(std::move(file));
    return {};
}

QString FileBatch::commit()
{
    for (const std::unique_ptr<QSaveFile>& file : m_files) {
        if (!file->commit())
            return failure(file->fileName(), QStringLiteral("cannot save: %1").arg(file->errorString()));
    }
    m_files.clear();
    return {};
}

QString saveAtomically(const QString& path, const FileContent& write)
{
    FileBatch batch;
    if (const QString error = batch.write(path, write); !error.isEmpty())
        return error;
    return batch.commit();
}

QString checkWritable(const QString& path)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return cannotWrite(file);
    file.cancelWriting();  // and the destructor removes the temporary
    return {};
}

QString writeAll(QIODevice& device, const QByteArray& bytes)
{
    return writeAll(device, bytes.constData(), bytes.size());
}

// A write that fills the disk part-way returns a short count with no error set; the next write of
// the rest fails at once, and only that one says why.
QString writeAll(QIODevice& device, const char* data, qint64 size)
{
    while (size > 0) {
        errno = 0;
        const qint64 written = device.write(data, size);
        if (written <= 0)
            return writeFailure(errno, device.errorString());
        data += written;
        size -= written;
    }
    return {};
}

} // namespace vf::model
