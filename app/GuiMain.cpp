// The desktop app's start: one window, opened on the file given (or a blank tray), offering to
// recover what a crashed session left.
#include "app/Commands.h"
#include "app/MainWindow.h"
#include "app/Recovery.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTextStream>
#include <QTimer>

namespace vf::app {

int guiMain(int argc, char** argv)
{
    QElapsedTimer sinceLaunch;
    sinceLaunch.start();
    // Checked before QApplication exists, which would talk to the display (and warn) first.
    if (argc > 2) {
        QTextStream(stderr) << "vectorfluid: expected at most one file to open (see vectorfluid --help)\n";
        return BadInput;
    }
    if (argc == 2 && !QFileInfo(QString::fromLocal8Bit(argv[1])).isFile()) {
        QTextStream(stderr) << QStringLiteral("vectorfluid: no such file or command '%1' (see vectorfluid --help)\n")
                                   .arg(QString::fromLocal8Bit(argv[1]));
        return BadInput;
    }
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("vectorfluid"));
    QApplication::setOrganizationName(QStringLiteral("vectorfluid"));
    QApplication::setApplicationDisplayName(QStringLiteral("Vector Fluid"));
    // The installed launcher (resources/desktop): Wayland compositors show its name and icon.
    QApplication::setDesktopFileName(QStringLiteral("org.vectorfluid.VectorFluid"));
    const QStringList arguments = QApplication::arguments().mid(1);

    MainWindow window;
    window.show();
    if (!arguments.isEmpty())
        window.openFile(arguments.front());  // a broken file is reported; the window stays, blank
    if (window.recovery().hasCrashedSession()
        && QMessageBox::question(&window, QObject::tr("Recover"),
                                 QObject::tr("Vector Fluid did not exit cleanly last time. Recover the unsaved work?"))
            == QMessageBox::Yes)
        window.recover();

    // The launch benchmark (docs/BENCHMARKS.md, "The app"): time until the first frame of the simulation is
    // on screen, then quit.
    if (qEnvironmentVariableIsSet("VF_EXIT_WHEN_READY")) {
        QObject::connect(&window.simulation(), &SimulationController::frameArrived, &app, [&] {
            QTimer::singleShot(0, &app, [&] {
                QTextStream(stdout) << "interactive after " << sinceLaunch.elapsed() << " ms\n";
                app.quit();
            });
        });
    }
    // The README's screenshot (scripts/screenshot): the window after the scene has played a while.
    if (const QString shot = qEnvironmentVariable("VF_SCREENSHOT"); !shot.isEmpty()) {
        const int afterMs = qEnvironmentVariableIntValue("VF_SCREENSHOT_AFTER_MS");
        QTimer::singleShot(afterMs > 0 ? afterMs : 3000, &app, [&window, &app, shot] {
            const bool saved = window.grab().save(shot);
            QTextStream(saved ? stdout : stderr) << (saved ? "wrote " : "vectorfluid: cannot write ") << shot << '\n';
            window.document().undoStack().setClean();  // nothing to ask about on the way out
            app.exit(saved ? Done : BadInput);
        });
    }
    window.simulation().setPlaying(true);
    return app.exec();
}

} // namespace vf::app
