#include "app/Backend.h"

#include "sim/opencl/OpenClSimulation.h"

namespace vf::app {

std::unique_ptr<sim::Simulation> makeBackend(const sim::SimulationSettings& settings, const QString& backend,
                                             std::optional<int> device, QString& notice)
{
    if (backend != QLatin1String("reference")) {
        try {
            return sim::opencl::makeSimulation(settings, "opencl", device);
        } catch (const sim::opencl::DeviceError& e) {
            const QString what = QString::fromUtf8(e.what());
            notice = QStringLiteral("OpenCL backend unavailable (%1); using the reference backend").arg(what.section('\n', 0, 0));
            if (what.contains('\n'))
                notice += '\n' + what.section('\n', 1);
        }
    }
    return sim::makeReferenceSimulation(settings);
}

QString backendLabel(const sim::Simulation& simulation)
{
    return QString::fromStdString(simulation.description());
}

QString vertexLimitLabel(const sim::Simulation& simulation)
{
    const std::size_t maxVertices = simulation.settings().tracking.maxVertices;
    if (const std::size_t device = simulation.hardwareVertexLimit(); device < maxVertices)
        return QStringLiteral("the OpenCL device's vertex limit (%1)").arg(device);
    return QStringLiteral("max_vertices (%1)").arg(maxVertices);
}

} // namespace vf::app
