#include "app/SceneFrames.h"

#include "app/Backend.h"
#include "sim/opencl/OpenClSimulation.h"

#include <climits>
#include <cmath>

namespace vf::app {

qint64 frameCount(const FrameRange& range)
{
    return std::llround((range.end - range.start) * range.fps);
}

SceneFrames::SceneFrames(model::Player& player, const FrameRange& range, std::function<bool()> stop)
    : m_player(player), m_range(range), m_stop(std::move(stop))
{
}

render::Animation SceneFrames::animation()
{
    return {int(std::min<qint64>(frameCount(m_range), INT_MAX)), m_range.fps, [this](int index) { return frame(index); }};
}

model::Drawing SceneFrames::frame(int index)
{
    const qint64 steps = std::llround((m_range.start + index / m_range.fps) / m_player.dt());
    while (m_player.stepsDone() < steps && m_limit.isEmpty() && !(m_stop && m_stop())) {
        try {
            if (m_player.step().vertexLimitReached)
                m_limit = vertexLimitLabel(m_player.simulation()) + QStringLiteral(" reached");
        } catch (const sim::opencl::DeviceError& e) {  // e.g. the device ran out of memory
            m_limit = QString::fromUtf8(e.what()).section('\n', 0, 0);
        }
    }
    return m_player.drawing();
}

} // namespace vf::app
