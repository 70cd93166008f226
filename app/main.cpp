// vectorfluid: with no command (or a file), the desktop app; `render`, `animate` and `devices` run headless
// (no display needed, no QApplication), as do the program's own options (--help, --version).
// `render` and `animate` play scenes, whose text (a gather's target) is set with the font
// database, which needs a QGuiApplication: they get one on the offscreen platform.
#include "app/CommandLine.h"
#include "app/Commands.h"
#include "sim/HeapPolicy.h"

#include <QGuiApplication>
#include <QTextStream>

#include <cstring>
#include <memory>

namespace {

const char* usage =
    "usage: vectorfluid [FILE.vfproj | FILE.vfscene]   open the app\n"
    "       vectorfluid render SCENE [--steps N] [--dt S] [--backend reference|opencl] [--device N]\n"
    "                          [--out FILE]... [--polyline] [--dpi N] [--frames DIR --every K]\n"
    "                          [--stats FILE.json] [--check-topology K]\n"
    "       vectorfluid animate SCENE|PROJECT (--out FILE | --frames DIR [--frame-format F]) [--start S]\n"
    "                           [--end S] [--fps N] [--width N] [--transparent] [--polyline]\n"
    "                           [--backend reference|opencl] [--device N]\n"
    "       vectorfluid devices\n"
    "`vectorfluid render --help`, `vectorfluid animate --help` and `vectorfluid devices --help`\n"
    "describe the commands.\n";

// On the command line stderr carries one line per error and nothing else (README). Qt's own
// messages are about the program's insides (a font database, a platform plugin), so they are
// dropped; a fatal one is still printed, as the program aborts after it.
void dropQtMessages(QtMsgType type, const QMessageLogContext&, const QString& message)
{
    if (type == QtFatalMsg)
        QTextStream(stderr) << "vectorfluid: " << message << '\n';
}

bool isHeadless(const char* argument)
{
    return argument[0] == '-' || std::strcmp(argument, "render") == 0 || std::strcmp(argument, "animate") == 0
           || std::strcmp(argument, "devices") == 0;
}

// `vectorfluid --help`, `--version` and anything else that starts with a dash.
int programOptions(const QStringList& arguments)
{
    vf::app::CommandLine commandLine(QStringLiteral("vectorfluid"), QString::fromLatin1(usage));
    commandLine.parser().addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("A project or scene to open in the app."));
    if (const std::optional<int> exitCode = commandLine.parse(arguments))
        return *exitCode;
    // Parsed, yet neither --help nor --version: "--" before a file, which the app does not take.
    vf::app::printError(QStringLiteral("give a file to open without options (see vectorfluid --help)"));
    return vf::app::BadInput;
}

} // namespace

int main(int argc, char** argv)
{
    vf::sim::keepLargeBlocksMapped();
    if (argc < 2 || !isHeadless(argv[1]))
        return vf::app::guiMain(argc, argv);

    qInstallMessageHandler(dropQtMessages);
    const bool render = std::strcmp(argv[1], "render") == 0, animate = std::strcmp(argv[1], "animate") == 0;
    if (render || animate)
        qputenv("QT_QPA_PLATFORM", "offscreen");
    const std::unique_ptr<QCoreApplication> app = render || animate ? std::make_unique<QGuiApplication>(argc, argv)
                                                                     : std::make_unique<QCoreApplication>(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("vectorfluid"));
    QStringList arguments = QCoreApplication::arguments().mid(1);
    if (render)
        return vf::app::renderCommand(arguments.mid(1));
    if (animate)
        return vf::app::animateCommand(arguments.mid(1));
    if (arguments.front() == QLatin1String("devices"))
        return vf::app::devicesCommand(arguments.mid(1));
    return programOptions(arguments);
}
