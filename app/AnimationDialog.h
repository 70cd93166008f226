#pragma once
// File ▸ Export Animation: a time range of the document's scene played from its start, or of its
// history played again as it was made (model/HistoryReplay.h), in a simulation of its own (the
// reference backend) on a thread of its own, written through render::exportAnimation. The live
// simulation and the document are never touched: the dialog works on a copy of the scene and on a
// draft of the history (immutable states). A progress bar shows the frames done; Cancel stops the
// export and nothing is written; when done, the dialog says the file's size.
#include "model/Document.h"

#include <QDialog>

#include <atomic>
#include <optional>
#include <thread>

class QCheckBox;
class QComboBox;
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
    // `history`: a draft of the document whose history can be played; without one, only the scene.
    explicit AnimationDialog(model::Scene scene, std::optional<model::ProjectDraft> history = {},
                             QWidget* parent = nullptr);
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
    // Scene or history: the note and the range's end follow.
    void sourceChanged();

    model::Scene m_scene;
    std::optional<model::ProjectDraft> m_history;
    // The history's spans, once asked for (the first time it is chosen); the commands left out.
    std::optional<std::vector<model::ReplaySpan>> m_spans;
    int m_unrecorded = 0;
    std::thread m_thread;
    std::atomic<bool> m_cancel{false};
    QString m_written;

    QComboBox* m_source = nullptr;
    QLabel* m_note = nullptr;
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
