#include "app/Folders.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace vf::app {

QString documentsFolder()
{
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return !documents.isEmpty() && QFileInfo(documents).isDir() ? documents : QDir::homePath();
}

} // namespace vf::app
