#pragma once
// The fluid solvers every behavioural fluid test runs on, as QTest data rows (as Backends.h does
// for whole simulations): the reference FluidSolver (double) and the OpenCL DeviceFluid (float32),
// behind one small interface, so that one test body checks both. A solver that cannot run here
// (no OpenCL device) makes its rows skip, saying why (VF_REQUIRE_BACKEND).
#include "Backends.h"

#include "sim/FluidSolver.h"
#include "sim/opencl/DeviceFluid.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace vf::test {

constexpr double kDt = 0.002;  // the scene default time step

inline sim::FluidSettings fluidSettings(int nx, int ny, double width, double height, double viscosity,
                                        sim::Advection advection = sim::Advection::MacCormack)
{
    sim::FluidSettings s;
    s.nx = nx;
    s.ny = ny;
    s.width = width;
    s.height = height;
    s.viscosity = viscosity;
    s.advection = advection;
    return s;
}

class FluidUnderTest {
public:
    virtual ~FluidUnderTest() = default;
    virtual const sim::FluidSettings& settings() const = 0;
    virtual void addStylus(sim::Vec2 from, sim::Vec2 to, double radius, double duration) = 0;
    virtual void step(double dt) = 0;
    virtual sim::MacVelocity velocity() const = 0;
    virtual void setVelocity(const sim::MacVelocity& velocity) = 0;
    virtual double maxDivergence() const = 0;
    // The most max |div u| may be after a projection of `m`.
    virtual double divergenceBound(const sim::MacVelocity& m) const = 0;

    // Diagnostics in double, whatever the solver keeps.
    double maxSpeed() const { return probe().maxSpeed(); }
    double kineticEnergy() const { return probe().kineticEnergy(); }

private:
    sim::FluidSolver probe() const
    {
        sim::FluidSolver reference(settings());
        reference.setVelocity(velocity());
        return reference;
    }
};

class ReferenceFluid final : public FluidUnderTest {
public:
    explicit ReferenceFluid(const sim::FluidSettings& s) : m_fluid(s) {}
    const sim::FluidSettings& settings() const override { return m_fluid.settings(); }
    void addStylus(sim::Vec2 from, sim::Vec2 to, double radius, double duration) override
    {
        m_fluid.addStylus(from, to, radius, duration);
    }
    void step(double dt) override { m_fluid.step(dt); }
    sim::MacVelocity velocity() const override { return m_fluid.velocity(); }
    void setVelocity(const sim::MacVelocity& velocity) override { m_fluid.setVelocity(velocity); }
    double maxDivergence() const override { return m_fluid.maxDivergence(); }
    double divergenceBound(const sim::MacVelocity&) const override { return settings().pressureTolerance; }

private:
    sim::FluidSolver m_fluid;
};

// The largest sum of the magnitudes of the terms of a cell's divergence: the scale S that bounds
// float32 rounding of a projected field (DeviceFluid.cpp).
inline double divergenceScale(const sim::MacVelocity& m)
{
    double s = 0.0;
    for (int j = 0; j < m.ny; ++j)
        for (int i = 0; i < m.nx; ++i) {
            const double* u = m.u.data() + std::size_t(j) * (m.nx + 1) + i;
            const double* v = m.v.data() + std::size_t(j) * m.nx + i;
            s = std::max(s, (std::abs(u[0]) + std::abs(u[1])) / m.hx + (std::abs(v[0]) + std::abs(v[m.nx])) / m.hy);
        }
    return s;
}

class OpenClFluid final : public FluidUnderTest {
public:
    explicit OpenClFluid(const sim::FluidSettings& s) : m_device(sim::opencl::Device::open()), m_fluid(m_device, s) {}
    const sim::FluidSettings& settings() const override { return m_fluid.settings(); }
    void addStylus(sim::Vec2 from, sim::Vec2 to, double radius, double duration) override
    {
        m_fluid.addStylus(from, to, radius, duration);
    }
    void step(double dt) override { m_fluid.step(dt); }
    sim::MacVelocity velocity() const override { return m_fluid.readVelocity(); }
    void setVelocity(const sim::MacVelocity& velocity) override { m_fluid.writeVelocity(velocity); }
    double maxDivergence() const override { return m_fluid.maxDivergence(); }
    // The solver stops at 1e-6 S; float32 rounding of the stored field and pressure leaves up to
    // 2.2e-6 S at 256^2 (4.5e-6 S at 512^2).
    double divergenceBound(const sim::MacVelocity& m) const override
    {
        return std::max(settings().pressureTolerance, 1e-5 * divergenceScale(m));
    }

private:
    sim::opencl::Device m_device;
    sim::opencl::DeviceFluid m_fluid;
};

// The solver of backend `name` ("reference" or "opencl"); call VF_REQUIRE_BACKEND(name) first.
inline std::unique_ptr<FluidUnderTest> makeFluid(const QString& name, const sim::FluidSettings& s)
{
    if (name == QLatin1String("opencl"))
        return std::make_unique<OpenClFluid>(s);
    return std::make_unique<ReferenceFluid>(s);
}

// A pen circling the centre of the canvas, one segment per call.
template <class Fluid>
void stir(Fluid& fluid, int segment)
{
    const sim::FluidSettings& s = fluid.settings();
    const sim::Vec2 center{0.5 * s.width, 0.5 * s.height};
    const double radius = 0.3 * std::min(s.width, s.height);
    const auto at = [&](int k) {
        const double a = 0.4 * k;
        return center + radius * sim::Vec2{std::cos(a), std::sin(a)};
    };
    fluid.addStylus(at(segment), at(segment + 1), 0.05 * std::min(s.width, s.height), 5 * kDt);
}

// Stirred for the first 15 steps, then left to flow.
template <class Fluid>
void stirAndRun(Fluid& fluid, int first, int count)
{
    for (int k = first; k < first + count; ++k) {
        if (k < 15)
            stir(fluid, k);
        fluid.step(kDt);
    }
}

inline bool isZero(const std::vector<double>& values)
{
    return std::all_of(values.begin(), values.end(), [](double x) { return x == 0.0; });
}

} // namespace vf::test
