// vectorfluid: with no command (or a file), the desktop app; `render` and `devices` run headless
// (no display needed, no QApplication).
#include "app/Commands.h"

#include <QCoreApplication>
#include <QTextStream>

#include <cstring>

namespace {

const char* usage =
    "usage: vectorfluid [FILE.vfproj | FILE.vfscene]   open the app\n"
    "       vectorfluid render SCENE [--steps N] [--dt S] [--backend reference|opencl] [--device N]\n"
    "                          [--out FILE]... [--polyline] [--dpi N] [--frames DIR --every K]\n"
    "                          [--stats FILE.json]\n"
    "       vectorfluid devices\n";

bool isHeadless(const char* command)
{
    for (const char* c : {"render", "devices", "--help", "-h"})
        if (std::strcmp(command, c) == 0)
            return true;
    return false;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || !isHeadless(argv[1]))
        return vf::app::guiMain(argc, argv);

    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("vectorfluid"));
    QStringList arguments = QCoreApplication::arguments().mid(1);
    const QString command = arguments.takeFirst();
    if (command == QLatin1String("render"))
        return vf::app::renderCommand(arguments);
    if (command == QLatin1String("devices"))
        return vf::app::devicesCommand(arguments);
    QTextStream(stdout) << usage;
    return vf::app::Done;
}
