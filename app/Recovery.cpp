#include "app/Recovery.h"

#include "model/ProjectFile.h"

#include <QDir>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QThreadPool>

namespace vf::app {

namespace {

QString defaultDirectory()
{
    const QString overridden = qEnvironmentVariable("VF_RECOVERY_DIR");
    if (!overridden.isEmpty())
        return overridden;
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + QStringLiteral("/recovery");
}

} // namespace

Recovery::Recovery(model::Document& document, QString directory, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_directory(directory.isEmpty() ? defaultDirectory() : std::move(directory))
{
    QDir().mkpath(m_directory);
    auto lock = std::make_unique<QLockFile>(m_directory + QStringLiteral("/session.lock"));
    // A lock whose process is gone is stale, and QLockFile takes it over.
    if (lock->tryLock(0)) {
        m_lock = std::move(lock);
        m_crashed = QFile::exists(filePath());
    }
    m_timer.setInterval(QSettings().value(QStringLiteral("recovery/intervalSeconds"), 30).toInt() * 1000);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        if (m_document.isModified())
            saveNow();
    });
    if (m_lock)
        m_timer.start();
}

Recovery::~Recovery()
{
    // A background write reports back to this object: let it end first. One begun before the last
    // discard() (a clean exit) has no callback left to remove it, so it goes here.
    QThreadPool::globalInstance()->waitForDone();
    if (m_writing > 0 && m_lastWriteGeneration != m_generation)
        QFile::remove(filePath());
}

QString Recovery::filePath() const
{
    return m_directory + QStringLiteral("/recovery.vfproj");
}

void Recovery::setInterval(int seconds)
{
    m_timer.setInterval(std::max(1, seconds) * 1000);
    QSettings().setValue(QStringLiteral("recovery/intervalSeconds"), std::max(1, seconds));
}

void Recovery::saveNow()
{
    if (!m_lock || m_writing > 0)
        return;
    // The draft is the document at this moment; finishing it waits for the states the worker is
    // still taking, so that and the writing run on a pool thread and the GUI never waits. A
    // discard() in the meantime makes the finished write stale: it is removed again.
    ++m_writing;
    const int generation = m_lastWriteGeneration = m_generation;
    QThreadPool::globalInstance()->start([this, draft = m_document.draftProject(), path = filePath(), generation] {
        const QString error = model::writeProjectFile(draft.finish(), path);
        QMetaObject::invokeMethod(this, [this, error, generation] {
            --m_writing;
            if (generation != m_generation)
                QFile::remove(filePath());
            else
                emit saved(error);
        }, Qt::QueuedConnection);
    });
}

void Recovery::discard()
{
    ++m_generation;
    if (m_lock)
        QFile::remove(filePath());
    m_crashed = false;
}

} // namespace vf::app
