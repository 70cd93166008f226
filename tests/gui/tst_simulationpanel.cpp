// The Simulation dock's panel driven through its widgets: every committed edit is exactly one
// settingsEdited that changes exactly the field edited, showing settings is no edit, the mode and
// the viscosity follow each other, the ranges are the scene format's, and max vertices are held
// to what the memory available holds.
#include "FindChild.h"
#include "app/SimulationPanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QStyle>
#include <QStyleOptionButton>
#include <QTest>

#include <functional>
#include <memory>

using namespace vf;
using model::EngineSettings;

namespace {

using vf::test::child;

sim::opencl::DeviceListing twoDevices()
{
    sim::opencl::DeviceListing listing;
    listing.devices.push_back({0, "Test platform", "Fake GPU", "GPU", "OpenCL 1.2", 8, 1u << 30});
    listing.devices.push_back({1, "Test platform", "Fake CPU", "CPU", "OpenCL 3.0", 2, 1u << 30});
    return listing;
}

sim::opencl::DeviceListing noDevices()
{
    sim::opencl::DeviceListing listing;
    listing.error = "no OpenCL platforms";
    return listing;
}

// Every field away from its default, so that a control showing the wrong field is noticed.
EngineSettings testSettings()
{
    EngineSettings settings;
    settings.flow.gridX = 96;
    settings.flow.gridY = 48;
    model::applyPreset(settings.flow, model::FluidMode::Marbling);
    settings.tracking.maxSpacing = 0.008;
    settings.tracking.adaptive = false;
    settings.tracking.proximity = true;
    settings.tracking.areaCorrection = false;
    settings.tracking.maxVertices = 250'000;
    settings.backend = QStringLiteral("opencl");
    settings.device = 1;
    return settings;
}

void typeAndCommit(QAbstractSpinBox* box, const QString& text)
{
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
}

void pick(QComboBox* combo, const QString& text)
{
    const int target = combo->findText(text);
    QVERIFY2(target >= 0, qPrintable(text));
    while (combo->currentIndex() != target)
        QTest::keyClick(combo, combo->currentIndex() < target ? Qt::Key_Down : Qt::Key_Up);
}

// On the indicator: a check box in a form row is wider than its text, and its middle is no button.
void clickBox(QCheckBox* box)
{
    QStyleOptionButton option;
    option.initFrom(box);
    const QRect indicator = box->style()->subElementRect(QStyle::SE_CheckBoxIndicator, &option, box);
    QTest::mouseClick(box, Qt::LeftButton, {}, indicator.center());
}

EngineSettings edited(const QSignalSpy& spy, qsizetype i = 0)
{
    return spy.at(i).at(0).value<EngineSettings>();
}

struct Edit {
    const char* name;
    std::function<void(app::SimulationPanel&)> act;
    std::function<void(EngineSettings&)> expect;
};

const std::vector<Edit>& edits()
{
    using Panel = app::SimulationPanel;
    static const std::vector<Edit> table{
        {"grid x", [](Panel& p) { typeAndCommit(child<QSpinBox>(p, "gridX"), QStringLiteral("128")); },
         [](EngineSettings& s) { s.flow.gridX = 128; }},
        {"grid y", [](Panel& p) { typeAndCommit(child<QSpinBox>(p, "gridY"), QStringLiteral("32")); },
         [](EngineSettings& s) { s.flow.gridY = 32; }},
        {"viscosity", [](Panel& p) { typeAndCommit(child<QDoubleSpinBox>(p, "viscosity"), QStringLiteral("0.02")); },
         [](EngineSettings& s) { s.flow.viscosity = 0.02; }},
        {"shape design", [](Panel& p) { QTest::mouseClick(child<QRadioButton>(p, "shapeDesign"), Qt::LeftButton); },
         [](EngineSettings& s) { model::applyPreset(s.flow, model::FluidMode::ShapeDesign); }},
        {"stylus radius", [](Panel& p) { typeAndCommit(child<QDoubleSpinBox>(p, "stylusRadius"), QStringLiteral("0.05")); },
         [](EngineSettings& s) { s.flow.stylusRadius = 0.05; }},
        {"stylus response", [](Panel& p) { typeAndCommit(child<QDoubleSpinBox>(p, "stylusResponse"), QStringLiteral("0.004")); },
         [](EngineSettings& s) { s.flow.stylusResponse = 0.004; }},
        {"max spacing", [](Panel& p) { typeAndCommit(child<QDoubleSpinBox>(p, "maxSpacing"), QStringLiteral("0.002")); },
         [](EngineSettings& s) { s.tracking.maxSpacing = 0.002; }},
        {"adaptive", [](Panel& p) { clickBox(child<QCheckBox>(p, "adaptive")); },
         [](EngineSettings& s) { s.tracking.adaptive = true; }},
        {"proximity", [](Panel& p) { clickBox(child<QCheckBox>(p, "proximity")); },
         [](EngineSettings& s) { s.tracking.proximity = false; }},
        {"area correction", [](Panel& p) { QTest::keyClick(child<QCheckBox>(p, "areaCorrection"), Qt::Key_Space); },
         [](EngineSettings& s) { s.tracking.areaCorrection = true; }},
        {"max vertices", [](Panel& p) { typeAndCommit(child<QSpinBox>(p, "maxVertices"), QStringLiteral("5000")); },
         [](EngineSettings& s) { s.tracking.maxVertices = 5000; }},
        {"backend", [](Panel& p) { pick(child<QComboBox>(p, "backend"), QStringLiteral("Reference")); },
         [](EngineSettings& s) { s.backend = QStringLiteral("reference"); }},
        {"device", [](Panel& p) { pick(child<QComboBox>(p, "device"), QStringLiteral("0: Fake GPU [GPU]")); },
         [](EngineSettings& s) { s.device = 0; }},
    };
    return table;
}

} // namespace

