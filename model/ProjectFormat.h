#pragma once
// The layout of *.vfproj files that ProjectReader.cpp and ProjectWriter.cpp share
// (docs/project-format.md), and the checks both apply to what is in them.
#include "model/JsonFormat.h"
#include "model/Project.h"
#include "model/StateBlob.h"

#include <QByteArrayView>

#include <cstdint>

namespace vf::model::projectformat {

// The first line: the magic word, a space, the version, a newline. Version 3 adds the journal
// between the states ("origin", "drives", each state's "reached") and predicts the states' packed
// arrays linearly (StateEncoding::PackedLinear); version 2 packed them from the value before
// (Packed); both deflate them; version 1 stored them plain. All read.
inline constexpr QByteArrayView kMagic = "VFPROJ ";
inline constexpr int kVersion = 3;
inline constexpr int kOldestVersion = 1;
inline constexpr qsizetype kMaxHeaderLine = 32;
// After the header line: the manifest's length in bytes, unsigned 64-bit little-endian.
inline constexpr qsizetype kLengthBytes = 8;

inline StateEncoding stateEncoding(int version)
{
    return version == 1 ? StateEncoding::Plain : version == 2 ? StateEncoding::Packed : StateEncoding::PackedLinear;
}

// qCompress stores the uncompressed length in 32 bits.
inline constexpr std::int64_t kMaxRawBlob = 0xffffffffLL;
// The most that deflate can expand one compressed byte to (RFC 1951's best case is 1032:1): a
// blob claiming more is corrupt, and the reader refuses it before allocating.
inline constexpr std::int64_t kMaxInflation = 1032;
inline constexpr std::int64_t kMaxHistory = 1'000'000;
// Integers in JSON are doubles: this is the largest range they hold exactly.
inline constexpr std::int64_t kMaxJsonInteger = std::int64_t(1) << 53;

// Every region table of the project (now, and before and after each history entry): unique
// non-empty names (they become SVG ids), and sim indices that name a region of the state the table
// goes with. Throws json::ReadError at the table's key path.
void checkRegionTables(const Project& project);

// Each history entry has states at both ends (a command on the simulation) or at neither (a look
// edit): undo and redo restore what is there. Throws json::ReadError at the null one's key path.
void checkCommandEnds(const Project& project);

} // namespace vf::model::projectformat
