#pragma once
// The backends every accuracy test runs on: each test adds these as QTest data rows, so one test
// body checks all of them (not copies per backend).
#include "sim/Simulation.h"

#include <QString>
#include <QTest>

#include <memory>

namespace vf::test {

inline void addBackendColumn()
{
    QTest::addColumn<QString>("backend");
}

inline QStringList backendNames()
{
    return {QStringLiteral("reference")};
}

// The column and one row per backend, for tests that vary nothing else.
inline void addBackendRows()
{
    addBackendColumn();
    for (const QString& b : backendNames())
        QTest::newRow(qPrintable(b)) << b;
}

inline std::unique_ptr<sim::Simulation> makeBackend(const QString& name, const sim::SimulationSettings& settings)
{
    Q_UNUSED(name);
    return sim::makeReferenceSimulation(settings);
}

} // namespace vf::test
