#pragma once
// A simulation state as the bytes a project file stores (docs/project-format.md, "State blobs"):
// little-endian integers and IEEE doubles, every array preceded by its length, so that a state
// reads back bit for bit. Compression is the project file's business, not this one's; this one
// only lays the numbers out so that they compress well.
#include "model/JsonFormat.h"
#include "sim/SimulationState.h"

#include <QByteArray>

namespace vf::model {

// How the arrays of doubles are laid out (docs/project-format.md, "State blobs"): as they are
// (project version 1), or each value less a prediction and split into byte planes, the same size
// but far more compressible: predicted from the value before (version 2) or on the line through
// the two before (version 3).
enum class StateEncoding { Plain, Packed, PackedLinear };

QByteArray encodeState(const sim::SimulationState& state, StateEncoding encoding);

// Reads what encodeState wrote. Every length is checked against the bytes left before anything is
// allocated, so a hostile length cannot ask for more memory than the blob's own size. Throws
// json::ReadError at `where` for a blob that ends early, has bytes left over or holds a state that
// checkState refuses.
sim::SimulationState decodeState(const QByteArray& bytes, StateEncoding encoding, const json::KeyPath& where);

// What a state must satisfy to be written and read: parallel arrays of equal length, a velocity
// and pressure that fit the grid, contours of existing regions with at least 3 vertices, and
// finite numbers everywhere. Throws json::ReadError at `where`.
void checkState(const sim::SimulationState& state, const json::KeyPath& where);

} // namespace vf::model
