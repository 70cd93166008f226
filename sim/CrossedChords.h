#pragma once
// The last guard of an exact motion (a drop's push, a tool's map). Such a motion is a bijection of
// the plane, so the curves it carries the contours to never cross; but the contours are chords of
// those curves, within chordTolerance of them, and a layer the motion presses thinner than that can
// be crossed by a chord. Where two chords cross and their pre-images (the chords at the start of
// the motion) do not, both are split where the curve runs (at the pre-image's crease or middle,
// moved): the chords close in on the curves, which do not cross, until neither do they.
#include "sim/ContourTracker.h"

#include <cstddef>
#include <vector>

namespace vf::sim {

// Splits crossed chords of `contours` after `motion` (each vertex's `previous` its pre-image), in
// rounds until none is left or maxCrossedChordRounds have run. `floatPositions`: the new vertices'
// positions are rounded to float, as a device stores them, before they are checked. Returns how
// many vertices were inserted. A crossing the contours had before the motion is left alone.
std::size_t splitCrossedChords(std::vector<Contour>& contours, const ExactMotion& motion, bool floatPositions);

inline constexpr int maxCrossedChordRounds = 64;

} // namespace vf::sim
