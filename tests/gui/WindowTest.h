#pragma once
// What every test of the main window sets up: settings of its own in Qt's test mode, cleared and
// on the reference backend (the same on every machine), and a recovery folder in its temporary
// one; and a window shown and active, since shortcuts reach the active window only.
#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QWidget>

#include <algorithm>

namespace vf::test {

inline void useTestSettings(const char* application, const QTemporaryDir& dir)
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("vectorfluid-tests"));
    QCoreApplication::setApplicationName(QLatin1String(application));
    QSettings().clear();
    QSettings().setValue(QStringLiteral("simulation/backend"), QStringLiteral("reference"));
    qputenv("VF_RECOVERY_DIR", dir.filePath(QStringLiteral("recovery")).toUtf8());
}

[[nodiscard]] inline bool showActive(QWidget& window)
{
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return false;
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

// Opens the menu bar's first menu (File) by mouse and clicks its item whose text starts with
// `text` (with its & mnemonic); a dialog it opens runs in its own event loop, so answer it with
// whenModal first.
inline void clickFileMenuItem(QMainWindow& window, const QString& text)
{
    QMenu* file = window.menuBar()->actions().front()->menu();
    QTest::mouseClick(window.menuBar(), Qt::LeftButton, {}, window.menuBar()->actionGeometry(file->menuAction()).center());
    const QList<QAction*> actions = file->actions();  // a copy: begin and end of one list
    QAction* item = *std::find_if(actions.begin(), actions.end(), [&text](QAction* a) { return a->text().startsWith(text); });
    QTest::mouseClick(file, Qt::LeftButton, {}, file->actionGeometry(item).center());
    QApplication::setActiveWindow(&window);  // the offscreen platform leaves the menu active
}

} // namespace vf::test
