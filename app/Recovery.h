#pragma once
// Autosave and crash recovery. While the document has unsaved changes, it is written every few
// seconds (a setting) as a project to a recovery file; a clean exit or a save removes the file.
// A session holds a lock beside it, so a file left without a live lock means the last session
// crashed, and the next start offers to recover it.
#include "model/Document.h"

#include <QLockFile>
#include <QObject>
#include <QTimer>

#include <memory>

namespace vf::app {

class Recovery final : public QObject {
    Q_OBJECT

public:
    // `directory` empty: the recovery folder in the app's data location (VF_RECOVERY_DIR
    // overrides it, for tests and portable installs).
    Recovery(model::Document& document, QString directory = {}, QObject* parent = nullptr);
    ~Recovery() override;

    // Whether the lock could be taken: without it another instance owns the folder and this one
    // neither autosaves nor recovers.
    bool isActive() const { return m_lock != nullptr; }
    QString filePath() const;
    // A recovery file left by a session that did not exit cleanly.
    bool hasCrashedSession() const { return m_crashed; }

    void setInterval(int seconds);
    int interval() const { return m_timer.interval() / 1000; }

    // Takes the current state and writes the recovery file in the background, without blocking;
    // saved(error) follows when the file is written.
    void saveNow();
    // Removes the recovery file (after a save, or on a clean exit).
    void discard();

signals:
    void saved(const QString& error);

private:
    model::Document& m_document;
    QString m_directory;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
    bool m_crashed = false;
    int m_writing = 0;     // background writes under way
    int m_generation = 0;  // discard() counts up: a write begun before it is stale
    int m_lastWriteGeneration = 0;
};

} // namespace vf::app
