#pragma once
// Reading and writing *.vfscene files (docs/scene-format.md). Validation is strict: every error is
// one line naming the file, the key path (or line and column for broken JSON) and what is wrong.
#include "model/Scene.h"

#include <QByteArray>
#include <QString>

namespace vf::model {

struct SceneReadResult {
    Scene scene;
    QString error;  // empty on success
    bool ok() const { return error.isEmpty(); }
};

// SVG shapes are read relative to the scene file's folder.
SceneReadResult readSceneFile(const QString& path);
// SVG shapes are read relative to `folder`; without one they must carry their contents.
SceneReadResult parseScene(const QByteArray& json, const QString& sourceName, const QString& folder = {});

QByteArray sceneToJson(const Scene& scene);
// Atomic (QSaveFile): the previous file survives any failure. Returns an error line or empty.
[[nodiscard]] QString writeSceneFile(const Scene& scene, const QString& path);

} // namespace vf::model
