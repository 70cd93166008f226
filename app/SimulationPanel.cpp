#include "app/SimulationPanel.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>

namespace vf::app {
namespace {

namespace limits = model::limits;
constexpr int kMinVertices = 3;       // a contour has at least 3; the scene reader's minimum
constexpr double kMaxViscosity = 10;  // far beyond shape design; above it a stroke moves nothing
constexpr int kDecimals = 6;          // enough for marbling's 5e-4 and fine spacings
constexpr double kMaxStylusResponse = 10;  // s; far slower than any stroke

const QString kReference = QStringLiteral("reference");
const QString kOpenCl = QStringLiteral("opencl");

// Spin boxes commit on Enter, focus loss or a step, never per keystroke, and clamp what is typed
// to their range instead of throwing it away.
template <typename SpinBox>
SpinBox* committingSpinBox(const char* name)
{
    auto* box = new SpinBox;
    box->setObjectName(QLatin1String(name));
    box->setKeyboardTracking(false);
    box->setCorrectionMode(QAbstractSpinBox::CorrectToNearestValue);
    return box;
}

// Steps of about a tenth of the value at any magnitude, for quantities spanning decades.
QDoubleSpinBox* decadeSpinBox(const char* name, double minimum, double maximum)
{
    auto* box = committingSpinBox<QDoubleSpinBox>(name);
    box->setDecimals(kDecimals);
    box->setRange(minimum, maximum);
    box->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    return box;
}

QCheckBox* checkBox(const QString& text, const char* name)
{
    auto* box = new QCheckBox(text);
    box->setObjectName(QLatin1String(name));
    return box;
}

QLineEdit* readOnlyLine(const char* name)
{
    auto* line = new QLineEdit;
    line->setObjectName(QLatin1String(name));
    line->setReadOnly(true);
    return line;
}

QString deviceText(const sim::opencl::DeviceInfo& device)
{
    return QStringLiteral("%1: %2 [%3]")
        .arg(device.index)
        .arg(QString::fromStdString(device.name), QString::fromStdString(device.type));
}

} // namespace

SimulationPanel::SimulationPanel(sim::opencl::DeviceListing devices, QWidget* parent,
                                 std::function<double()> availableMemory)
    : QWidget(parent), m_devices(std::move(devices)), m_availableMemory(std::move(availableMemory))
{
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(createFlowGroup());
    layout->addWidget(createTrackingGroup());
    layout->addWidget(createBackendGroup());
    layout->addStretch(1);
    showSettings();
    connectEdits();
}

QWidget* SimulationPanel::createFlowGroup()
{
    m_marbling = new QRadioButton(tr("Marbling"));
    m_marbling->setObjectName(QStringLiteral("marbling"));
    m_marbling->setToolTip(tr("Low viscosity: the ink keeps moving after a stroke"));
    m_shapeDesign = new QRadioButton(tr("Shape design"));
    m_shapeDesign->setObjectName(QStringLiteral("shapeDesign"));
    m_shapeDesign->setToolTip(tr("High viscosity: the ink stops right after a stroke"));
    m_mode = new QButtonGroup(this);
    m_mode->addButton(m_marbling, static_cast<int>(model::FluidMode::Marbling));
    m_mode->addButton(m_shapeDesign, static_cast<int>(model::FluidMode::ShapeDesign));
    auto* modeRow = new QHBoxLayout;
    modeRow->addWidget(m_marbling);
    modeRow->addWidget(m_shapeDesign);

    m_viscosity = decadeSpinBox("viscosity", 0.0, kMaxViscosity);
    m_viscosity->setToolTip(tr("Kinematic viscosity in canvas units²/s"));
    m_stylusRadius = decadeSpinBox("stylusRadius", std::pow(10.0, -kDecimals), limits::maxCanvasSize);
    m_stylusRadius->setToolTip(tr("The radius of a stylus stroke, in canvas units"));
    m_stylusResponse = decadeSpinBox("stylusResponse", 0.0, kMaxStylusResponse);
    m_stylusResponse->setToolTip(tr("Seconds the water under the stylus takes to follow it; 0: at once"));
    m_gridX = committingSpinBox<QSpinBox>("gridX");
    m_gridY = committingSpinBox<QSpinBox>("gridY");
    auto* gridRow = new QHBoxLayout;
    for (QSpinBox* box : {m_gridX, m_gridY}) {
        box->setRange(limits::minGrid, limits::maxGrid);
        gridRow->addWidget(box, 1);
    }
    gridRow->insertWidget(1, new QLabel(QStringLiteral("×")));

    m_flowU = readOnlyLine("flowU");
    m_flowV = readOnlyLine("flowV");

    auto* group = new QGroupBox(tr("Flow"));
    m_flowForm = new QFormLayout(group);
    m_flowForm->addRow(tr("Mode:"), modeRow);
    m_flowForm->addRow(tr("Viscosity:"), m_viscosity);
    m_flowForm->addRow(tr("Stylus radius:"), m_stylusRadius);
    m_flowForm->addRow(tr("Stylus response:"), m_stylusResponse);
    m_flowForm->addRow(tr("Grid:"), gridRow);
    m_flowForm->addRow(tr("u(x, y, t):"), m_flowU);
    m_flowForm->addRow(tr("v(x, y, t):"), m_flowV);
    return group;
}

QWidget* SimulationPanel::createTrackingGroup()
{
    m_maxSpacing = decadeSpinBox("maxSpacing", std::pow(10.0, -kDecimals), limits::maxCanvasSize);
    m_maxSpacing->setToolTip(tr("The longest edge of a contour, in canvas units"));
    m_adaptive = checkBox(tr("Adaptive spacing"), "adaptive");
    m_proximity = checkBox(tr("Keep contours apart"), "proximity");
    m_areaCorrection = checkBox(tr("Area correction"), "areaCorrection");
    m_maxVertices = committingSpinBox<QSpinBox>("maxVertices");
    m_maxVertices->setRange(kMinVertices, static_cast<int>(limits::maxVertices));
    m_maxVertices->setGroupSeparatorShown(true);
    m_maxVertices->setToolTip(tr("Refinement stops here; at most what the memory available holds"));
    m_memoryNote = new QLabel;
    m_memoryNote->setObjectName(QStringLiteral("memoryNote"));
    m_memoryNote->setWordWrap(true);  // one sentence, however narrow the dock
    m_memoryNote->hide();

    auto* group = new QGroupBox(tr("Tracking"));
    auto* form = new QFormLayout(group);
    form->addRow(tr("Max spacing:"), m_maxSpacing);
    form->addRow(m_adaptive);
    form->addRow(m_proximity);
    form->addRow(m_areaCorrection);
    form->addRow(tr("Max vertices:"), m_maxVertices);
    form->addRow(m_memoryNote);
    return group;
}

QWidget* SimulationPanel::createBackendGroup()
{
    m_backend = new QComboBox;
    m_backend->setObjectName(QStringLiteral("backend"));
    m_backend->addItem(tr("Reference"), kReference);
    m_backend->addItem(tr("OpenCL"), kOpenCl);
    m_device = new QComboBox;
    m_device->setObjectName(QStringLiteral("device"));
    if (m_devices.devices.empty()) {
        auto* model = qobject_cast<QStandardItemModel*>(m_backend->model());
        model->item(m_backend->findData(kOpenCl))->setEnabled(false);
        m_backend->setToolTip(tr("No OpenCL device: %1").arg(QString::fromStdString(m_devices.error)));
    }

    auto* group = new QGroupBox(tr("Backend"));
    auto* form = new QFormLayout(group);
    form->addRow(tr("Backend:"), m_backend);
    form->addRow(tr("Device:"), m_device);
    return group;
}

void SimulationPanel::connectEdits()
{
    connect(m_mode, &QButtonGroup::idClicked, this, [this](int mode) {
        edit(nullptr, [&](model::EngineSettings& s) { model::applyPreset(s.flow, model::FluidMode(mode)); });
    });
    const auto onDouble = [this](QDoubleSpinBox* box, double model::FlowSpec::*field) {
        connect(box, &QDoubleSpinBox::valueChanged, this,
                [=, this](double value) { edit(box, [&](model::EngineSettings& s) { s.flow.*field = value; }); });
    };
    onDouble(m_viscosity, &model::FlowSpec::viscosity);
    onDouble(m_stylusRadius, &model::FlowSpec::stylusRadius);
    onDouble(m_stylusResponse, &model::FlowSpec::stylusResponse);
    connect(m_gridX, &QSpinBox::valueChanged, this,
            [this](int value) { edit(m_gridX, [&](model::EngineSettings& s) { s.flow.gridX = value; }); });
    connect(m_gridY, &QSpinBox::valueChanged, this,
            [this](int value) { edit(m_gridY, [&](model::EngineSettings& s) { s.flow.gridY = value; }); });
    connect(m_maxSpacing, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        edit(m_maxSpacing, [&](model::EngineSettings& s) { s.tracking.maxSpacing = value; });
    });
    connect(m_adaptive, &QCheckBox::toggled, this,
            [this](bool on) { edit(nullptr, [&](model::EngineSettings& s) { s.tracking.adaptive = on; }); });
    connect(m_proximity, &QCheckBox::toggled, this,
            [this](bool on) { edit(nullptr, [&](model::EngineSettings& s) { s.tracking.proximity = on; }); });
    connect(m_areaCorrection, &QCheckBox::toggled, this,
            [this](bool on) { edit(nullptr, [&](model::EngineSettings& s) { s.tracking.areaCorrection = on; }); });
    connect(m_maxVertices, &QSpinBox::valueChanged, this, &SimulationPanel::editMaxVertices);
    connect(m_backend, &QComboBox::currentIndexChanged, this, [this] {
        edit(nullptr, [&](model::EngineSettings& s) { s.backend = m_backend->currentData().toString(); });
    });
    connect(m_device, &QComboBox::currentIndexChanged, this, [this] {
        edit(nullptr, [&](model::EngineSettings& s) { s.device = m_device->currentData().toInt(); });
    });
}

