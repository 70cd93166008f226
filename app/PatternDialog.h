#pragma once
// Tools ▸ Pattern…: picks a traditional pattern and its few parameters. It says what the pattern
// will make on this canvas (how many drops, which passes) and refuses one the canvas cannot hold,
// in the dialog, before anything is done.
#include "model/Scene.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace vf::app {

class PatternDialog final : public QDialog {
    Q_OBJECT

public:
    // Starts from `pattern` (its colours are the inks it will use); `canvas` sizes the counts.
    PatternDialog(const model::PatternStroke& pattern, const model::Canvas& canvas, QWidget* parent = nullptr);

    model::PatternStroke pattern() const;

private:
    void updateSummary();

    model::PatternStroke m_start;
    model::Canvas m_canvas;
    QComboBox* m_kind;
    QDoubleSpinBox *m_dropRadius, *m_spacing, *m_fineSpacing, *m_shift, *m_sharpness;
    QSpinBox* m_seed;
    QLabel* m_summary;
    QDialogButtonBox* m_buttons;
};

} // namespace vf::app
