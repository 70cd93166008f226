#pragma once
// The Text tool's options: the typeface and the size of the letters in canvas units (the height of
// the em square). Shown while the Text tool is picked; the typeface is remembered across sessions.
#include <QFont>
#include <QToolBar>

class QDoubleSpinBox;
class QPushButton;

namespace vf::app {

class TextToolBar final : public QToolBar {
    Q_OBJECT

public:
    explicit TextToolBar(QWidget* parent = nullptr);

    QFont font() const { return m_font; }
    double size() const;

signals:
    void changed();  // the typeface or the size

private:
    void chooseFont();
    void setTextFont(const QFont& font);

    QFont m_font;
    QPushButton* m_fontButton;
    QDoubleSpinBox* m_size;
};

} // namespace vf::app