void SimulationPanel::setSettings(const model::EngineSettings& settings)
{
    // The document hands back the settings this panel just edited: a note on them stays.
    if (settings != m_settings)
        m_memoryNote->hide();
    m_settings = settings;
    showSettings();
}

// More vertices than the memory available holds beside the grid, by the estimate with which
// `vectorfluid render` refuses a scene, would end the simulation in an allocation failure hours
// later: the value is lowered to the most that fits, and the note says so.
void SimulationPanel::editMaxVertices(int value)
{
    if (m_showing)
        return;
    const double available = m_availableMemory();
    const std::int64_t fits = std::clamp<std::int64_t>(maxVerticesFitting(m_settings.flow, available), kMinVertices,
                                                       m_maxVertices->maximum());
    m_memoryNote->setVisible(value > fits);
    if (value > fits) {
        m_memoryNote->setText(tr("%1 vertices need about %2 of memory, more than the %3 available: lowered to %4.")
                                  .arg(locale().toString(value),
                                       bytesText(vertexBytes(value) + gridBytes(m_settings.flow)),
                                       bytesText(available), locale().toString(qlonglong(fits))));
        value = int(fits);
    }
    edit(m_maxVertices, [&](model::EngineSettings& s) { s.tracking.maxVertices = value; });
}

