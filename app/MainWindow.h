#pragma once
// The desktop app's main window: the canvas, the tool bar, the Regions / History / Simulation
// docks, the menus and the status bar, over one Document and its simulation worker
// (MainWindow.cpp; its file actions in MainWindowFiles.cpp).
#include "app/Canvas.h"
#include "app/RegionsDock.h"
#include "app/SimulationController.h"
#include "model/Document.h"
#include "model/Drawing.h"
#include "model/RegionListModel.h"

#include <QLabel>
#include <QListView>
#include <QMainWindow>
#include <QMessageBox>
#include <QThreadPool>
#include <QUndoView>

#include <functional>

namespace vf::app {

class PaletteDock;
class RecentFiles;
class Recovery;
class SimulationPanel;
class TextToolBar;

class MainWindow final : public QMainWindow {
    Q_OBJECT

public:
    // How the window asks the user a question or reports an error: message boxes by default;
    // tests put in answers so that nothing modal blocks them.
    using Ask = std::function<QMessageBox::StandardButton(const QString& title, const QString& text,
                                                          QMessageBox::StandardButtons buttons)>;
    using Report = std::function<void(const QString& title, const QString& text)>;

    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    void setAsk(Ask ask) { m_ask = std::move(ask); }
    void setReport(Report report) { m_report = std::move(report); }

    // Opens a scene (*.vfscene) or project (*.vfproj); on failure reports one line and keeps the
    // open document as it was.
    bool openFile(const QString& path);
    // Opens what a crashed session left in the recovery file, as unsaved work without a file.
    bool recover();
    // Writes the project and waits for it (File ▸ Save writes in the background instead).
    bool saveTo(const QString& path);
    void newDocument();
    bool importSvg(const QString& path);
    void insertText(const QString& text, QPointF baselineStart);

    model::Document& document() { return m_document; }
    SimulationController& simulation() { return m_simulation; }
    Canvas& canvas() { return *m_canvas; }
    model::RegionListModel& regionModel() { return m_regionModel; }
    QListView& regionView() { return m_regionsDock->view(); }
    Recovery& recovery() { return *m_recovery; }
    model::Drawing drawing() const;  // the picture as it is now, for export
    QColor inkColor() const { return m_inkColor; }
    void setInkColor(const QColor& color);
    // The undo history's memory budget (Edit ▸ History Memory; remembered), at least 16 MB.
    void setHistoryBudgetMb(int megabytes);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    bool load(const QString& path);
    void rememberBackend(const model::EngineSettings& settings);  // for the next new document
    void createActions();
    void createFileMenu();
    void createEditMenu();
    void createTools();
    void createSimulationMenu();
    void createViewMenu();
    void createDocks();
    void createStatusBar();
    void connectDocument();
    // The menu saves in the background; the prompt before closing or opening waits.
    enum class SaveMode { Wait, Background };
    bool maybeSave();
    bool save(SaveMode mode);
    bool saveAs(SaveMode mode);
    void saveInBackground(const QString& path);
    bool saved(const QString& path, int opened, std::uint64_t revision, const QString& error);
    void open();
    void exportPicture();
    void exportAnimation();
    void copySvg();
    void chooseImport();
    void choosePattern();
    void chooseGather();
    void spatter(QPointF center, double spread);
    std::vector<sim::Polygon> textOutlines(const QString& text, QPointF baselineStart) const;
    void previewText();
    void updateTitle();
    QString suggestedProjectPath() const;
    void showFrame();

    SimulationController m_simulation;
    model::Document m_document;
    model::RegionListModel m_regionModel;
    Canvas* m_canvas;
    RegionsDock* m_regionsDock = nullptr;
    QUndoView* m_historyView = nullptr;
    SimulationPanel* m_panel = nullptr;
    PaletteDock* m_paletteDock = nullptr;
    TextToolBar* m_textOptions = nullptr;
    model::PatternStroke m_pattern;  // the last one made (Tools ▸ Pattern… starts from it)
    std::uint64_t m_spatterSeed = 1;  // the next spatter's
    Recovery* m_recovery = nullptr;
    RecentFiles* m_recentFiles = nullptr;
    QAction* m_playAction = nullptr;
    QAction* m_marblingAction = nullptr;
    QAction* m_shapeDesignAction = nullptr;
    QLabel* m_timeLabel = nullptr;
    QLabel* m_verticesLabel = nullptr;
    QLabel* m_stepsLabel = nullptr;
    QLabel* m_fpsLabel = nullptr;
    QLabel* m_backendLabel = nullptr;
    QThreadPool m_saves;  // project saves, one at a time
    int m_opened = 0;  // counts documents opened, so a late save result finds its own
    QString m_sceneName;  // of the scene file the document was opened from; the title shows it
    QColor m_inkColor = QColor(0x1d, 0x35, 0x57);
    Ask m_ask;
    Report m_report;
};

} // namespace vf::app
