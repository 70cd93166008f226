#pragma once
// A time range of a player (a scene, or the history replayed) as the frames of an animation: frame
// k shows it played from its start to start + k / fps seconds, to the nearest step of its dt.
// Shared by `vectorfluid animate` and File ▸ Export Animation.
#include "model/Player.h"
#include "render/Animation.h"

#include <QString>

#include <functional>

namespace vf::app {

struct FrameRange {
    double start = 0;  // seconds of scene time
    double end = 0;
    double fps = 30;
};

// round((end - start) × fps): the frames of the range (may be 0 or negative for an empty range).
qint64 frameCount(const FrameRange& range);

// Plays `player` forward as the frames are asked for. Stepping stops early when a vertex limit is
// reached or `stop` says so; limit() then says which limit.
class SceneFrames {
public:
    SceneFrames(model::Player& player, const FrameRange& range, std::function<bool()> stop = {});

    // The animation of frameCount(range) frames (at most INT_MAX).
    render::Animation animation();
    // What stopped the stepping: "max_vertices (N) reached", a device error's first line; or empty.
    const QString& limit() const { return m_limit; }

private:
    model::Drawing frame(int index);

    model::Player& m_player;
    FrameRange m_range;
    std::function<bool()> m_stop;
    QString m_limit;
};

} // namespace vf::app
