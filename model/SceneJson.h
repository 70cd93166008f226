#pragma once
// The scene as a JSON object, for formats that embed one (the project file keeps its scene under
// "scene"). model/SceneFile.h reads and writes whole scene files with these.
#include "model/JsonFormat.h"
#include "model/Scene.h"

#include <QJsonObject>

namespace vf::model {

// How a region's SVG shape is written: the file's name as the scene gives it (scene files), or
// with the file's contents too (project files, which must open without it).
enum class SvgShapes { Reference, Embedded };

// Every key, defaults included, doubles in their shortest round-trip form.
QJsonObject sceneToJsonObject(const Scene& scene, SvgShapes svg);
// Its "flow" and "tracking" objects alone (a project's history records them per command).
QJsonObject flowToJson(const FlowSpec& flow);
QJsonObject trackingToJson(const TrackingSpec& tracking);

// Reads and validates the object of a scene file (docs/scene-format.md) found at `root`; throws
// json::ReadError with key paths below root's. SVG files are found relative to `folder`; with an
// empty folder every SVG shape must carry its contents.
Scene readSceneObject(const json::Field& root, const QString& folder);
FlowSpec readFlowObject(const json::Field& field);
TrackingSpec readTrackingObject(const json::Field& field);

} // namespace vf::model
