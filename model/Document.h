#pragma once
// The open piece of work: the scene it started from, the region looks, the engine settings and
// the undo history, over a live simulation it reaches only through a SimulationPort. Lives on the
// GUI thread; every user action is one command on its QUndoStack (docs/ARCHITECTURE.md, "Undo and the document").
#include "model/DocumentCommand.h"
#include "model/Frame.h"
#include "model/HistoryReplay.h"
#include "model/Project.h"
#include "model/SceneScript.h"
#include "model/SimulationPort.h"

#include <QObject>
#include <QUndoStack>

#include <functional>
#include <optional>

namespace vf::model {

struct NewRegion {
    QString name;
    QColor color;
    std::vector<sim::Polygon> contours;
};

// Everything a project file needs, taken at one moment: values and state slots, so that it can be
// finished on any thread (the slots awaited) while the document moves on.
class ProjectDraft {
public:
    // Waits for the states the worker is still taking, then puts the project together.
    Project finish() const;
    // The line of work from the document's opening to now through its done commands, as spans to
    // play again (model/HistoryReplay.h), oldest first: each command's, and the flow between them
    // where no command was open. Waits like finish(). Commands whose span the journal does not hold
    // (those read from a project file) are left out and counted in `unrecorded` (when given).
    std::vector<ReplaySpan> replaySpans(int* unrecorded = nullptr) const;
    const Scene& scene() const { return m_scene; }

private:
    friend class Document;
    Scene m_scene;
    RegionTable m_regions;
    EngineSettings m_settings;
    StateSlotPtr m_origin;  // the state the document was opened at
    std::int64_t m_steps = 0;
    double m_time = 0.0;  // simulated seconds: of the newest frame, or of the state last restored
    std::vector<CommandRecord> m_records;  // the newest, if still open, ends at m_now
    int m_index = 0;
    StateSlotPtr m_now;
};

class Document final : public QObject {
    Q_OBJECT

public:
    // Default budget for the simulation states the history keeps (see setHistoryBudget).
    static constexpr std::size_t defaultHistoryBudget = std::size_t(512) << 20;

    explicit Document(SimulationPort& port, QObject* parent = nullptr);
    ~Document() override;

    // Opening replaces the whole document and its history.
    void openScene(const Scene& scene, const QString& backend, int device = -1);
    void openProject(const Project& project, const QString& backend, int device = -1);
    // The document as it is now, for a project file: requests the current state and returns at
    // once; ProjectDraft::finish() waits for it.
    ProjectDraft draftProject();

    const Scene& scene() const { return m_scene; }
    const RegionTable& regions() const { return m_regions; }
    const EngineSettings& settings() const { return m_settings; }
    QUndoStack& undoStack() { return m_undo; }
    SimulationPort& port() { return m_port; }

    QString filePath() const { return m_filePath; }
    void setFilePath(const QString& path);
    bool isModified() const { return !m_undo.isClean(); }
    // Counts every move of the history (push, undo, redo, trimming): equal revisions mean the
    // same commands are done, which an index alone cannot tell after undo and a new command.
    std::uint64_t revision() const { return m_revision; }

    // False while drops of the scene's own script are still to land: a region added (or deleted)
    // then would take (or free) a simulation index that one of them is due to have.
    bool canAddRegions() const;
    // `base`, or `base` with a number appended, that no region has yet.
    QString unusedName(const QString& base) const;

    // ---- Actions: each is one undoable command. ---------------------------------------------
    void drop(sim::Vec2 center, double radius, const QColor& color);
    // A pattern's drops and passes as one command, its passes exact whatever its mode says: all of
    // it acts at once (model/Patterns.h).
    void applyPattern(const PatternStroke& pattern);
    // A spatter's drops as one command, landing one after another at once.
    void spatter(const SpatterStroke& brush);
    // Drops (each a region named and coloured as the Drop tool's) and exact combs, circular combs
    // and swirls, in order, as one command called `text`. Refused, like a drop, while the scene's own drops are landing
    // if there is a drop among them.
    void applyTools(const QString& text, const std::vector<Stroke>& tools);
    // A stroke of pens through the water, live: one command called `text` ("Stylus stroke" when
    // empty) for all the pens' moves until the next command.
    void beginStroke(const QString& text = {});
    void stroke(const std::vector<sim::StylusSegment>& pens);
    void addRegions(const QString& commandText, const std::vector<NewRegion>& regions);
    // Target-driven design as one command called `text`: the fluid draws the ink into the drive's
    // target for `duration` seconds of the steps to come (SimulationPort::gather); the command
    // holds all they do until the next command, as a stroke does.
    void gather(const QString& text, const std::shared_ptr<const sim::TargetDrive>& drive, double duration);
    // `control` names what changed them (a widget of the settings panel): changes by one control
    // while the command it began is still the open top of the history join that command, so that
    // holding a spin box's arrow down is one undo step. Empty: always a command of its own.
    void setSettings(const EngineSettings& settings, const QString& control = {});
    void reset();  // back to the scene's starting picture

