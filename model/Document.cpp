// The document (model/Document.h): opening and drafting, the regions, the commands, the history's
// memory. About 600 lines, kept as one because every part works on the same undo stack and command
// records; its sections below are the seams to split along should one part grow. What a draft
// does once taken (a project, the spans of a replay) is in ProjectDraft.cpp.
#include "model/Document.h"

#include "model/Patterns.h"

#include <QSet>

#include <algorithm>
#include <map>
#include <optional>
#include <unordered_set>

namespace vf::model {

namespace {

// `base`, or `base` with a number appended, that no region of `table` has.
QString unusedNameIn(const RegionTable& table, const QString& base)
{
    QSet<QString> taken;
    for (const RegionLook& r : table)
        taken.insert(r.name);
    if (!taken.contains(base))
        return base;
    for (int n = 2;; ++n)
        if (const QString name = QStringLiteral("%1 %2").arg(base).arg(n); !taken.contains(name))
            return name;
}

// The name of a new drop (or other numbered ink): `base` in an empty table, else "base N" past
// the highest N any region has, so drops added to a scene's "drop 1" … "drop 36" go on at "drop 37".
QString nextNumberedName(const RegionTable& table, const QString& base)
{
    const QString prefix = base + u' ';
    int highest = 0;
    bool taken = false;
    for (const RegionLook& r : table) {
        taken = taken || r.name == base;
        bool number = false;
        const int n = r.name.startsWith(prefix) ? r.name.mid(prefix.size()).toInt(&number) : 0;
        if (number && n > 0)
            highest = std::max(highest, n);
    }
    if (!taken && highest == 0)
        return base;
    return QStringLiteral("%1 %2").arg(base).arg(std::max(highest, 1) + 1);
}

const std::shared_ptr<CommandRecord>& recordAt(const QUndoStack& stack, int i)
{
    return static_cast<const DocumentCommand*>(stack.command(i))->record();
}

} // namespace

EngineSettings engineSettingsOf(const Scene& scene, const QString& backend, int device)
{
    return {scene.flow, scene.tracking, backend, device};
}

Document::Document(SimulationPort& port, QObject* parent)
    : QObject(parent)
    , m_port(port)
{
    connect(&m_undo, &QUndoStack::indexChanged, this, [this] { ++m_revision; });
}

Document::~Document()
{
    // The commands call back into this document while the stack deletes them.
    m_rebuilding = true;
    m_undo.clear();
}

void Document::setFilePath(const QString& path)
{
    if (path == m_filePath)
        return;
    m_filePath = path;
    emit filePathChanged(path);
}

// ---- Opening and saving --------------------------------------------------------------------------

void Document::open(const Scene& scene, const EngineSettings& settings, const RegionTable& regions, const StateSlotPtr& start,
                    const StateSlotPtr& origin)
{
    m_rebuilding = true;
    m_undo.clear();
    m_rebuilding = false;
    m_scene = scene;
    m_script.emplace(m_scene);
    m_stepsBefore = m_steps = 0;
    m_time = start ? start->state()->time : 0.0;
    m_port.load(m_scene, settings, start);
    m_origin = origin;
    if (!m_origin) {
        m_origin = std::make_shared<StateSlot>();
        m_port.snapshot(m_origin);
    }
    m_restoreSerial = m_port.requestCount();
    applySettings(settings);
    emit regionsAboutToBeReset();
    m_regions = regions;
    emit regionsReset();
}

void Document::openScene(const Scene& scene, const QString& backend, int device)
{
    const SceneScript script(scene);
    const RegionTable starting(script.looks().begin(), script.looks().begin() + script.startingRegionCount());
    open(scene, engineSettingsOf(scene, backend, device), starting, nullptr);
    setFilePath({});
}

void Document::openProject(const Project& project, const QString& backend, int device)
{
    // One slot per distinct state, so states the file shares stay shared; each with its mark in
    // the journal the file holds, so the history plays again across the opening.
    std::map<const sim::SimulationState*, StateSlotPtr> slotOfState;
    auto slotFor = [&slotOfState](const StatePtr& state, const JournalMark& mark) -> StateSlotPtr {
        if (!state)
            return nullptr;
        StateSlotPtr& slot = slotOfState[state.get()];
        if (!slot)
            slot = std::make_shared<StateSlot>(state, mark);
        return slot;
    };
    open(project.scene, engineSettingsOf(project.scene, backend, device), project.regions,
         std::make_shared<StateSlot>(std::make_shared<const sim::SimulationState>(project.state), project.stateMark),
         slotFor(project.origin, project.originMark));
    m_stepsBefore = m_steps = project.steps;

    std::vector<std::shared_ptr<CommandRecord>> records;
    for (const HistoryEntry& e : project.history) {
        auto r = std::make_shared<CommandRecord>();
        r->text = e.text;
        r->regionsBefore = e.regionsBefore;
        r->regionsAfter = e.regionsAfter;
        r->settingsBefore = {e.flowBefore, e.trackingBefore, backend, device};
        r->settingsAfter = {e.flowAfter, e.trackingAfter, backend, device};
        r->before = slotFor(e.before, e.beforeMark);
        r->after = slotFor(e.after, e.afterMark);
        records.push_back(std::move(r));
    }
    rebuildHistory(std::move(records), project.historyIndex, project.historyIndex);
}

ProjectDraft Document::draftProject()
{
    ProjectDraft draft;
    draft.m_now = std::make_shared<StateSlot>();
    m_port.snapshot(draft.m_now);
    draft.m_scene = m_scene;
    draft.m_scene.flow = m_settings.flow;
    draft.m_scene.tracking = m_settings.tracking;
    draft.m_regions = m_regions;
    draft.m_settings = m_settings;
    draft.m_origin = m_origin;
    draft.m_steps = m_steps;
    draft.m_index = m_undo.index();
    for (int i = 0; i < m_undo.count(); ++i) {
        CommandRecord r = *recordAt(m_undo, i);
        if (r.isOpen()) {  // the newest command, still running, ends now
            r.after = draft.m_now;
            r.regionsAfter = m_regions;
            r.settingsAfter = m_settings;
        }
        draft.m_records.push_back(std::move(r));
    }
    return draft;
}

// ---- Regions ----------------------------------------------------------------------------------------

// By time, not by counting regions: a deleted region leaves fewer rows than the script has looks.
bool Document::canAddRegions() const
{
    return m_script && m_time >= m_script->lastDropTime();
}

QString Document::unusedName(const QString& base) const
{
    return unusedNameIn(m_regions, base);
}

namespace {

bool sameRegions(RegionTable::const_iterator first, RegionTable::const_iterator last,
                 RegionTable::const_iterator other)
{
    return std::equal(first, last, other,
                      [](const RegionLook& a, const RegionLook& b) { return a.simIndex == b.simIndex; });
}

// Where `after` holds the regions of `before` with one of them moved: its index before and after.
std::optional<std::pair<int, int>> singleMove(const RegionTable& before, const RegionTable& after)
{
    if (before.size() != after.size())
        return std::nullopt;
    const auto differs = [&](std::size_t i) { return before[i].simIndex != after[i].simIndex; };
    std::size_t first = 0, last = before.size();
    while (first < last && !differs(first))
        ++first;
    while (last > first && !differs(last - 1))
        --last;
    if (last - first < 2)
        return std::nullopt;
    const auto b = before.begin(), a = after.begin();
    const int down = int(first), up = int(last - 1);
    if (before[first].simIndex == after[last - 1].simIndex && sameRegions(b + down + 1, b + up + 1, a + down))
        return std::pair{down, up};
    if (before[last - 1].simIndex == after[first].simIndex && sameRegions(b + down, b + up, a + down + 1))
        return std::pair{up, down};
    return std::nullopt;
}

} // namespace

void Document::replaceRegions(const RegionTable& regions)
{
    if (const auto move = singleMove(m_regions, regions)) {
        // Views keep their selection through a move, which a reset would clear.
        const auto [from, to] = *move;
        emit regionAboutToMove(from, to);
        const RegionLook moved = m_regions[std::size_t(from)];
        m_regions.erase(m_regions.begin() + from);
        m_regions.insert(m_regions.begin() + to, moved);
        emit regionMoved();
    }
    if (regions.size() != m_regions.size() || !sameRegions(regions.begin(), regions.end(), m_regions.begin())) {
        emit regionsAboutToBeReset();
        m_regions = regions;
        emit regionsReset();
        return;
    }
    for (std::size_t i = 0; i < regions.size(); ++i) {
        if (m_regions[i] == regions[i])
            continue;
        m_regions[i] = regions[i];
        emit regionChanged(int(i));
    }
}

void Document::takeFrame(const Frame& frame)
{
    // Only regions the scene's script has landed can appear unannounced; a frame from before the
    // last restore still shows the regions of the state that was replaced.
    if (frame.serial < m_restoreSerial)
        return;
    m_steps = m_stepsBefore + frame.steps;
    m_time = frame.time;
    if (!m_script || frame.regions.size() <= m_regions.size())
        return;
    RegionTable grown = m_regions;
    while (grown.size() < frame.regions.size() && grown.size() < m_script->looks().size()) {
        RegionLook look = m_script->looks()[grown.size()];
        look.simIndex = int(grown.size());
        look.name = unusedNameIn(grown, look.name);  // a user rename may have taken it
        grown.push_back(look);
    }
    replaceRegions(grown);
}

// ---- Commands ------------------------------------------------------------------------------------

CommandRecord* Document::openCommand()
{
    if (m_undo.index() == 0)
        return nullptr;
    CommandRecord* top = recordAt(m_undo, m_undo.index() - 1).get();
    return top->isOpen() ? top : nullptr;
}

void Document::closeCommand(CommandRecord& record)
{
    if (m_rebuilding)  // rebuildHistory() moves through the commands without acting
        return;
    record.after = std::make_shared<StateSlot>();
    m_port.snapshot(record.after);
    record.regionsAfter = m_regions;
    record.settingsAfter = m_settings;
}

StateSlotPtr Document::stateNow()
{
    if (CommandRecord* open = openCommand()) {
        closeCommand(*open);
        return open->after;
    }
    auto slot = std::make_shared<StateSlot>();
    m_port.snapshot(slot);
    return slot;
}

std::shared_ptr<const CommandRecord> Document::pushSimulationCommand(const QString& text,
                                                                   const std::function<void()>& action)
{
    auto record = std::make_shared<CommandRecord>();
    record->text = text;
    record->before = stateNow();
    record->regionsBefore = m_regions;
    record->settingsBefore = m_settings;
    action();
    m_undo.push(new DocumentCommand(*this, record, true));
    enforceHistoryBudget();
    return record;
}

void Document::pushRegionsCommand(const QString& text, RegionTable after)
{
    if (CommandRecord* open = openCommand())
        closeCommand(*open);
    auto record = std::make_shared<CommandRecord>();
    record->text = text;
    record->regionsBefore = m_regions;
    record->regionsAfter = std::move(after);
    record->settingsBefore = record->settingsAfter = m_settings;
    m_undo.push(new DocumentCommand(*this, std::move(record), false));
    enforceHistoryBudget();
}

void Document::applySide(const CommandRecord& record, bool after)
{
    if (m_rebuilding)
        return;
    const RegionTable& table = after ? record.regionsAfter : record.regionsBefore;
    if (!record.touchesSimulation()) {
        // The simulation stays as it is, with any regions its scene has landed since the look
        // edit: they keep their rows.
        RegionTable kept = table;
        for (const RegionLook& r : m_regions)
            if (r.simIndex >= int(table.size()))
                kept.push_back(r);
        replaceRegions(kept);
        return;
    }
    const EngineSettings& settings = after ? record.settingsAfter : record.settingsBefore;
    if (settings != m_settings)
        m_port.configure(settings);
    const StateSlotPtr& state = after ? record.after : record.before;
    m_port.restore(state);
    m_restoreSerial = m_port.requestCount();
    if (const StatePtr restored = state->state())  // else the next frame tells
        m_time = restored->time;
    applySettings(settings);
    replaceRegions(table);
}

void Document::applySettings(const EngineSettings& settings)
{
    if (settings == m_settings)
        return;
    m_settings = settings;
    emit settingsChanged(m_settings);
}

void Document::drop(sim::Vec2 center, double radius, const QColor& color)
{
    if (!canAddRegions())
        return;
    pushSimulationCommand(tr("Drop"), [&] {
        m_port.drop(center, radius);
        RegionTable regions = m_regions;
        regions.push_back({nextNumberedName(m_regions, tr("drop")), color, true, int(m_regions.size())});
        replaceRegions(regions);
    });
}

void Document::applyPattern(const PatternStroke& pattern)
{
    if (pattern.colors.empty() || patternProblem(pattern, m_scene.canvas))
        return;
    PatternStroke exact = pattern;
    exact.mode = CombStroke::Mode::Exact;
    applyTools(tr("Pattern: %1").arg(patternName(pattern.kind)), patternStrokes(exact, m_scene.canvas));
}

void Document::spatter(const SpatterStroke& brush)
{
    if (brush.colors.empty())
        return;
    const std::vector<DropStroke> drops = brush.drops();
    applyTools(tr("Spatter"), std::vector<Stroke>(drops.begin(), drops.end()));
}

void Document::applyTools(const QString& text, const std::vector<Stroke>& tools)
{
    const bool drops = std::any_of(tools.begin(), tools.end(), [](const Stroke& s) { return std::holds_alternative<DropStroke>(s); });
    if (drops && !canAddRegions())
        return;
    pushSimulationCommand(text, [&] {
        RegionTable regions = m_regions;
        for (const Stroke& tool : tools) {
            if (const auto* drop = std::get_if<DropStroke>(&tool)) {
                m_port.drop(drop->center, drop->radius);
                regions.push_back({nextNumberedName(regions, tr("drop")), drop->color, true, int(regions.size())});
            } else if (const auto* comb = std::get_if<CombStroke>(&tool)) {
                m_port.applyMap(comb->map());
            } else if (const auto* circular = std::get_if<CircularCombStroke>(&tool)) {
                m_port.applyMap(circular->map());
            } else {
                m_port.applyMap(std::get<SwirlStroke>(tool).map());
            }
        }
        replaceRegions(regions);
    });
}

void Document::beginStroke(const QString& text)
{
    m_stroke = pushSimulationCommand(text.isEmpty() ? tr("Stylus stroke") : text, [] {});
}

void Document::stroke(const std::vector<sim::StylusSegment>& pens)
{
    // Only while the stroke's command is still the open one: after an undo in mid-stroke (or any
    // other command) the rest of the pen's path belongs to no command and is dropped.
    if (const auto stroke = m_stroke.lock(); stroke && openCommand() == stroke.get())
        m_port.stylus(pens);
}

void Document::gather(const QString& text, const std::shared_ptr<const sim::TargetDrive>& drive, double duration)
{
    pushSimulationCommand(text, [&] { m_port.gather(drive, duration); });
}

void Document::addRegions(const QString& commandText, const std::vector<NewRegion>& regions)
{
    if (!canAddRegions() || regions.empty())
        return;
    pushSimulationCommand(commandText, [&] {
        RegionTable table = m_regions;
        for (const NewRegion& r : regions) {
            m_port.addRegion(r.contours);
            table.push_back({unusedNameIn(table, r.name), r.color, true, int(table.size())});
        }
        replaceRegions(table);
    });
}

void Document::setSettings(const EngineSettings& settings, const QString& control)
{
    if (settings == m_settings)
        return;
    const auto apply = [&] {
        m_port.configure(settings);
        applySettings(settings);
    };
    const auto last = m_settingsCommand.lock();
    if (!control.isEmpty() && control == m_settingsControl && last && openCommand() == last.get()) {
        apply();  // the open command's end, taken when it closes, holds these settings
        return;
    }
    m_settingsCommand = pushSimulationCommand(tr("Simulation settings"), apply);
    m_settingsControl = control;
}

void Document::reset()
{
    pushSimulationCommand(tr("Reset"), [&] {
        m_stepsBefore = m_steps;  // the worker counts from zero again
        m_time = 0.0;
        m_port.load(m_scene, m_settings, nullptr);
        m_restoreSerial = m_port.requestCount();
        const RegionTable starting(m_script->looks().begin(), m_script->looks().begin() + m_script->startingRegionCount());
        replaceRegions(starting);
    });
}

bool Document::setRegionColor(int index, const QColor& color)
{
    if (index < 0 || index >= int(m_regions.size()) || !color.isValid() || m_regions[index].color == color)
        return false;
    RegionTable after = m_regions;
    after[index].color = color;
    pushRegionsCommand(tr("Recolour %1").arg(m_regions[index].name), std::move(after));
    return true;
}

bool Document::setRegionName(int index, const QString& name)
{
    const QString trimmed = name.trimmed();
    if (index < 0 || index >= int(m_regions.size()) || trimmed.isEmpty() || unusedName(trimmed) != trimmed)
        return false;
    RegionTable after = m_regions;
    after[index].name = trimmed;
    pushRegionsCommand(tr("Rename %1 to %2").arg(m_regions[index].name, trimmed), std::move(after));
    return true;
}

bool Document::setRegionVisible(int index, bool visible)
{
    if (index < 0 || index >= int(m_regions.size()) || m_regions[index].visible == visible)
        return false;
    RegionTable after = m_regions;
    after[index].visible = visible;
    pushRegionsCommand((visible ? tr("Show %1") : tr("Hide %1")).arg(m_regions[index].name), std::move(after));
    return true;
}

bool Document::moveRegion(int from, int to)
{
    const int n = int(m_regions.size());
    if (from < 0 || from >= n || to < 0 || to >= n || from == to)
        return false;
    RegionTable after = m_regions;
    const RegionLook moved = after[from];
    after.erase(after.begin() + from);
    after.insert(after.begin() + to, moved);
    pushRegionsCommand(tr("Reorder %1").arg(moved.name), std::move(after));
    return true;
}

bool Document::deleteRegion(int index)
{
    if (index < 0 || index >= int(m_regions.size()) || !canAddRegions())
        return false;
    const RegionLook gone = m_regions[std::size_t(index)];
    pushSimulationCommand(tr("Delete %1").arg(gone.name), [&] {
        m_port.removeRegion(gone.simIndex);
        m_restoreSerial = m_port.requestCount();  // older frames number the regions as before
        RegionTable table = m_regions;
        table.erase(table.begin() + index);
        for (RegionLook& look : table)
            if (look.simIndex > gone.simIndex)
                --look.simIndex;
        replaceRegions(table);
    });
    return true;
}

bool Document::duplicateRegion(int index, const std::vector<sim::Polygon>& contours)
{
    if (index < 0 || index >= int(m_regions.size()) || contours.empty() || !canAddRegions())
        return false;
    const RegionLook original = m_regions[std::size_t(index)];
    pushSimulationCommand(tr("Duplicate %1").arg(original.name), [&] {
        m_port.addRegion(contours);
        RegionTable table = m_regions;
        RegionLook copy = original;
        copy.name = unusedName(tr("%1 copy").arg(original.name));
        copy.simIndex = int(table.size());
        table.insert(table.begin() + index + 1, copy);
        replaceRegions(table);
    });
    return true;
}

// ---- History memory ------------------------------------------------------------------------------

std::size_t Document::historyBytes(int first) const
{
    std::unordered_set<const sim::SimulationState*> counted;
    std::size_t bytes = 0;
    for (int i = first; i < m_undo.count(); ++i) {
        const CommandRecord& r = *recordAt(m_undo, i);
        for (const StateSlotPtr& slot : {r.before, r.after})
            if (StatePtr state = slot ? slot->state() : nullptr; state && counted.insert(state.get()).second)
                bytes += state->bytes();
    }
    return bytes;
}

void Document::setHistoryBudget(std::size_t bytes)
{
    m_historyBudget = bytes;
    enforceHistoryBudget();
}

void Document::enforceHistoryBudget()
{
    // States count once taken; the newest are usually still being taken on the worker, so the
    // check runs a command behind, which a budget of hundreds of megabytes absorbs.
    // Commands not yet done (redoable) stay: the current state lies before them.
    int drop = 0;
    while (drop < m_undo.index() && drop + 1 < m_undo.count() && historyBytes(drop) > m_historyBudget)
        ++drop;
    if (drop == 0)
        return;
    std::vector<std::shared_ptr<CommandRecord>> records;
    for (int i = drop; i < m_undo.count(); ++i)
        records.push_back(recordAt(m_undo, i));
    const int clean = m_undo.cleanIndex();
    rebuildHistory(std::move(records), m_undo.index() - drop,
                   clean >= drop ? std::optional<int>(clean - drop) : std::nullopt);
    emit historyTrimmed(drop);
}

void Document::rebuildHistory(std::vector<std::shared_ptr<CommandRecord>> records, int index, std::optional<int> cleanIndex)
{
    // QUndoStack cannot drop its oldest commands, so the kept ones are pushed into the emptied
    // stack again, with nothing applied while it moves to their index.
    m_rebuilding = true;
    m_undo.clear();
    for (auto& r : records)
        m_undo.push(new DocumentCommand(*this, std::move(r), false));
    if (cleanIndex) {
        m_undo.setIndex(*cleanIndex);
        m_undo.setClean();
    } else {
        m_undo.resetClean();
    }
    m_undo.setIndex(index);
    m_rebuilding = false;
    ++m_revision;
}

} // namespace vf::model
