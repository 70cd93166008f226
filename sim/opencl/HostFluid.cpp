#include "sim/opencl/HostFluid.h"

#include <string>

namespace vf::sim::opencl {

namespace {

template <class F>
void onDevice(const Device& device, F&& f)
{
    try {
        f();
    } catch (const cl::Error& e) {
        throw DeviceError("the OpenCL device " + device.name() + " could not take the fluid's stream functions: "
                          + e.what() + " (error " + std::to_string(e.err()) + ")");
    }
}

} // namespace

HostFluid::HostFluid(Device& device, const FluidSettings& settings)
    : m_device(device)
    , m_flow(settings)
{
    const StreamField& end = *m_flow.streams().back();
    m_staging.resize(3 * end.psi.size());
    onDevice(m_device, [&] {
        m_stream = cl::Buffer(m_device.context(), CL_MEM_READ_ONLY, m_staging.size() * sizeof(float));
    });
    upload();
}

void HostFluid::addStylus(Vec2 from, Vec2 to, double radius, double duration)
{
    m_flow.solver().addStylus(from, to, radius, duration);
}

void HostFluid::step(double dt)
{
    m_flow.advance(dt);
    upload();
}

FlowBinding HostFluid::binding(double t0, double t1) const
{
    const FluidSolver& solver = m_flow.solver();
    FlowBinding b;
    b.field = m_stream;
    b.nx = solver.settings().nx;
    b.ny = solver.settings().ny;
    b.hx = float(solver.velocity().hx);
    b.hy = float(solver.velocity().hy);
    b.t0 = t0;
    b.t1 = t1;
    return b;
}

void HostFluid::writeVelocity(const MacVelocity& velocity)
{
    const FluidState state{velocity, std::vector<double>(m_flow.solver().pressure().size(), 0.0)};
    m_flow.setState(&state);
    upload();
}

void HostFluid::writePressure(const std::vector<double>& pressure)
{
    m_flow.solver().setPressure(pressure);
}

// Blocking: the contour kernels of the last substep have finished by now (each refinement pass
// reads its total back), so the write waits for nothing, and the staging can be reused at once.
void HostFluid::upload()
{
    auto out = m_staging.begin();
    for (const StreamField* field : m_flow.streams())
        for (const double psi : field->psi)
            *out++ = float(psi);
    onDevice(m_device, [&] {
        m_device.queue().enqueueWriteBuffer(m_stream, CL_TRUE, 0, m_staging.size() * sizeof(float),
                                            m_staging.data());
    });
}

} // namespace vf::sim::opencl
