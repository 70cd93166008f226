#pragma once
// The backends every accuracy test runs on: each test adds these as QTest data rows, so one test
// body checks all of them (not copies per backend). A backend that cannot run here (no OpenCL
// device) makes its rows skip, saying why.
#include "sim/Simulation.h"
#include "sim/opencl/OpenClSimulation.h"

#include <QString>
#include <QTest>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>

namespace vf::test {

inline void addBackendColumn()
{
    QTest::addColumn<QString>("backend");
}

inline QStringList backendNames()
{
    return {QStringLiteral("reference"), QStringLiteral("opencl")};
}

// The column and one row per backend, for tests that vary nothing else.
inline void addBackendRows()
{
    addBackendColumn();
    for (const QString& b : backendNames())
        QTest::newRow(qPrintable(b)) << b;
}

// Why `name` cannot run on this machine; empty when it can.
inline QString unavailable(const QString& name)
{
    if (name != QLatin1String("opencl"))
        return {};
    static const QString why = [] {
        try {
            sim::opencl::Device::open();
            return QString();
        } catch (const sim::opencl::DeviceError& e) {
            return QStringLiteral("no OpenCL device: ") + QString::fromUtf8(e.what()).section('\n', 0, 0);
        }
    }();
    return why;
}

// The smallest relative error the backend's positions can promise: double on the reference,
// float32 on OpenCL.
inline double positionEpsilon(const QString& name)
{
    return name == QLatin1String("opencl") ? 1e-5 : 1e-12;
}

// How far under half its spacing an edge may be: the device counts an edge short only below half
// its spacing less a few roundings of its coordinates (shortLength in contours_refine.cl), the
// reference exactly at half.
inline double shortEdgeSlack(const QString& name, sim::Vec2 p)
{
    return name == QLatin1String("opencl") ? 2.0 * FLT_EPSILON * std::max(std::abs(p.x), std::abs(p.y)) : 0.0;
}

inline std::unique_ptr<sim::Simulation> makeBackend(const QString& name, const sim::SimulationSettings& settings)
{
    return sim::opencl::makeSimulation(settings, name.toStdString());
}

} // namespace vf::test

// First line of every test that takes a backend row.
#define VF_REQUIRE_BACKEND(name)                                         \
    do {                                                                 \
        if (const QString why = vf::test::unavailable(name); !why.isEmpty()) \
            QSKIP(qPrintable(why));                                      \
    } while (false)
