// vectorfluid: the command-line entry. `render` and `devices` run headless (no display needed).
#include "app/Commands.h"

#include <QCoreApplication>
#include <QTextStream>

namespace {

const char* usage =
    "usage: vectorfluid render SCENE [--steps N] [--dt S] [--backend reference|opencl] [--device N]\n"
    "                          [--out FILE]... [--polyline] [--dpi N] [--frames DIR --every K]\n"
    "                          [--stats FILE.json]\n"
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
    if (command == QLatin1String("--help") || command == QLatin1String("-h")) {
        QTextStream(stdout) << usage;
        return vf::app::Done;
    }
    QTextStream(stderr) << (command.isEmpty() ? QStringLiteral("vectorfluid: no command given (see vectorfluid --help)")
                                              : QStringLiteral("vectorfluid: unknown command '%1' (see vectorfluid --help)").arg(command))
                        << '\n';
    return vf::app::BadInput;
}
