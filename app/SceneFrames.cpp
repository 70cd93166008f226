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

SceneFrames::SceneFrames(model::SceneRunner& runner, const FrameRange& range, std::function<bool()> stop)
    : m_runner(runner), m_range(range), m_stop(std::move(stop))
{
}

render::Animation SceneFrames::animation()
{
    return {int(std::min<qint64>(frameCount(m_range), INT_MAX)), m_range.fps, [this](int index) { return frame(index); }};
}

model::Drawing SceneFrames::frame(int index)
{
    const double dt = m_runner.scene().time.dt;
    const qint64 steps = std::llround((m_range.start + index / m_range.fps) / dt);
    while (m_runner.stepsDone() < steps && m_limit.isEmpty() && !(m_stop && m_stop())) {
        try {
            if (m_runner.step(dt).vertexLimitReached)
                m_limit = vertexLimitLabel(m_runner.simulation()) + QStringLiteral(" reached");
        } catch (const sim::opencl::DeviceError& e) {  // e.g. the device ran out of memory
            m_limit = QString::fromUtf8(e.what()).section('\n', 0, 0);
        }
    }
    return m_runner.drawing();
}

} // namespace vf::app
