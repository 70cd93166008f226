#pragma once
// Tools ▸ Gather Into…: target-driven design (sim/TargetDrive.h). The target is text set in a font
// and fitted to the canvas, a region's present shape, or the shapes of an SVG file; the dialog
// outlines it in a preview as the choices change, says what gathering will do, and refuses a
// target without an outline (blank text, an SVG file that cannot be read) before anything is done.
#include "model/Scene.h"
#include "sim/TargetDrive.h"

#include <QDialog>
#include <QFont>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QFontComboBox;
class QFormLayout;
class QHBoxLayout;
class QLabel;
class QLineEdit;

namespace vf::app {

// A region as the dialog offers it: its name and its contours as they are now.
struct RegionOutline {
    QString name;
    std::vector<sim::Polygon> contours;
};

struct GatherChoice {
    QString name;  // of the target, for the history: "INK", a region's or a file's name
    std::vector<std::vector<sim::Polygon>> target;  // shapes, each filled even-odd
    double duration = 6.0;
    sim::TargetDriveSettings drive;
};

// `text` set in `font`, centred on the canvas and as large as fits in 84 % of its width and 60 % of
// its height; no contours for blank text.
std::vector<sim::Polygon> fittedText(const QString& text, const QFont& font, const model::Canvas& canvas);

class GatherDialog final : public QDialog {
    Q_OBJECT

public:
    GatherDialog(const model::Canvas& canvas, std::vector<RegionOutline> regions, QWidget* parent = nullptr);

    // What OK stands for (valid while OK is enabled).
    const GatherChoice& choice() const { return m_choice; }

private:
    void browse();
    void update();
    QString outlineTarget();  // fills m_choice's name and target; returns what is wrong, if anything

    model::Canvas m_canvas;
    std::vector<RegionOutline> m_regions;
    GatherChoice m_choice;
    QFormLayout* m_form;
    QComboBox* m_kind;
    QLineEdit* m_text;
    QFontComboBox* m_font;
    QCheckBox* m_bold;
    QLineEdit* m_file;
    QHBoxLayout* m_fileRow;
    QDoubleSpinBox *m_duration, *m_strength, *m_gathering;
    QLabel *m_preview, *m_summary;
    QDialogButtonBox* m_buttons;
};

} // namespace vf::app
