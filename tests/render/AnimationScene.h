#pragma once
// A small scene for the animation tests, played one step per frame: a stylus stroke stirs one
// region and a translucent drop lands on it at frame 2, so a layer starts part-way, vertex counts
// change from frame to frame and the region below shows through the drop.
#include "model/SceneFile.h"
#include "model/SceneRunner.h"
#include "render/Animation.h"

#include <QtTest>

#include <vector>

namespace vf::test {

inline const char* const kAnimationScene = R"({
  "vectorfluid": 1,
  "canvas": {"width": 1.0, "height": 0.8, "background": "#fdf8ef"},
  "flow": {"type": "fluid", "grid": [16, 16], "viscosity": 0.001},
  "time": {"dt": 0.01, "steps": 6},
  "tracking": {"max_spacing": 0.01, "max_vertices": 100000},
  "regions": [
    {"name": "ink", "color": "#1d3557", "shape": {"circle": {"center": [0.4, 0.4], "radius": 0.22}}}
  ],
  "strokes": [
    {"tool": "stylus", "radius": 0.08, "points": [[0.1, 0.3, 0.0], [0.9, 0.5, 0.06]]},
    {"tool": "drop", "name": "madder", "time": 0.02, "center": [0.4, 0.4], "radius": 0.1, "color": "#e6394680"}
  ]
})";

inline model::Scene animationScene()
{
    const model::SceneReadResult read = model::parseScene(kAnimationScene, QStringLiteral("animation.vfscene"));
    if (!read.ok())
        qFatal("%s", qPrintable(read.error));
    return read.scene;
}

// `count` frames, one step of the scene's dt apart, starting with the scene as it starts; each
// frame handed out is also kept in `frames`.
inline render::Animation recordedAnimation(model::SceneRunner& runner, int count, std::vector<model::Drawing>& frames)
{
    return {count, 30.0, [&runner, &frames](int index) {
                if (index > 0)
                    runner.step(runner.scene().time.dt);
                frames.push_back(runner.drawing());
                return frames.back();
            }};
}

} // namespace vf::test
