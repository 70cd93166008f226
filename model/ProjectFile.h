#pragma once
// Reading and writing *.vfproj files (docs/project-format.md): a JSON manifest with the scene,
// the region tables and the undo history, followed by the simulation states as compressed binary
// blobs, each distinct state once. Validation is strict: every error is one line naming the file,
// where in it (a manifest key path or a state) and what is wrong.
#include "model/Project.h"

#include <QByteArray>
#include <QString>

namespace vf::model {

struct ProjectReadResult {
    Project project;
    QString error;  // empty on success
    bool ok() const { return error.isEmpty(); }
};

ProjectReadResult readProjectFile(const QString& path);
ProjectReadResult parseProject(const QByteArray& bytes, const QString& sourceName);

// The whole file in memory. A project that checkProject() refuses gives an empty array.
QByteArray projectToBytes(const Project& project);
// Atomic (model/AtomicFile.h): the previous file survives any failure, including a project that
// could not be read back (a NaN in a state, a duplicate region name). Returns an error line or
// empty.
[[nodiscard]] QString writeProjectFile(const Project& project, const QString& path);

// What a project must satisfy to be written, the same rules the reader applies: an empty string,
// or "key path: what is wrong" with the manifest's key paths ("history[2].after: contour 0 …").
[[nodiscard]] QString checkProject(const Project& project);

} // namespace vf::model
