#include "app/RenderProgress.h"

#include <QString>

#include <cstdio>
#include <unistd.h>

namespace vf::app {

namespace {

// A run shorter than this shows nothing; a shown line changes at most this often.
constexpr std::chrono::seconds kQuietStart{3};
constexpr std::chrono::milliseconds kRefresh{500};

QString duration(double seconds)
{
    if (seconds < 90)
        return QStringLiteral("%1 s").arg(qRound(seconds));
    if (seconds < 90 * 60)
        return QStringLiteral("%1 min").arg(qRound(seconds / 60));
    return QStringLiteral("%1 h").arg(seconds / 3600, 0, 'f', 1);
}

// "\r" returns to the line's start and ESC [K clears what a longer earlier line left.
void show(const QString& line)
{
    std::fputs(("\r" + line + "\033[K").toLocal8Bit().constData(), stderr);
    std::fflush(stderr);
}

} // namespace

RenderProgress::RenderProgress(qint64 steps, QString unit)
    : m_steps(steps), m_unit(std::move(unit)), m_enabled(isatty(STDERR_FILENO) == 1) {}

RenderProgress::~RenderProgress()
{
    if (m_shown)
        show({});
}

void RenderProgress::update(qint64 step, std::size_t vertices)
{
    const Clock::time_point now = Clock::now();
    if (!m_enabled || step <= 0 || now - m_start < kQuietStart || (m_shown && now - m_lastShown < kRefresh))
        return;
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    const double left = elapsed / double(step) * double(m_steps - step);
    show(QStringLiteral("%1 %2 of %3, %4 vertices, about %5 left")
             .arg(m_unit)
             .arg(step)
             .arg(m_steps)
             .arg(qulonglong(vertices))
             .arg(duration(left)));
    m_lastShown = now;
    m_shown = true;
}

} // namespace vf::app
