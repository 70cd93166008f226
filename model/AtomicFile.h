#pragma once
// Every file the program writes goes through here: a temporary beside the target, renamed over it
// only when complete, so a failure at any point leaves the previous file as it was.
#include <QIODevice>
#include <QString>

#include <functional>

namespace vf::model {

// Calls `write` with the open temporary; it returns an empty string or what went wrong. The
// device is unbuffered: Qt 6.4's QSaveFile::commit() does not report a failure of its final
// flush (disk full, file size limit), and the truncated file would replace the old one, so every
// write must reach the disk while its result can still be checked.
// Returns an empty string, or one line "path: what went wrong".
QString saveAtomically(const QString& path, const std::function<QString(QIODevice&)>& write);

// Writes all of `bytes`, or says why not.
QString writeAll(QIODevice& device, const QByteArray& bytes);

} // namespace vf::model
