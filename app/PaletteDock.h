#pragma once
// The Palette dock: the current ink picked from a palette. The built-in palettes and any GIMP .gpl
// files loaded (remembered, and loaded again at the next start) are offered in a list; a click on a
// swatch makes its colour the ink; "Add ink" puts the current ink into the palette shown, and
// "Save…" writes that palette as a .gpl file (model/Palette.h).
#include "model/Palette.h"

#include <QDockWidget>

class QComboBox;
class QListWidget;

namespace vf::app {

class PaletteDock final : public QDockWidget {
    Q_OBJECT

public:
    explicit PaletteDock(QWidget* parent);

    const model::Palette& shown() const { return m_palettes[std::size_t(m_current)]; }
    // The colours of the palette shown, for the tools that draw inks from it (spatter, patterns).
    std::vector<QColor> inks() const;
    // The ink as it is now (from the tool bar or a swatch): what "Add ink" adds; a swatch of that
    // colour is marked.
    void setInkColour(const QColor& colour);
    // Reads a .gpl file and shows it; problem() says why when it cannot be read.
    void load(const QString& path);
    // The files loaded before (remembered in the settings) loaded again; a file that can no longer
    // be read is forgotten, and its one-line reason returned.
    QStringList loadRemembered();

signals:
    void colourPicked(const QColor& colour);
    void problem(const QString& title, const QString& line);  // one line, for a message box

private:
    void showPalette(int index);
    QString add(const QString& path);  // reads and shows; the one-line error, or empty
    void chooseFile();
    void saveShown();
    void addInk();
    void markInk();

    std::vector<model::Palette> m_palettes;
    int m_current = 0;
    QColor m_ink;
    QComboBox* m_choice;
    QListWidget* m_swatches;
};

} // namespace vf::app
