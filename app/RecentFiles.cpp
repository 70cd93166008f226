#include "app/RecentFiles.h"

#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace vf::app {

namespace {

constexpr int maxRecentFiles = 8;
const QString recentKey = QStringLiteral("files/recent");

QStringList recentPaths()
{
    return QSettings().value(recentKey).toStringList();
}

} // namespace

RecentFiles::RecentFiles(QMenu* menu, std::function<void(const QString&)> open, QObject* parent)
    : QObject(parent), m_menu(menu), m_open(std::move(open))
{
    updateMenu();
}

void RecentFiles::add(const QString& path)
{
    QStringList recent = recentPaths();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    QSettings().setValue(recentKey, recent.mid(0, maxRecentFiles));
    updateMenu();
}

QString RecentFiles::folder() const
{
    const QStringList recent = recentPaths();
    return recent.isEmpty() ? QString() : QFileInfo(recent.front()).absolutePath();
}

void RecentFiles::updateMenu()
{
    m_menu->clear();
    const QStringList recent = recentPaths();
    for (const QString& path : recent)
        m_menu->addAction(QFileInfo(path).fileName(), this, [this, path] { m_open(path); })->setToolTip(path);
    m_menu->setEnabled(!recent.isEmpty());
}

} // namespace vf::app
