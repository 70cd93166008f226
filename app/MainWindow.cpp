// The main window: its actions, docks and menus, and what each user action does to the document
// (import, export, tools, modes). Opening and saving are in MainWindowFiles.cpp; the pieces with
// their own state live apart (Canvas, ExportDialog, AnimationDialog, RegionsDock, SimulationPanel,
// Recovery, RecentFiles, ClipboardExport).
// Past 500 lines because every action's slot is here, each short and each using the window's state.
#include "app/MainWindow.h"

#include "app/AnimationDialog.h"
#include "app/ClipboardExport.h"
#include "app/ExportDialog.h"
#include "app/MarblingToolBar.h"
#include "app/PaletteDock.h"
#include "app/GatherDialog.h"
#include "app/PatternDialog.h"
#include "app/RecentFiles.h"
#include "app/Recovery.h"
#include "app/SimulationPanel.h"
#include "app/TextToolBar.h"
#include "model/SvgImport.h"
#include "model/TextOutlines.h"
#include "sim/opencl/DeviceList.h"

#include <QActionGroup>
#include <QApplication>
#include <QColorDialog>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenuBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QThreadPool>
#include <QToolBar>

#include <exception>

namespace vf::app {

namespace {

const QString historyBudgetKey = QStringLiteral("history/budgetMB");

sim::Vec2 toVec(QPointF p)
{
    return {p.x(), p.y()};
}

// What the history calls a marbling tool's step.
QString marblingToolName(Tool tool)
{
    return tool == Tool::Comb           ? MainWindow::tr("Comb")
         : tool == Tool::CircularComb ? MainWindow::tr("Circular comb")
                                        : MainWindow::tr("Swirl");
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent)
    , m_document(m_simulation)
    , m_regionModel(m_document)
    , m_canvas(new Canvas(this))
{
    m_saves.setMaxThreadCount(1);
    m_ask = [this](const QString& title, const QString& text, QMessageBox::StandardButtons buttons) {
        return QMessageBox::question(this, title, text, buttons);
    };
    m_report = [this](const QString& title, const QString& text) { QMessageBox::warning(this, title, text); };

    setCentralWidget(m_canvas);
    createDocks();
    createActions();
    createStatusBar();
    connectDocument();
    m_recovery = new Recovery(m_document, {}, this);
    setHistoryBudgetMb(QSettings().value(historyBudgetKey, int(model::Document::defaultHistoryBudget >> 20)).toInt());
    resize(1280, 800);
    newDocument();
    if (const QStringList gone = m_paletteDock->loadRemembered(); !gone.isEmpty())
        statusBar()->showMessage(tr("Palette forgotten: %1").arg(gone.front()), 10000);
}

MainWindow::~MainWindow()
{
    // A save or autosave under way may wait for a state the worker has still to take: they end
    // first, while the worker runs. Then nothing of the document may call back into this window.
    m_saves.waitForDone();
    QThreadPool::globalInstance()->waitForDone();
    delete m_recovery;
    m_recovery = nullptr;
    disconnect(&m_document.undoStack(), nullptr, this, nullptr);
    disconnect(&m_document, nullptr, this, nullptr);
}

// ---- Set-up ------------------------------------------------------------------------------------------

void MainWindow::createActions()
{
    createFileMenu();
    createEditMenu();
    createTools();
    createSimulationMenu();
    createViewMenu();
}

void MainWindow::createFileMenu()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, this, [this] {
        if (maybeSave())
            newDocument();
    });
    file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::open);
    m_recentFiles = new RecentFiles(file->addMenu(tr("Open &Recent")), [this](const QString& path) {
        if (maybeSave())
            openFile(path);
    }, this);
    file->addAction(tr("&Save"), QKeySequence::Save, this, [this] { save(SaveMode::Background); });
    // Ctrl+Shift+S on every platform: some (the offscreen one, say) bind no key to SaveAs.
    file->addAction(tr("Save &As…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S), this, [this] { saveAs(SaveMode::Background); });
    file->addSeparator();
    file->addAction(tr("&Import SVG…"), QKeySequence(Qt::CTRL | Qt::Key_I), this, &MainWindow::chooseImport);
    file->addAction(tr("&Export…"), QKeySequence(Qt::CTRL | Qt::Key_E), this, &MainWindow::exportPicture);
    file->addAction(tr("Export &Animation…"), this, &MainWindow::exportAnimation);
    file->addAction(tr("&Copy as SVG"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C), this, &MainWindow::copySvg);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
}

void MainWindow::createEditMenu()
{
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_document.undoStack().createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = m_document.undoStack().createRedoAction(this, tr("&Redo"));
    // Ctrl+Shift+Z and Ctrl+Y everywhere, and whatever the platform adds, each once: a key given
    // twice makes the shortcut ambiguous and it does nothing.
    QList<QKeySequence> redoKeys{QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)};
    for (const QKeySequence& key : QKeySequence::keyBindings(QKeySequence::Redo))
        if (!redoKeys.contains(key))
            redoKeys << key;
    redo->setShortcuts(redoKeys);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    edit->addAction(m_regionsDock->duplicateAction());
    edit->addAction(m_regionsDock->deleteAction());
    edit->addSeparator();
    edit->addAction(tr("History &Memory…"), this, [this] {
        bool ok = false;
        const int mb = QInputDialog::getInt(this, tr("History memory"),
                                            tr("Memory for undo states (MB); past it the oldest steps can no longer be undone:"),
                                            int(m_document.historyBudget() >> 20), 16, 1 << 20, 64, &ok);
        if (ok)
            setHistoryBudgetMb(mb);
    });
    edit->addAction(tr("&Autosave Interval…"), this, [this] {
        bool ok = false;
        const int seconds = QInputDialog::getInt(this, tr("Autosave"), tr("Save unsaved work for recovery every (seconds):"),
                                                 m_recovery->interval(), 5, 3600, 5, &ok);
        if (ok)
            m_recovery->setInterval(seconds);
    });
}

