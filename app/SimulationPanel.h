#pragma once
// The content of the "Simulation" dock: the flow, tracking and backend settings of the document.
// It holds no document state of its own: the app shows the document's settings with setSettings
// and turns each settingsEdited into one undoable command.
#include "app/MemoryBudget.h"
#include "model/EngineSettings.h"
#include "sim/opencl/DeviceList.h"

#include <QWidget>

#include <functional>

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QRadioButton;
class QSpinBox;

namespace vf::app {

class SimulationPanel final : public QWidget {
    Q_OBJECT

public:
    // `devices`: the OpenCL listing (sim::opencl::listDevices(), taken once by the caller).
    // `availableMemory`: bytes free now (app/MemoryBudget.h), asked at each max vertices edit.
    explicit SimulationPanel(sim::opencl::DeviceListing devices, QWidget* parent = nullptr,
                             std::function<double()> availableMemory = app::availableMemory);

    void setSettings(const model::EngineSettings& settings);  // shows them; emits nothing
    model::EngineSettings settings() const { return m_settings; }

signals:
    // Once per committed user edit that changed the settings; carries all of them, and the object
    // name of the spin box that changed them (empty for the other controls, whose every change
    // is a step of its own: see model::Document::setSettings).
    void settingsEdited(const model::EngineSettings& settings, const QString& control);

private:
    QWidget* createFlowGroup();
    QWidget* createTrackingGroup();
    QWidget* createBackendGroup();
    void connectEdits();
    // `spinBox`: the spin box being changed, or null.
    void edit(const QObject* spinBox, const std::function<void(model::EngineSettings&)>& change);
    void editMaxVertices(int value);
    void showSettings();
    void showMode();
    void showDevices();

    model::EngineSettings m_settings;
    sim::opencl::DeviceListing m_devices;
    std::function<double()> m_availableMemory;
    bool m_showing = false;  // the widgets are being set from m_settings: their signals are no edits

    QFormLayout* m_flowForm = nullptr;
    QButtonGroup* m_mode = nullptr;
    QRadioButton* m_marbling = nullptr;
    QRadioButton* m_shapeDesign = nullptr;
    QDoubleSpinBox* m_viscosity = nullptr;
    QDoubleSpinBox* m_stylusRadius = nullptr;
    QDoubleSpinBox* m_stylusResponse = nullptr;
    QSpinBox* m_gridX = nullptr;
    QSpinBox* m_gridY = nullptr;
    QLineEdit* m_flowU = nullptr;
    QLineEdit* m_flowV = nullptr;
    QDoubleSpinBox* m_maxSpacing = nullptr;
    QCheckBox* m_adaptive = nullptr;
    QCheckBox* m_proximity = nullptr;
    QCheckBox* m_areaCorrection = nullptr;
    QSpinBox* m_maxVertices = nullptr;
    QLabel* m_memoryNote = nullptr;  // why the last max vertices typed was lowered; hidden otherwise
    QComboBox* m_backend = nullptr;
    QComboBox* m_device = nullptr;
};

} // namespace vf::app