class TestSimulationPanel : public QObject {
    Q_OBJECT

private slots:
    void setSettingsShowsThemAndEmitsNothing();
    void eachEditEmitsOnceWithThatFieldChanged_data();
    void eachEditEmitsOnceWithThatFieldChanged();
    void typingCommitsOnEnterOnly();
    void unchangedValuesEmitNothing();
    void modeSetsThePreset();
    void modeFollowsTheViscosity();
    void viscosityStepsByAFractionOfItself();
    void referenceBackendDisablesTheDevice();
    void withoutDevicesOpenClCannotBeChosen();
    void unknownDeviceIsShownAsMissing();
    void rangesAreTheSceneFormatLimits();
    void typedValuesAreClamped();
    void maxVerticesBeyondMemoryAreLowered();
    void analyticFlowShowsItsExpressions();

private:
    std::unique_ptr<app::SimulationPanel> openPanel(sim::opencl::DeviceListing devices = twoDevices(),
                                                    std::function<double()> availableMemory = app::availableMemory);
};

std::unique_ptr<app::SimulationPanel> TestSimulationPanel::openPanel(sim::opencl::DeviceListing devices,
                                                                     std::function<double()> availableMemory)
{
    auto panel = std::make_unique<app::SimulationPanel>(std::move(devices), nullptr, std::move(availableMemory));
    panel->setSettings(testSettings());
    panel->show();
    if (!QTest::qWaitForWindowExposed(panel.get()))
        qFatal("the panel was not shown");
    return panel;
}

