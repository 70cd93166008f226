#pragma once
// File ▸ Export Animation: a time range of the document's scene, played from its start in a
// simulation of its own (the reference backend) on a thread of its own, written through
// render::exportAnimation. The live simulation and the document are never touched: the dialog
// works on a copy of the scene. A progress bar shows the frames done; Cancel stops the export
// and nothing is written; when done, the dialog says the file's size.
#include "model/Scene.h"

#include <QDialog>

#include <atomic>
#include <thread>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace vf::app {

class AnimationDialog final : public QDialog {
    Q_OBJECT

public:
    explicit AnimationDialog(model::Scene scene, QWidget* parent = nullptr);
    ~AnimationDialog() override;  // cancels a running export and waits for its thread

    // The file the last export wrote; empty before one succeeded.
    QString writtenPath() const { return m_written; }
    bool running() const { return m_thread.joinable(); }

    // While an export runs, Escape and Cancel stop it; otherwise they close the dialog.
    void reject() override;

private:
    void browse();
    void start();
    void finished(const QString& error);
    void updateEnabled();

    model::Scene m_scene;
    std::thread m_thread;
    std::atomic<bool> m_cancel{false};
    QString m_written;

    QLineEdit* m_path = nullptr;
    QLabel* m_format = nullptr;
    QDoubleSpinBox* m_start = nullptr;
    QDoubleSpinBox* m_end = nullptr;
    QSpinBox* m_fps = nullptr;
    QSpinBox* m_width = nullptr;
    QCheckBox* m_transparent = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_result = nullptr;
    QPushButton* m_export = nullptr;
    QPushButton* m_close = nullptr;
};

} // namespace vf::app
