// `vectorfluid devices`: list the OpenCL platforms and devices this machine offers.
#include "app/Commands.h"
#include "sim/opencl/DeviceList.h"

#include <QTextStream>

namespace vf::app {

int devicesCommand(const QStringList& arguments)
{
    QTextStream out(stdout);
    if (!arguments.isEmpty()) {
        QTextStream(stderr) << "vectorfluid: devices takes no arguments\n";
        return BadInput;
    }
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