    // Index into regions() (paint order). Each returns false, changing nothing, when the edit is
    // invalid (out of range, an empty or taken name) or changes nothing.
    bool setRegionColor(int index, const QColor& color);
    bool setRegionName(int index, const QString& name);
    bool setRegionVisible(int index, bool visible);
    bool moveRegion(int from, int to);
    // Takes the region and its ink out of the simulation (the regions above it in the simulation
    // move down one index). Refused, like adding, while the scene's own drops are still to land.
    bool deleteRegion(int index);
    // A new region of `contours` (the region's ink as it is, moved where the copy should be) with
    // the region's looks and a name of its own, just above it.
    bool duplicateRegion(int index, const std::vector<sim::Polygon>& contours);

    // ---- From the worker. --------------------------------------------------------------------
    // Regions the scene's script has landed since get their looks here.
    void takeFrame(const Frame& frame);

    // ---- History memory. ----------------------------------------------------------------------
    // The history keeps the simulation states of its commands (about 41 bytes per vertex each).
    // Past the budget, the oldest commands are dropped from the history (never corrupted): they
    // can no longer be undone. At least the newest command is always kept.
    void setHistoryBudget(std::size_t bytes);
    std::size_t historyBudget() const { return m_historyBudget; }
    // Bytes of the distinct states taken so far by commands [first, count).
    std::size_t historyBytes(int first = 0) const;

    // Used by DocumentCommand.
    void applySide(const CommandRecord& record, bool after);
    void closeCommand(CommandRecord& record);

signals:
    void regionsAboutToBeReset();
    void regionsReset();
    // One region moved in the paint order, from index `from` to index `to` (indices before the move).
    void regionAboutToMove(int from, int to);
    void regionMoved();
    void regionChanged(int index);
    void settingsChanged(const vf::model::EngineSettings& settings);
    void historyTrimmed(int commands);
    void filePathChanged(const QString& path);

private:
    // `origin`: where a replay of the history starts; without one, the state once loaded.
    void open(const Scene& scene, const EngineSettings& settings, const RegionTable& regions, const StateSlotPtr& start,
              const StateSlotPtr& origin = nullptr);
    // The state now, closing the open command if there is one (its end is this state).
    StateSlotPtr stateNow();
    // Returns the record of the command pushed.
    std::shared_ptr<const CommandRecord> pushSimulationCommand(const QString& text,
                                                               const std::function<void()>& action);
    void pushRegionsCommand(const QString& text, RegionTable after);
    void replaceRegions(const RegionTable& regions);
    void applySettings(const EngineSettings& settings);
    void enforceHistoryBudget();
    void rebuildHistory(std::vector<std::shared_ptr<CommandRecord>> records, int index, std::optional<int> cleanIndex);
    CommandRecord* openCommand();

    SimulationPort& m_port;
    QUndoStack m_undo;
    Scene m_scene;
    std::optional<SceneScript> m_script;
    RegionTable m_regions;
    EngineSettings m_settings;
    QString m_filePath;
    // Steps taken: those of the project it was opened from and those the worker counts since.
    std::int64_t m_stepsBefore = 0;
    std::int64_t m_steps = 0;
    double m_time = 0.0;  // simulated seconds: of the newest frame, or of the state last restored
    std::uint64_t m_revision = 0;
    std::uint64_t m_restoreSerial = 0;  // frames older than the last restore or load are stale
    StateSlotPtr m_origin;              // the state at the opening, where a replay of the history starts
    std::size_t m_historyBudget = defaultHistoryBudget;
    bool m_rebuilding = false;          // rebuildHistory() replays commands without applying them
    std::weak_ptr<const CommandRecord> m_stroke;  // the last stroke begun; it takes the pen while its command is open
    std::weak_ptr<const CommandRecord> m_settingsCommand;  // the last settings change, by m_settingsControl
    QString m_settingsControl;
};

EngineSettings engineSettingsOf(const Scene& scene, const QString& backend, int device);

} // namespace vf::model
