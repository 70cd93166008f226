#pragma once
// Traditional marbling patterns (stone, gel-git, chevron, nonpareil, bouquet) as the sequences of
// drops and combs a marbler makes them with (docs/scene-format.md, "pattern").
#include "model/Scene.h"

#include <QString>

#include <optional>

namespace vf::model {

// The pattern's tools on this canvas, in the order they act: the stone's drops one every
// `dropInterval` seconds from its time, then each pass after the last (exact passes
// `dropInterval` apart, passes in the water `duration` apart).
std::vector<Stroke> patternStrokes(const PatternStroke& pattern, const Canvas& canvas);
inline constexpr double dropInterval = 0.002;

// How much the pattern makes on this canvas, counted without making it.
struct PatternSize {
    double drops = 0.0;  // the stone's
    std::size_t passes = 0;
};
PatternSize patternSize(const PatternStroke& pattern, const Canvas& canvas);

// Why the pattern cannot be made on this canvas (more drops than a spatter may have, or more tines
// than a comb), naming the key to change; empty when it can. Cheap: expands nothing.
struct PatternProblem {
    QString key, message;
};
std::optional<PatternProblem> patternProblem(const PatternStroke& pattern, const Canvas& canvas);

// The pattern kinds' names in files and menus, in the order of PatternStroke::Kind.
QString patternName(PatternStroke::Kind kind);

} // namespace vf::model
