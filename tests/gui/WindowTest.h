#pragma once
// What every test of the main window sets up: settings of its own in Qt's test mode, cleared and
// on the reference backend (the same on every machine), and a recovery folder in its temporary
// one; and a window shown and active, since shortcuts reach the active window only.
#include <QCoreApplication>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QWidget>

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

} // namespace vf::test
