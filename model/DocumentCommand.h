#pragma once
// The one undo command of the document. Every user action is one: a drop, a stroke, a text or SVG
// insertion, a region deleted or duplicated, a settings change, a reset (these act on the
// simulation) or a recolour, rename,
// visibility change or reorder (these only change region looks). A command is its record: the
// region table, settings and simulation state at its start and at its end.
#include "model/EngineSettings.h"
#include "model/Regions.h"
#include "model/StateSlot.h"

#include <QUndoCommand>

#include <memory>

namespace vf::model {

class Document;

struct CommandRecord {
    QString text;
    RegionTable regionsBefore, regionsAfter;
    EngineSettings settingsBefore, settingsAfter;
    // Null for a command that leaves the simulation alone. `after` stays null until the command
    // ends: when the next command starts or when it is undone (a command covers the flow
    // it caused until the next one starts).
    StateSlotPtr before, after;

    bool touchesSimulation() const { return before != nullptr; }
    bool isOpen() const { return before && !after; }
};

class DocumentCommand final : public QUndoCommand {
public:
    // `alreadyDone`: the action already happened live (the first redo() that push() calls is
    // then skipped), as for everything done on the simulation.
    DocumentCommand(Document& document, std::shared_ptr<CommandRecord> record, bool alreadyDone);

    void undo() override;
    void redo() override;

    const std::shared_ptr<CommandRecord>& record() const { return m_record; }

private:
    Document& m_document;
    std::shared_ptr<CommandRecord> m_record;
    bool m_skipRedo;
};

} // namespace vf::model
