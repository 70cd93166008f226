#pragma once
// File ▸ Open Recent: the last files opened or saved, kept in the app's settings, most recent
// first, shown in a menu whose entries open them.
#include <QObject>
#include <QString>

#include <functional>

class QMenu;

namespace vf::app {

class RecentFiles final : public QObject {
    Q_OBJECT

public:
    // `open` is called with the path of the entry chosen in `menu`.
    RecentFiles(QMenu* menu, std::function<void(const QString& path)> open, QObject* parent = nullptr);

    // Puts `path` first (once), keeping the newest few.
    void add(const QString& path);
    // The folder of the most recent file, or an empty string.
    QString folder() const;

private:
    void updateMenu();

    QMenu* m_menu;
    std::function<void(const QString&)> m_open;
};

} // namespace vf::app
