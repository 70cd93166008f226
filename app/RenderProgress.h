#pragma once
// The progress line of a long render on a terminal: "step 1200 of 50000, 84311 vertices, about
// 3 min left" (or "frame ..." for an animation), rewritten in place on stderr. It appears only once a run has taken a few seconds,
// and never when stderr is not a terminal (a pipe, a log file), so scripts see only real errors.
#include <QString>

#include <chrono>
#include <cstddef>

namespace vf::app {

class RenderProgress {
public:
    // `steps`: how many there are; `unit`: what they are called ("step", "frame").
    explicit RenderProgress(qint64 steps, QString unit = QStringLiteral("step"));
    ~RenderProgress();  // clears the line
    RenderProgress(const RenderProgress&) = delete;
    RenderProgress& operator=(const RenderProgress&) = delete;

    void update(qint64 step, std::size_t vertices);

private:
    using Clock = std::chrono::steady_clock;

    const qint64 m_steps;
    const QString m_unit;
    const bool m_enabled;
    const Clock::time_point m_start = Clock::now();
    Clock::time_point m_lastShown;
    bool m_shown = false;
};

} // namespace vf::app
