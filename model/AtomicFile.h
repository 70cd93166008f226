#pragma once
// Every file the program writes goes through here: a temporary beside the target, renamed over it
// only when complete, so a failure at any point leaves the previous file as it was.
#include <QIODevice>
#include <QString>

#include <functional>
#include <memory>
#include <vector>

class QSaveFile;

namespace vf::model {

// Writes a file's content into the open temporary; returns an empty string or what went wrong.
using FileContent = std::function<QString(QIODevice&)>;

// Calls `write` with the open temporary. The device is unbuffered: Qt 6.4's QSaveFile::commit()
// does not report a failure of its final flush (disk full, file size limit), and the truncated
// file would replace the old one, so every write must reach the disk while its result can still
// be checked. Nor does it report a failed sync, so the temporary is synced (fsync) here: a disk
// that fills or fails only when the data is written back says so before anything is renamed.
// Returns an empty string, or one line "path: what went wrong".
[[nodiscard]] QString saveAtomically(const QString& path, const FileContent& write);

// Several files put in place together: each is written into its temporary by write(), and only
// commit() renames them, one after the other, over their targets. Temporaries not committed are
// removed when the batch goes, so a run that fails or is interrupted anywhere before commit()
// leaves every target as it was.
class FileBatch {
public:
    FileBatch();
    ~FileBatch();
    FileBatch(const FileBatch&) = delete;
    FileBatch& operator=(const FileBatch&) = delete;

    // Returns an empty string, or one line "path: what went wrong" (the batch is then unusable).
    [[nodiscard]] QString write(const QString& path, const FileContent& content);
    [[nodiscard]] QString commit();

private:
    std::vector<std::unique_ptr<QSaveFile>> m_files;
};

// Whether `path` could be written: creates and removes a temporary beside it. Returns an empty
// string, or one line "path: cannot write: why".
[[nodiscard]] QString checkWritable(const QString& path);

// Writes all of `bytes`, or says why not.
[[nodiscard]] QString writeAll(QIODevice& device, const QByteArray& bytes);
[[nodiscard]] QString writeAll(QIODevice& device, const char* data, qint64 size);

} // namespace vf::model
