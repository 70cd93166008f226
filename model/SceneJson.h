#pragma once
// The scene as a JSON object, for formats that embed one (the project file keeps its scene under
// "scene"). model/SceneFile.h reads and writes whole scene files with these.
#include "model/JsonFormat.h"
#include "model/Scene.h"

#include <QJsonObject>

namespace vf::model {

// Every key, defaults included, doubles in their shortest round-trip form.
QJsonObject sceneToJsonObject(const Scene& scene);
// Its "flow" and "tracking" objects alone (a project's history records them per command).
QJsonObject flowToJson(const FlowSpec& flow);
QJsonObject trackingToJson(const TrackingSpec& tracking);

// Reads and validates the object of a scene file (docs/scene-format.md) found at `root`; throws
// json::ReadError with key paths below root's.
Scene readSceneObject(const json::Field& root);
FlowSpec readFlowObject(const json::Field& field);
TrackingSpec readTrackingObject(const json::Field& field);

} // namespace vf::model
