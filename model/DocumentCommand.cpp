#include "model/DocumentCommand.h"

#include "model/Document.h"

namespace vf::model {

DocumentCommand::DocumentCommand(Document& document, std::shared_ptr<CommandRecord> record, bool alreadyDone)
    : QUndoCommand(record->text)
    , m_document(document)
    , m_record(std::move(record))
    , m_skipRedo(alreadyDone)
{
}

void DocumentCommand::undo()
{
    if (m_record->isOpen())
        m_document.closeCommand(*m_record);
    m_document.applySide(*m_record, false);
}

void DocumentCommand::redo()
{
    if (m_skipRedo) {
        m_skipRedo = false;
        return;
    }
    m_document.applySide(*m_record, true);
}

} // namespace vf::model
