#include "app/TextEntry.h"

#include <QKeyEvent>

namespace vf::app {

void TextEntry::begin(QPointF baselineStart)
{
    m_active = true;
    m_baselineStart = baselineStart;
    m_text.clear();
}

void TextEntry::end()
{
    m_active = false;
    m_text.clear();
}

bool TextEntry::takes(const QKeyEvent& event) const
{
    if (!m_active || (event.modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)))
        return false;
    switch (event.key()) {
    case Qt::Key_Backspace:
    case Qt::Key_Return:
    case Qt::Key_Enter:
    case Qt::Key_Escape:
        return true;
    default:
        return !event.text().isEmpty() && event.text().front().isPrint();
    }
}

TextEntry::Outcome TextEntry::press(const QKeyEvent& event)
{
    if (!takes(event))
        return Outcome::Ignored;
    switch (event.key()) {
    case Qt::Key_Backspace:
        m_text.chop(1);
        return Outcome::Edited;
    case Qt::Key_Return:
    case Qt::Key_Enter:
        return Outcome::Committed;
    case Qt::Key_Escape:
        return Outcome::Cancelled;
    default:
        m_text += event.text();
        return Outcome::Edited;
    }
}

} // namespace vf::app
