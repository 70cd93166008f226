#pragma once
// Text typed in place on the canvas (the Text tool): where its baseline starts and what has been
// typed so far. The canvas hands it the key presses; it says what each one did.
#include <QPointF>
#include <QString>

class QKeyEvent;

namespace vf::app {

class TextEntry {
public:
    enum class Outcome { Ignored, Edited, Committed, Cancelled };

    bool isActive() const { return m_active; }
    QPointF baselineStart() const { return m_baselineStart; }
    const QString& text() const { return m_text; }

    void begin(QPointF baselineStart);
    void end();
    // Whether typing takes this key before any shortcut: text, Backspace, Enter and Esc, without
    // Ctrl, Alt or Meta (so that Ctrl+Z and the like still reach their actions).
    bool takes(const QKeyEvent& event) const;
    Outcome press(const QKeyEvent& event);

private:
    bool m_active = false;
    QPointF m_baselineStart;
    QString m_text;
};

} // namespace vf::app