void TestSimulationPanel::setSettingsShowsThemAndEmitsNothing()
{
    app::SimulationPanel panel(twoDevices());
    QSignalSpy spy(&panel, &app::SimulationPanel::settingsEdited);
    const EngineSettings settings = testSettings();
    panel.setSettings(settings);
    QCOMPARE(spy.count(), 0);
    QVERIFY(panel.settings() == settings);

    QCOMPARE(child<QSpinBox>(panel, "gridX")->value(), 96);
    QCOMPARE(child<QSpinBox>(panel, "gridY")->value(), 48);
    QCOMPARE(child<QDoubleSpinBox>(panel, "viscosity")->value(), model::marblingPreset.viscosity);
    QVERIFY(child<QRadioButton>(panel, "marbling")->isChecked());
    QVERIFY(!child<QRadioButton>(panel, "shapeDesign")->isChecked());
    QCOMPARE(child<QDoubleSpinBox>(panel, "maxSpacing")->value(), 0.008);
    QVERIFY(!child<QCheckBox>(panel, "adaptive")->isChecked());
    QVERIFY(child<QCheckBox>(panel, "proximity")->isChecked());
    QVERIFY(!child<QCheckBox>(panel, "areaCorrection")->isChecked());
    QCOMPARE(child<QSpinBox>(panel, "maxVertices")->value(), 250'000);
    QCOMPARE(child<QComboBox>(panel, "backend")->currentData().toString(), QStringLiteral("opencl"));
    QCOMPARE(child<QComboBox>(panel, "device")->currentData().toInt(), 1);
    QVERIFY(child<QComboBox>(panel, "device")->isEnabled());
}

void TestSimulationPanel::eachEditEmitsOnceWithThatFieldChanged_data()
{
    QTest::addColumn<int>("edit");
    for (std::size_t i = 0; i < edits().size(); ++i)
        QTest::newRow(edits()[i].name) << int(i);
}

void TestSimulationPanel::eachEditEmitsOnceWithThatFieldChanged()
{
    QFETCH(int, edit);
    const auto panel = openPanel();
    QSignalSpy spy(panel.get(), &app::SimulationPanel::settingsEdited);
    edits()[std::size_t(edit)].act(*panel);

    EngineSettings expected = testSettings();
    edits()[std::size_t(edit)].expect(expected);
    QCOMPARE(spy.count(), 1);
    QVERIFY(edited(spy) == expected);
    QVERIFY(panel->settings() == expected);
}

void TestSimulationPanel::typingCommitsOnEnterOnly()
{
    const auto panel = openPanel();
    QSignalSpy spy(panel.get(), &app::SimulationPanel::settingsEdited);
    QSpinBox* gridX = child<QSpinBox>(*panel, "gridX");
    gridX->selectAll();
    QTest::keyClicks(gridX, QStringLiteral("256"));
    QCOMPARE(spy.count(), 0);  // "2", "25", "256" are no edits of their own
    QTest::keyClick(gridX, Qt::Key_Return);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(edited(spy).flow.gridX, 256);
}

void TestSimulationPanel::unchangedValuesEmitNothing()
{
    const auto panel = openPanel();
    QSignalSpy spy(panel.get(), &app::SimulationPanel::settingsEdited);
    typeAndCommit(child<QSpinBox>(*panel, "gridX"), QStringLiteral("96"));
    QTest::mouseClick(child<QRadioButton>(*panel, "marbling"), Qt::LeftButton);  // already marbling
    QCOMPARE(spy.count(), 0);
    QVERIFY(panel->settings() == testSettings());
}

void TestSimulationPanel::modeSetsThePreset()
{
    const auto panel = openPanel();
    QSignalSpy spy(panel.get(), &app::SimulationPanel::settingsEdited);
    QRadioButton* marbling = child<QRadioButton>(*panel, "marbling");
    QRadioButton* shapeDesign = child<QRadioButton>(*panel, "shapeDesign");
    const QDoubleSpinBox* viscosity = child<QDoubleSpinBox>(*panel, "viscosity");

    const QDoubleSpinBox* radius = child<QDoubleSpinBox>(*panel, "stylusRadius");
    const QDoubleSpinBox* response = child<QDoubleSpinBox>(*panel, "stylusResponse");

    QTest::mouseClick(shapeDesign, Qt::LeftButton);
    QCOMPARE(viscosity->value(), model::shapeDesignPreset.viscosity);
    QCOMPARE(radius->value(), model::shapeDesignPreset.stylusRadius);
    QCOMPARE(response->value(), model::shapeDesignPreset.stylusResponse);
    QVERIFY(shapeDesign->isChecked() && !marbling->isChecked());
    QTest::mouseClick(marbling, Qt::LeftButton);
    QCOMPARE(viscosity->value(), model::marblingPreset.viscosity);
    QCOMPARE(radius->value(), model::marblingPreset.stylusRadius);
    QCOMPARE(response->value(), model::marblingPreset.stylusResponse);
    QVERIFY(marbling->isChecked() && !shapeDesign->isChecked());
    QCOMPARE(spy.count(), 2);
    QVERIFY(model::isPreset(edited(spy, 0).flow, model::FluidMode::ShapeDesign));
    QVERIFY(model::isPreset(edited(spy, 1).flow, model::FluidMode::Marbling));
}

void TestSimulationPanel::modeFollowsTheViscosity()
{
    const auto panel = openPanel();
    QDoubleSpinBox* viscosity = child<QDoubleSpinBox>(*panel, "viscosity");
    QRadioButton* marbling = child<QRadioButton>(*panel, "marbling");
    QRadioButton* shapeDesign = child<QRadioButton>(*panel, "shapeDesign");

    QTest::mouseClick(shapeDesign, Qt::LeftButton);
    typeAndCommit(viscosity, QStringLiteral("0.01"));  // between the presets: a custom fluid, neither mode
    QVERIFY(!shapeDesign->isChecked() && !marbling->isChecked());
    // ...and both stay as legible as ever, to pick one again.
    QVERIFY(shapeDesign->isEnabled() && marbling->isEnabled());
    typeAndCommit(viscosity, QString::number(model::shapeDesignPreset.viscosity));
    QVERIFY(shapeDesign->isChecked() && !marbling->isChecked());
    typeAndCommit(child<QDoubleSpinBox>(*panel, "stylusRadius"), QStringLiteral("0.05"));  // a custom pen
    QVERIFY(!shapeDesign->isChecked() && !marbling->isChecked());
    QTest::mouseClick(marbling, Qt::LeftButton);
    QVERIFY(marbling->isChecked() && !shapeDesign->isChecked());
}

// Adaptive decimal steps: about a tenth of the value at marbling and at shape-design magnitudes.
void TestSimulationPanel::viscosityStepsByAFractionOfItself()
{
    const auto panel = openPanel();
    QSignalSpy spy(panel.get(), &app::SimulationPanel::settingsEdited);
    QDoubleSpinBox* viscosity = child<QDoubleSpinBox>(*panel, "viscosity");
    for (const double start : {model::marblingPreset.viscosity, model::shapeDesignPreset.viscosity}) {
        EngineSettings settings = testSettings();
        settings.flow.viscosity = start;
        panel->setSettings(settings);
        spy.clear();
        QTest::keyClick(viscosity, Qt::Key_Up);
        QCOMPARE(spy.count(), 1);
        const double ratio = edited(spy).flow.viscosity / start;
        QVERIFY2(ratio > 1.01 && ratio < 1.5, qPrintable(QString::number(ratio)));
        QVERIFY(!child<QRadioButton>(*panel, "marbling")->isChecked());
        QVERIFY(!child<QRadioButton>(*panel, "shapeDesign")->isChecked());
    }
}

void TestSimulationPanel::referenceBackendDisablesTheDevice()
{
    const auto panel = openPanel();
    QComboBox* backend = child<QComboBox>(*panel, "backend");
    const QComboBox* device = child<QComboBox>(*panel, "device");
    QVERIFY(device->isEnabled());
    pick(backend, QStringLiteral("Reference"));
    QVERIFY(!device->isEnabled());
    pick(backend, QStringLiteral("OpenCL"));
    QVERIFY(device->isEnabled());
    QCOMPARE(device->currentData().toInt(), 1);  // the choice survives the round trip
    QCOMPARE(device->itemText(0), QStringLiteral("Automatic"));
}

void TestSimulationPanel::withoutDevicesOpenClCannotBeChosen()
{
    const auto panel = openPanel(noDevices());
    QComboBox* backend = child<QComboBox>(*panel, "backend");
    const QComboBox* device = child<QComboBox>(*panel, "device");
    QVERIFY(!device->isEnabled());
    QVERIFY(device->currentText().contains(QLatin1String("No OpenCL device")));
    const auto* items = qobject_cast<const QStandardItemModel*>(backend->model());
    QVERIFY(items);
    QVERIFY(!items->item(backend->findData(QStringLiteral("opencl")))->isEnabled());

    QSignalSpy spy(panel.get(), &app::SimulationPanel::settingsEdited);
    pick(backend, QStringLiteral("Reference"));
    QCOMPARE(spy.count(), 1);
    QTest::keyClick(backend, Qt::Key_Down);  // the disabled OpenCL entry is skipped
    QCOMPARE(backend->currentText(), QStringLiteral("Reference"));
    QCOMPARE(spy.count(), 1);
}

void TestSimulationPanel::unknownDeviceIsShownAsMissing()
{
    const auto panel = openPanel();
    EngineSettings settings = testSettings();
    settings.device = 7;
    QSignalSpy spy(panel.get(), &app::SimulationPanel::settingsEdited);
    panel->setSettings(settings);
    const QComboBox* device = child<QComboBox>(*panel, "device");
    QCOMPARE(device->currentData().toInt(), 7);
    QVERIFY(device->currentText().contains(QLatin1String("not on this machine")));
    QCOMPARE(spy.count(), 0);
    QVERIFY(panel->settings() == settings);
}

void TestSimulationPanel::rangesAreTheSceneFormatLimits()
{
    const auto panel = openPanel();
    for (const char* name : {"gridX", "gridY"}) {
        QCOMPARE(child<QSpinBox>(*panel, name)->minimum(), model::limits::minGrid);
        QCOMPARE(child<QSpinBox>(*panel, name)->maximum(), model::limits::maxGrid);
    }
    QCOMPARE(child<QSpinBox>(*panel, "maxVertices")->minimum(), 3);
    QCOMPARE(child<QSpinBox>(*panel, "maxVertices")->maximum(), model::limits::maxVertices);
    QCOMPARE(child<QDoubleSpinBox>(*panel, "viscosity")->minimum(), 0.0);
    QCOMPARE(child<QDoubleSpinBox>(*panel, "viscosity")->maximum(), 10.0);
    QVERIFY(child<QDoubleSpinBox>(*panel, "maxSpacing")->minimum() > 0);
    QCOMPARE(child<QDoubleSpinBox>(*panel, "maxSpacing")->maximum(), model::limits::maxCanvasSize);
}

void TestSimulationPanel::typedValuesAreClamped()
{
    const auto panel = openPanel();
    QSignalSpy spy(panel.get(), &app::SimulationPanel::settingsEdited);
    QSpinBox* gridX = child<QSpinBox>(*panel, "gridX");
    typeAndCommit(gridX, QStringLiteral("2"));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(edited(spy, 0).flow.gridX, model::limits::minGrid);
    typeAndCommit(gridX, QStringLiteral("5000"));
    QCOMPARE(spy.count(), 2);
    QVERIFY(edited(spy, 1).flow.gridX <= model::limits::maxGrid);

    typeAndCommit(gridX, QString::number(model::limits::maxGrid));
    spy.clear();
    QTest::keyClick(gridX, Qt::Key_Up);  // nothing beyond the limit
    QCOMPARE(spy.count(), 0);
    QCOMPARE(panel->settings().flow.gridX, model::limits::maxGrid);

    typeAndCommit(child<QSpinBox>(*panel, "maxVertices"), QStringLiteral("1"));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(edited(spy).tracking.maxVertices, 3);
    typeAndCommit(child<QDoubleSpinBox>(*panel, "maxSpacing"), QStringLiteral("0"));
    QCOMPARE(spy.count(), 2);
    QVERIFY(edited(spy, 1).tracking.maxSpacing > 0);
}

// With 1 GB available, the most that `vectorfluid render`'s estimate (app/MemoryBudget.cpp) lets
// beside the 96 x 48 grid: (1e9 - 96 * 48 * 600) / 200 = 4,986,176 vertices.
void TestSimulationPanel::maxVerticesBeyondMemoryAreLowered()
{
    const auto panel = openPanel(twoDevices(), [] { return 1e9; });
    QSignalSpy spy(panel.get(), &app::SimulationPanel::settingsEdited);
    QSpinBox* maxVertices = child<QSpinBox>(*panel, "maxVertices");
    const QLabel* note = child<QLabel>(*panel, "memoryNote");
    QVERIFY(!note->isVisible());

    typeAndCommit(maxVertices, QStringLiteral("10000000"));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(edited(spy).tracking.maxVertices, 4'986'176);
    QCOMPARE(maxVertices->value(), 4'986'176);
    QVERIFY(note->isVisible());
    const QLocale locale = panel->locale();
    QCOMPARE(note->text(), QStringLiteral("%1 vertices need about 2 GB of memory, more than the 1 GB available: lowered to %2.")
                               .arg(locale.toString(10'000'000), locale.toString(4'986'176)));

    QTest::keyClick(maxVertices, Qt::Key_Up);  // no step past it either
    QCOMPARE(spy.count(), 1);
    QCOMPARE(maxVertices->value(), 4'986'176);
    // The window hands the edited settings back from the document: the note stays; other
    // settings (an undo, another document) take it away.
    panel->setSettings(edited(spy));
    QVERIFY(note->isVisible());
    panel->setSettings(testSettings());
    QVERIFY(!note->isVisible());
    typeAndCommit(maxVertices, QStringLiteral("10000000"));
    QCOMPARE(spy.count(), 2);
    QVERIFY(note->isVisible());

    typeAndCommit(maxVertices, QStringLiteral("5000"));
    QCOMPARE(spy.count(), 3);
    QCOMPARE(edited(spy, 2).tracking.maxVertices, 5000);
    QVERIFY(!note->isVisible());
}

void TestSimulationPanel::analyticFlowShowsItsExpressions()
{
    const auto panel = openPanel();
    const QLineEdit* u = child<QLineEdit>(*panel, "flowU");
    const QLineEdit* v = child<QLineEdit>(*panel, "flowV");
    QVERIFY(!u->isVisibleTo(panel.get()));

    EngineSettings settings = testSettings();
    settings.flow.type = model::FlowSpec::Type::Analytic;
    settings.flow.u = QStringLiteral("-sin(pi*x)^2*sin(2*pi*y)");
    settings.flow.v = QStringLiteral("sin(pi*y)^2*sin(2*pi*x)");
    panel->setSettings(settings);
    QVERIFY(u->isVisibleTo(panel.get()) && v->isVisibleTo(panel.get()));
    QVERIFY(u->isReadOnly() && v->isReadOnly());
    QCOMPARE(u->text(), settings.flow.u);
    QCOMPARE(v->text(), settings.flow.v);
    for (const char* fluidOnly : {"viscosity", "gridX", "gridY", "marbling", "shapeDesign"})
        QVERIFY2(!child<QWidget>(*panel, fluidOnly)->isEnabled(), fluidOnly);
    QVERIFY(child<QWidget>(*panel, "maxSpacing")->isEnabled());  // tracking still applies
}

QTEST_MAIN(TestSimulationPanel)
#include "tst_simulationpanel.moc"