// The tool bar and the Tools menu (one action per tool, each with its key), the ink colour, and
// the options bars of the Text tool and of the marbling tools.
void MainWindow::createTools()
{
    QToolBar* tools = addToolBar(tr("Tools"));
    tools->setObjectName(QStringLiteral("tools"));
    auto* toolGroup = new QActionGroup(this);
    const struct {
        QString text;
        QKeySequence key;
        Tool tool;
        const char* name;
    } toolList[] = {
        {tr("Se&lect"), QKeySequence(Qt::Key_V), Tool::Select, "toolSelect"},
        {tr("&Drop"), QKeySequence(Qt::Key_D), Tool::Drop, "toolDrop"},
        {tr("Spatte&r"), QKeySequence(Qt::Key_B), Tool::Spatter, "toolSpatter"},
        {tr("&Comb"), QKeySequence(Qt::Key_C), Tool::Comb, "toolComb"},
        {tr("Circular C&omb"), QKeySequence(Qt::Key_O), Tool::CircularComb, "toolCircularComb"},
        {tr("S&wirl"), QKeySequence(Qt::Key_W), Tool::Swirl, "toolSwirl"},
        {tr("&Stylus"), QKeySequence(Qt::Key_S), Tool::Stylus, "toolStylus"},
        {tr("&Text"), QKeySequence(Qt::Key_T), Tool::Text, "toolText"},
        {tr("&Pan"), QKeySequence(Qt::Key_H), Tool::Pan, "toolPan"},
    };
    QMenu* toolMenu = menuBar()->addMenu(tr("&Tools"));
    for (const auto& t : toolList) {
        QAction* a = toolGroup->addAction(t.text);
        a->setObjectName(QLatin1String(t.name));
        a->setShortcut(t.key);
        a->setCheckable(true);
        a->setToolTip(QStringLiteral("%1 (%2)").arg(QString(t.text).remove('&'), t.key.toString()));
        connect(a, &QAction::triggered, this, [this, tool = t.tool] { m_canvas->setTool(tool); });
        tools->addAction(a);
        toolMenu->addAction(a);
    }
    toolMenu->addSeparator();
    QAction* pattern = toolMenu->addAction(tr("P&attern…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P), this,
                                           &MainWindow::choosePattern);
    pattern->setObjectName(QStringLiteral("pattern"));
    QAction* gather = toolMenu->addAction(tr("&Gather Into…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_G), this,
                                          &MainWindow::chooseGather);
    gather->setObjectName(QStringLiteral("gather"));
    findChild<QAction*>(QStringLiteral("toolDrop"))->setChecked(true);
    m_canvas->setTool(Tool::Drop);

    auto* colorButton = new QPushButton(tr("Ink"), this);
    colorButton->setObjectName(QStringLiteral("inkColor"));
    colorButton->setToolTip(tr("Colour of the next drop or text"));
    connect(colorButton, &QPushButton::clicked, this, [this] {
        const QColor c = QColorDialog::getColor(m_inkColor, this, tr("Ink colour"), QColorDialog::ShowAlphaChannel);
        if (c.isValid())
            setInkColor(c);
    });
    tools->addSeparator();
    tools->addWidget(colorButton);
    setInkColor(m_inkColor);

    // The Text tool's options, on a bar of their own that shows while the tool is picked.
    m_textOptions = new TextToolBar(this);
    addToolBar(m_textOptions);
    m_textOptions->setVisible(false);
    connect(m_textOptions, &TextToolBar::changed, this, &MainWindow::previewText);
    connect(findChild<QAction*>(QStringLiteral("toolText")), &QAction::toggled, m_textOptions, &QWidget::setVisible);

    for (const auto& [kind, action] : {std::pair{MarblingToolBar::Kind::Comb, "toolComb"},
                                       std::pair{MarblingToolBar::Kind::CircularComb, "toolCircularComb"},
                                       std::pair{MarblingToolBar::Kind::Swirl, "toolSwirl"}}) {
        auto* options = new MarblingToolBar(kind, this);
        addToolBar(options);
        options->setVisible(false);
        const auto use = [this, options] { m_canvas->setToolOptions(options->options()); };
        connect(options, &MarblingToolBar::changed, this, use);
        use();
        connect(findChild<QAction*>(QLatin1String(action)), &QAction::toggled, options, &QWidget::setVisible);
    }
}

// The Simulation menu and the Playback tool bar: play, step, reset, and the two modes.
void MainWindow::createSimulationMenu()
{
    QMenu* simulation = menuBar()->addMenu(tr("&Simulation"));
    auto* playback = new QToolBar(tr("Playback"), this);
    // On the tools' row: the tools' options bars have a row of their own, so that a long one shows whole.
    insertToolBar(m_textOptions, playback);
    insertToolBarBreak(m_textOptions);
    playback->setObjectName(QStringLiteral("playback"));
    m_playAction = simulation->addAction(tr("&Play"));
    m_playAction->setObjectName(QStringLiteral("play"));
    m_playAction->setCheckable(true);
    m_playAction->setShortcut(QKeySequence(Qt::Key_Space));
    connect(m_playAction, &QAction::toggled, &m_simulation, &SimulationController::setPlaying);
    connect(&m_simulation, &SimulationController::playingChanged, m_playAction, [this](bool playing) {
        const QSignalBlocker block(m_playAction);
        m_playAction->setChecked(playing);
    });
    QAction* step = simulation->addAction(tr("Single &Step"), QKeySequence(Qt::Key_Period), &m_simulation, &SimulationController::stepOnce);
    step->setObjectName(QStringLiteral("step"));
    QAction* reset = simulation->addAction(tr("&Reset"), QKeySequence(Qt::CTRL | Qt::Key_R), this, [this] { m_document.reset(); });
    reset->setObjectName(QStringLiteral("reset"));
    playback->addActions({m_playAction, step, reset});
    simulation->addSeparator();
    auto* modes = new QActionGroup(this);
    m_marblingAction = modes->addAction(tr("&Marbling"));
    m_shapeDesignAction = modes->addAction(tr("Shape &Design"));
    m_marblingAction->setObjectName(QStringLiteral("modeMarbling"));
    m_shapeDesignAction->setObjectName(QStringLiteral("modeShapeDesign"));
    for (auto [action, mode] : {std::pair{m_marblingAction, model::FluidMode::Marbling},
                                std::pair{m_shapeDesignAction, model::FluidMode::ShapeDesign}}) {
        action->setCheckable(true);
        simulation->addAction(action);
        playback->addAction(action);
        connect(action, &QAction::triggered, this, [this, mode] {
            model::EngineSettings s = m_document.settings();
            model::applyPreset(s.flow, mode);
            m_document.setSettings(s);
        });
    }
}

void MainWindow::createViewMenu()
{
    QMenu* view = menuBar()->addMenu(tr("&View"));
    // The canvas's own zoom actions, their shortcuts made window-wide now that a menu shows them.
    for (QAction* zoom : m_canvas->actions()) {
        zoom->setShortcutContext(Qt::WindowShortcut);
        view->addAction(zoom);
    }
    view->addSeparator();
    const struct {
        QString text;
        const char* name;
        void (Canvas::*set)(bool);
    } overlays[] = {
        {tr("Show &Vertices"), "showVertices", &Canvas::setShowVertices},
        {tr("Show Ve&locity"), "showVelocity", &Canvas::setShowVelocity},
        {tr("Show &Grid"), "showGrid", &Canvas::setShowGrid},
    };
    for (const auto& o : overlays) {
        QAction* a = view->addAction(o.text);
        a->setObjectName(QLatin1String(o.name));
        a->setCheckable(true);
        connect(a, &QAction::toggled, m_canvas, o.set);
        if (o.set == &Canvas::setShowVelocity)
            connect(a, &QAction::toggled, &m_simulation, &SimulationController::setVelocityWanted);
    }
    view->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        view->addAction(dock->toggleViewAction());
}

void MainWindow::createDocks()
{
    m_regionsDock = new RegionsDock(m_document, m_regionModel, m_simulation, this);
    addDockWidget(Qt::RightDockWidgetArea, m_regionsDock);

    m_paletteDock = new PaletteDock(this);
    addDockWidget(Qt::LeftDockWidgetArea, m_paletteDock);
    resizeDocks({m_paletteDock}, {m_paletteDock->minimumSizeHint().width()}, Qt::Horizontal);  // the canvas keeps the room
    m_paletteDock->setInkColour(m_inkColor);
    connect(m_paletteDock, &PaletteDock::colourPicked, this, &MainWindow::setInkColor);
    connect(m_paletteDock, &PaletteDock::problem, this, [this](const QString& title, const QString& line) { m_report(title, line); });

    auto* history = new QDockWidget(tr("History"), this);
    history->setObjectName(QStringLiteral("historyDock"));
    m_historyView = new QUndoView(&m_document.undoStack(), history);
    m_historyView->setEmptyLabel(tr("<opened>"));
    history->setWidget(m_historyView);
    addDockWidget(Qt::RightDockWidgetArea, history);

    auto* simulation = new QDockWidget(tr("Simulation"), this);
    simulation->setObjectName(QStringLiteral("simulationDock"));
    // Scrolled, so that the docks fit a window of 800 pixels with the Regions list eight rows tall.
    auto* scroll = new QScrollArea(simulation);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    m_panel = new SimulationPanel(sim::opencl::listDevices(), scroll);
    scroll->setWidget(m_panel);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setMinimumWidth(m_panel->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width());
    simulation->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, simulation);
    // The settings whole where the window allows; the history takes what is left.
    resizeDocks({history, simulation}, {1, m_panel->sizeHint().height()}, Qt::Vertical);
    connect(m_panel, &SimulationPanel::settingsEdited, &m_document, &model::Document::setSettings);
}

void MainWindow::createStatusBar()
{
    // The figures change with every frame. Each label is as wide as its widest text from the
    // start, so the status bar does not jitter and the window is not laid out again as they grow.
    const struct {
        QLabel*& label;
        QString widest;
    } labels[] = {
        {m_timeLabel, tr("%1 s").arg(99999.99, 0, 'f', 2)},
        {m_verticesLabel, tr("%L1 vertices").arg(99'999'999)},
        {m_stepsLabel, tr("%1 steps/s").arg(9999.9, 0, 'f', 1)},
        {m_fpsLabel, tr("%1 fps").arg(999)},
        {m_backendLabel, {}},
    };
    for (const auto& l : labels) {
        l.label = new QLabel(this);
        l.label->setMinimumWidth(l.label->fontMetrics().horizontalAdvance(l.widest));
        l.label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        statusBar()->addPermanentWidget(l.label);
    }
    m_timeLabel->setObjectName(QStringLiteral("simulatedTime"));
    m_backendLabel->setObjectName(QStringLiteral("backendInUse"));
    connect(m_canvas, &Canvas::displayFpsChanged, this, [this](int fps) { m_fpsLabel->setText(tr("%1 fps").arg(fps)); });
}

void MainWindow::connectDocument()
{
    connect(&m_simulation, &SimulationController::frameArrived, this, &MainWindow::showFrame);
    connect(&m_simulation, &SimulationController::failed, this, [this](const QString& message) {
        statusBar()->showMessage(message, 10000);
    });
    connect(&m_simulation, &SimulationController::notice, this, [this](const QString& message) {
        statusBar()->showMessage(message, 10000);
    });
    connect(&m_document, &model::Document::regionsReset, this, [this] { m_canvas->setRegions(m_document.regions()); });
    connect(&m_document, &model::Document::regionChanged, this, [this] { m_canvas->setRegions(m_document.regions()); });
    connect(&m_document, &model::Document::settingsChanged, this, [this](const model::EngineSettings& s) {
        m_panel->setSettings(s);
        m_canvas->setStylusRadius(s.flow.stylusRadius);
        rememberBackend(s);
        m_marblingAction->setChecked(model::isPreset(s.flow, model::FluidMode::Marbling));
        m_shapeDesignAction->setChecked(model::isPreset(s.flow, model::FluidMode::ShapeDesign));
    });
    connect(&m_document, &model::Document::historyTrimmed, this, [this](int commands) {
        statusBar()->showMessage(tr("History memory budget reached: the oldest %n step(s) can no longer be undone", nullptr, commands), 10000);
    });
    connect(&m_document.undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(&m_document, &model::Document::filePathChanged, this, &MainWindow::updateTitle);

    connect(m_canvas, &Canvas::dropRequested, this, [this](QPointF center, double radius) {
        if (!m_document.canAddRegions()) {
            statusBar()->showMessage(tr("The scene's own drops are still landing; play on and drop again"), 5000);
            return;
        }
        m_document.drop(toVec(center), radius, m_inkColor);
    });
    connect(m_canvas, &Canvas::spatterRequested, this, &MainWindow::spatter);
    connect(m_canvas, &Canvas::toolApplied, this, [this](const model::Stroke& tool) {
        m_document.applyTools(marblingToolName(m_canvas->tool()), {tool});
    });
    connect(m_canvas, &Canvas::strokeStarted, this, [this] {
        m_document.beginStroke(m_canvas->tool() == Tool::Stylus ? QString()
                                                                : tr("%1 (in the water)").arg(marblingToolName(m_canvas->tool())));
        m_simulation.setStroking(true);
    });
    connect(m_canvas, &Canvas::strokeFinished, &m_simulation, [this] { m_simulation.setStroking(false); });
    connect(m_canvas, &Canvas::strokeMoved, this, [this](QPointF from, QPointF to, double seconds) {
        m_document.stroke({{toVec(from), toVec(to), m_document.settings().flow.stylusRadius, seconds}});
    });
    connect(m_canvas, &Canvas::pensMoved, &m_document, &model::Document::stroke);
    connect(m_canvas, &Canvas::textEdited, this, &MainWindow::previewText);
    connect(m_canvas, &Canvas::textCommitted, this, [this](QPointF at, const QString& text) { insertText(text, at); });
    connect(m_canvas, &Canvas::regionClicked, m_regionsDock, &RegionsDock::selectRegion);
    connect(m_regionsDock, &RegionsDock::selectedRegionChanged, m_canvas, &Canvas::setSelectedRegion);
    connect(m_regionsDock, &RegionsDock::refused, this, [this](const QString& reason) { statusBar()->showMessage(reason, 5000); });
}

// ---- Frames -------------------------------------------------------------------------------------------

void MainWindow::showFrame()
{
    const auto frame = m_simulation.frame();
    m_document.takeFrame(*frame);
    m_canvas->setFrame(frame);
    m_timeLabel->setText(tr("%1 s").arg(frame->time, 0, 'f', 2));
    m_verticesLabel->setText(tr("%L1 vertices").arg(qulonglong(frame->vertexCount)));
    m_stepsLabel->setText(frame->playing ? tr("%1 steps/s").arg(frame->stepsPerSecond, 0, 'f', 1) : tr("paused"));
    m_backendLabel->setText(QString::fromStdString(frame->backend));
}

model::Drawing MainWindow::drawing() const
{
    static const std::vector<std::vector<sim::Polygon>> nothingYet;
    const auto frame = m_simulation.frame();
    return model::drawingOf(m_document.scene().canvas, m_document.regions(), frame ? frame->regions : nothingYet);
}

// ---- Import and export --------------------------------------------------------------------------------

// Twenty drops within `spread` of `center`, in the inks of the palette shown, each spatter's from a
// seed of its own.
void MainWindow::spatter(QPointF center, double spread)
{
    if (!m_document.canAddRegions()) {
        statusBar()->showMessage(tr("The scene's own drops are still landing; play on and spatter again"), 5000);
        return;
    }
    model::SpatterStroke brush;
    brush.center = toVec(center);
    brush.spread = spread;
    brush.smallest = 0.005 * m_document.scene().canvas.width;
    brush.largest = 0.02 * m_document.scene().canvas.width;
    brush.seed = m_spatterSeed++;
    brush.colors = m_paletteDock->inks();
    if (brush.colors.empty()) {
        statusBar()->showMessage(tr("The palette shown has no inks; add one to spatter"), 5000);
        return;
    }
    m_document.spatter(brush);
}

// A pattern in the inks of the palette shown, made at once as one step of the history.
void MainWindow::choosePattern()
{
    if (!m_document.canAddRegions()) {
        m_report(tr("Cannot make a pattern yet"), tr("The scene's own drops are still landing; play on and try again."));
        return;
    }
    m_pattern.colors = m_paletteDock->inks();
    if (m_pattern.colors.empty()) {
        m_report(tr("Cannot make a pattern"), tr("The palette shown has no inks; add one first."));
        return;
    }
    PatternDialog dialog(m_pattern, m_document.scene().canvas, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    m_pattern = dialog.pattern();
    m_document.applyPattern(m_pattern);
    ++m_pattern.seed;  // the next one's drops fall elsewhere
}

// Target-driven design: the fluid draws the ink into the chosen target while the simulation plays,
// one step of the history.
void MainWindow::chooseGather()
{
    if (m_document.settings().flow.type != model::FlowSpec::Type::Fluid) {
        m_report(tr("Cannot gather"), tr("Gathering drives the fluid; this scene's flow is prescribed."));
        return;
    }
    std::vector<RegionOutline> regions;
    for (const model::DrawnRegion& r : drawing().regions)
        regions.push_back({r.name, r.contours});
    GatherDialog dialog(m_document.scene().canvas, std::move(regions), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const GatherChoice& choice = dialog.choice();
    const model::FlowSpec& flow = m_document.settings().flow;
    const model::Canvas& canvas = m_document.scene().canvas;
    try {
        const auto drive = std::make_shared<const sim::TargetDrive>(
            choice.target, sim::FluidSettings{flow.gridX, flow.gridY, canvas.width, canvas.height}, choice.drive);
        m_document.gather(tr("Gather into %1").arg(choice.name), drive, choice.duration);
        m_playAction->setChecked(true);
    } catch (const std::invalid_argument& e) {
        m_report(tr("Cannot gather"), QString::fromUtf8(e.what()));
    }
}

void MainWindow::chooseImport()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Import SVG"), m_recentFiles->folder(), tr("SVG files (*.svg)"));
    if (!path.isEmpty())
        importSvg(path);
}

bool MainWindow::importSvg(const QString& path)
{
    if (!m_document.canAddRegions()) {
        m_report(tr("Cannot import yet"), tr("The scene's own drops are still landing; play on and import again."));
        return false;
    }
    const model::Scene& scene = m_document.scene();
    model::SvgImport imported;
    std::vector<model::NewRegion> regions;
    // The importer reports its own errors as a line; anything else it or the copy throws (memory)
    // must not take the user's document down with it. Nothing is added before this succeeds.
    try {
        imported = model::importSvgFile(path, scene.canvas.width, scene.canvas.height, m_document.settings().tracking.maxSpacing);
        for (const model::ImportedShape& shape : imported.shapes)
            regions.push_back({shape.name, shape.color, shape.contours});
    } catch (const std::exception& e) {
        imported.error = tr("%1: cannot import: %2").arg(QFileInfo(path).fileName(), QString::fromLocal8Bit(e.what()));
    }
    if (!imported.ok()) {
        m_report(tr("Cannot import SVG"), imported.error);
        return false;
    }
    m_document.addRegions(tr("Import %1").arg(QFileInfo(path).fileName()), regions);
    if (!imported.warnings.isEmpty())
        statusBar()->showMessage(imported.warnings.join(QStringLiteral("; ")), 10000);
    return true;
}

std::vector<sim::Polygon> MainWindow::textOutlines(const QString& text, QPointF baselineStart) const
{
    return model::textContours(text, m_textOptions->font(), toVec(baselineStart), m_textOptions->size(),
                               m_document.settings().tracking.maxSpacing);
}

// What the text being typed will become, shown on the canvas as it is typed.
void MainWindow::previewText()
{
    const TextEntry& entry = m_canvas->textEntry();
    if (!entry.isActive())
        return;
    QPainterPath outlines;
    outlines.setFillRule(Qt::OddEvenFill);
    for (const sim::Polygon& contour : textOutlines(entry.text(), entry.baselineStart())) {
        QPolygonF polygon;
        for (const sim::Vec2& p : contour)
            polygon << QPointF(p.x, p.y);
        outlines.addPolygon(polygon);
        outlines.closeSubpath();
    }
    m_canvas->setTextPreview(outlines, m_textOptions->size(), m_inkColor);
}

void MainWindow::insertText(const QString& text, QPointF baselineStart)
{
    if (text.trimmed().isEmpty())
        return;
    if (!m_document.canAddRegions()) {
        statusBar()->showMessage(tr("The scene's own drops are still landing; play on and try again"), 5000);
        return;
    }
    auto contours = textOutlines(text, baselineStart);
    if (contours.empty())
        return;
    m_document.addRegions(tr("Text “%1”").arg(text), {{text, m_inkColor, std::move(contours)}});
}

void MainWindow::exportPicture()
{
    ExportDialog dialog(drawing(), this);
    if (dialog.exec() == QDialog::Accepted)
        statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(dialog.filePath())), 10000);
}

// A draft of the document (its scene and history, copied): the dialog plays either in a
// simulation of its own.
void MainWindow::exportAnimation()
{
    AnimationDialog dialog(m_document.scene(), m_document.draftProject(), this);
    dialog.exec();
    if (!dialog.writtenPath().isEmpty())
        statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(dialog.writtenPath())), 10000);
}

void MainWindow::copySvg()
{
    const QString error = copyAsSvg(drawing());
    if (!error.isEmpty())
        m_report(tr("Cannot copy"), error);
    else
        statusBar()->showMessage(tr("Copied the picture as SVG"), 3000);
}

void MainWindow::setHistoryBudgetMb(int megabytes)
{
    m_document.setHistoryBudget(std::size_t(std::max(16, megabytes)) << 20);
    QSettings().setValue(historyBudgetKey, std::max(16, megabytes));
}

// ---- Regions dock -------------------------------------------------------------------------------------

void MainWindow::setInkColor(const QColor& color)
{
    m_inkColor = color;
    m_paletteDock->setInkColour(color);
    if (auto* button = findChild<QPushButton*>(QStringLiteral("inkColor"))) {
        QPixmap swatch(16, 16);
        swatch.fill(color);
        button->setIcon(QIcon(swatch));
    }
    previewText();
}

} // namespace vf::app