void SimulationPanel::edit(const QObject* spinBox, const std::function<void(model::EngineSettings&)>& change)
{
    if (m_showing)
        return;
    model::EngineSettings edited = m_settings;
    change(edited);
    const bool changed = edited != m_settings;
    m_settings = edited;
    showSettings();  // the mode follows the viscosity, the device combo the backend
    if (changed)
        emit settingsEdited(m_settings, spinBox ? spinBox->objectName() : QString());
}

void SimulationPanel::showSettings()
{
    m_showing = true;
    const model::FlowSpec& flow = m_settings.flow;
    const bool fluid = flow.type == model::FlowSpec::Type::Fluid;
    // An analytic flow prescribes the velocity: it has no viscosity or grid to edit.
    for (QWidget* fluidOnly : std::initializer_list<QWidget*>{m_marbling, m_shapeDesign, m_viscosity, m_stylusRadius,
                                                               m_stylusResponse, m_gridX, m_gridY})
        fluidOnly->setEnabled(fluid);
    m_flowForm->setRowVisible(m_flowU, !fluid);
    m_flowForm->setRowVisible(m_flowV, !fluid);
    m_flowU->setText(flow.u);
    m_flowV->setText(flow.v);
    showMode();
    m_viscosity->setValue(flow.viscosity);
    m_stylusRadius->setValue(flow.stylusRadius);
    m_stylusResponse->setValue(flow.stylusResponse);
    m_gridX->setValue(flow.gridX);
    m_gridY->setValue(flow.gridY);

    const model::TrackingSpec& tracking = m_settings.tracking;
    m_maxSpacing->setValue(tracking.maxSpacing);
    m_adaptive->setChecked(tracking.adaptive);
    m_proximity->setChecked(tracking.proximity);
    m_areaCorrection->setChecked(tracking.areaCorrection);
    m_maxVertices->setValue(static_cast<int>(std::clamp<std::int64_t>(tracking.maxVertices, kMinVertices, limits::maxVertices)));

    m_backend->setCurrentIndex(m_backend->findData(m_settings.backend));
    showDevices();
    m_showing = false;
}

// A mode is shown checked only while the fluid is its preset exactly; other values are a custom
// fluid, shown with neither checked (both stay enabled, to pick one again).
void SimulationPanel::showMode()
{
    m_mode->setExclusive(false);  // an exclusive group cannot show neither button checked
    m_marbling->setChecked(model::isPreset(m_settings.flow, model::FluidMode::Marbling));
    m_shapeDesign->setChecked(model::isPreset(m_settings.flow, model::FluidMode::ShapeDesign));
    m_mode->setExclusive(true);
}

void SimulationPanel::showDevices()
{
    m_device->clear();
    if (m_devices.devices.empty()) {
        m_device->addItem(tr("No OpenCL device"), -1);
        m_device->setToolTip(QString::fromStdString(m_devices.error));
        m_device->setEnabled(false);
        return;
    }
    m_device->addItem(tr("Automatic"), -1);
    for (const sim::opencl::DeviceInfo& device : m_devices.devices)
        m_device->addItem(deviceText(device), device.index);
    // A scene from another machine may name a device this one lacks; show it rather than hide it.
    if (m_device->findData(m_settings.device) < 0)
        m_device->addItem(tr("%1: not on this machine").arg(m_settings.device), m_settings.device);
    m_device->setCurrentIndex(m_device->findData(m_settings.device));
    m_device->setEnabled(m_settings.backend == kOpenCl);
}

} // namespace vf::app
