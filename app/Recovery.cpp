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
    // Background writes hold only immutable states, but they write into our folder: let them end.
    QThreadPool::globalInstance()->waitForDone();
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
    // Nothing here may hold up the GUI: the current state is taken on the worker and awaited by
    // polling; once it is in, every state the history refers to is too (requests run in order),
    // so putting the project together does not wait, and the slow part (encoding and writing the
    // immutable states) runs on a pool thread.
    auto now = std::make_shared<model::StateSlot>();
    m_document.port().snapshot(now);
    ++m_writing;
    auto* poll = new QTimer(this);
    poll->setInterval(20);
    connect(poll, &QTimer::timeout, this, [this, poll, now] {
        if (!now->state())
            return;
        poll->deleteLater();
        auto project = std::make_shared<model::Project>(m_document.project(now));
        QThreadPool::globalInstance()->start([this, project, path = filePath()] {
            const QString error = model::writeProjectFile(*project, path);
            QMetaObject::invokeMethod(this, [this, error] {
                --m_writing;
                emit saved(error);
            }, Qt::QueuedConnection);
        });
    });
    poll->start();
}

void Recovery::discard()
{
    QThreadPool::globalInstance()->waitForDone();
    if (m_lock)
        QFile::remove(filePath());
    m_crashed = false;
}

} // namespace vf::app
