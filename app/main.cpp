// vectorfluid: the command-line entry. `render` and `devices` run headless (no display needed).
#include "app/Commands.h"

#include <QCoreApplication>
#include <QTextStream>

namespace {

const char* usage =
    "usage: vectorfluid render SCENE [--steps N] [--dt S] [--backend reference|opencl] [--out FILE]...\n"
    "                          [--polyline] [--dpi N] [--frames DIR --every K] [--stats FILE.json]\n"
    "       vectorfluid devices\n";

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("vectorfluid"));
    QStringList arguments = QCoreApplication::arguments().mid(1);
    const QString command = arguments.isEmpty() ? QString() : arguments.takeFirst();
    if (command == QLatin1String("render"))
        return vf::app::renderCommand(arguments);
    if (command == QLatin1String("devices"))
        return vf::app::devicesCommand(arguments);
    QTextStream(command == QLatin1String("--help") ? stdout : stderr) << usage;
    return command == QLatin1String("--help") ? vf::app::Done : vf::app::BadInput;
}
