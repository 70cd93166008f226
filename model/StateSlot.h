#pragma once
// A place for one simulation state, filled on the simulation's thread and read anywhere. The GUI
// asks the worker to snapshot into a slot, or to restore from one; requests run in order on the
// worker, so a restore always finds the slot an earlier snapshot request filled. The GUI itself
// only waits on a slot when it must have the state (saving a project).
#include "model/Journal.h"
#include "sim/SimulationState.h"

#include <condition_variable>
#include <memory>
#include <mutex>

namespace vf::model {

using StatePtr = std::shared_ptr<const sim::SimulationState>;

class StateSlot {
public:
    StateSlot() = default;
    explicit StateSlot(StatePtr state, JournalMark mark = {}) : m_state(std::move(state)), m_mark(std::move(mark)) {}

    // `mark`: where the state was taken in the journal of the live simulation (model/Journal.h).
    void fill(StatePtr state, JournalMark mark = {})
    {
        {
            std::lock_guard lock(m_mutex);
            m_state = std::move(state);
            m_mark = std::move(mark);
        }
        m_filled.notify_all();
    }
    // Null until filled.
    StatePtr state() const
    {
        std::lock_guard lock(m_mutex);
        return m_state;
    }
    StatePtr wait() const
    {
        std::unique_lock lock(m_mutex);
        m_filled.wait(lock, [this] { return m_state != nullptr; });
        return m_state;
    }
    JournalMark waitForMark() const
    {
        std::unique_lock lock(m_mutex);
        m_filled.wait(lock, [this] { return m_state != nullptr; });
        return m_mark;
    }

private:
    mutable std::mutex m_mutex;
    mutable std::condition_variable m_filled;
    StatePtr m_state;
    JournalMark m_mark;
};

using StateSlotPtr = std::shared_ptr<StateSlot>;

} // namespace vf::model
