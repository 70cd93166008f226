// `vectorfluid devices`: list the OpenCL platforms and devices this machine offers.
#include "app/CommandLine.h"
#include "app/Commands.h"
#include "sim/opencl/DeviceList.h"

#include <QTextStream>

namespace vf::app {

int devicesCommand(const QStringList& arguments)
{
    CommandLine commandLine(QStringLiteral("vectorfluid devices"),
                            QStringLiteral("usage: vectorfluid devices\nLists the OpenCL platforms and devices, "
                                           "numbered as render --device takes them.\n"));
    const QString refusal = QStringLiteral("devices takes no arguments (see vectorfluid devices --help)");
    commandLine.setRefusal(refusal);
    if (const std::optional<int> exitCode = commandLine.parse(arguments))
        return *exitCode;
    if (!commandLine.parser().positionalArguments().isEmpty()) {
        printError(refusal);
        return BadInput;
    }
    QTextStream out(stdout);
    const sim::opencl::DeviceListing listing = sim::opencl::listDevices();
    if (!listing.error.empty()) {
        out << "no OpenCL devices: " << QString::fromStdString(listing.error) << '\n';
        return Done;
    }
    for (const sim::opencl::DeviceInfo& d : listing.devices)
        out << d.index << ": " << QString::fromStdString(d.name) << " [" << QString::fromStdString(d.type) << "] on "
            << QString::fromStdString(d.platform) << ", " << d.computeUnits << " compute units, "
            << (d.globalMemory >> 20) << " MiB, " << QString::fromStdString(d.version) << '\n';
    return Done;
}

} // namespace vf::app
