#pragma once
// Where a simulation's time goes, phase by phase, for the session benchmarks. Off by default and
// then free: a measurement costs two clock reads, and on a device a wait for the queued work at
// each phase boundary, which is why only a benchmark turns it on.
#include <array>
#include <chrono>
#include <cstddef>
#include <functional>

namespace vf::sim {

enum class Phase { Fluid, Advect, Spacing, Proximity, Split, Collapse, Area, Pinches };
inline constexpr std::size_t phaseCount = 8;
inline constexpr std::array<const char*, phaseCount> phaseNames{"fluid", "advect",   "spacing", "proximity",
                                                                "split", "collapse", "area",    "pinches"};

class PhaseClock {
public:
    using Seconds = std::array<double, phaseCount>;

    // `sync` waits for work queued on a device, so a phase is charged what it launched.
    void enable(std::function<void()> sync = {})
    {
        m_on = true;
        m_sync = std::move(sync);
    }
    const Seconds& seconds() const { return m_seconds; }

    // Charges the time until it goes out of scope to `phase` (nothing when the clock is off).
    class Scope {
    public:
        Scope(PhaseClock* clock, Phase phase) : m_clock(clock && clock->m_on ? clock : nullptr), m_phase(phase)
        {
            if (m_clock)
                m_start = m_clock->now();
        }
        ~Scope()
        {
            if (m_clock)
                m_clock->m_seconds[std::size_t(m_phase)] += std::chrono::duration<double>(m_clock->now() - m_start).count();
        }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        PhaseClock* m_clock;
        Phase m_phase;
        std::chrono::steady_clock::time_point m_start;
    };

private:
    std::chrono::steady_clock::time_point now() const
    {
        if (m_sync)
            m_sync();
        return std::chrono::steady_clock::now();
    }

    bool m_on = false;
    std::function<void()> m_sync;
    Seconds m_seconds{};
};

} // namespace vf::sim
