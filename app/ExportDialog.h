#pragma once
// File > Export: writes the current picture through render::exportDrawing, with the page size
// (the canvas's proportions, or any other with the canvas centred), resolution, background and
// curve options, remembered between sessions.
#include "model/Drawing.h"
#include "render/Exporter.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace vf::app {

class ExportDialog final : public QDialog {
    Q_OBJECT

public:
    explicit ExportDialog(model::Drawing drawing, QWidget* parent = nullptr);

    QString filePath() const;
    render::ExportOptions options() const;
    // Why the last export failed; empty after a success or before any attempt.
    QString lastError() const { return m_lastError; }

private:
    void browse();
    void exportFile();
    QString checkPngMemory() const;
    void showError();
    void formatPicked();
    void pathEdited();
    void pageWidthEdited();
    void pageHeightEdited();
    void keepAspectToggled(bool keep);
    void followCanvasAspect();
    void unitPicked();
    void dpiEdited();
    void showPageSize();
    void updateEnabled();
    double pointsPerUnit() const;
    void restoreSettings();
    void saveSettings() const;

    model::Drawing m_drawing;
    double m_pageWidth = render::ExportOptions{}.pageWidth;  // points; what the spin box shows in its unit
    double m_pageHeight = m_pageWidth;                        // points; likewise
    QString m_lastError;

    QLineEdit* m_path = nullptr;
    QComboBox* m_format = nullptr;
    QDoubleSpinBox* m_pageWidthBox = nullptr;
    QComboBox* m_unit = nullptr;
    QDoubleSpinBox* m_pageHeightBox = nullptr;
    QCheckBox* m_keepAspect = nullptr;
    QSpinBox* m_dpi = nullptr;
    QCheckBox* m_background = nullptr;
    QComboBox* m_curves = nullptr;
};

} // namespace vf::app
