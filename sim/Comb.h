#pragma once
// A comb (rake) of parallel tines drawn across the tray, as the exact, area-preserving map of
// Lu, Jaffer et al., "Mathematical Marbling" (IEEE CG&A 2012): every point moves along the stroke
// by z·u/(d + u) for each tine, d its distance to the tine's line, z the stroke's length, u the
// sharpness. A shear along the stroke's direction that depends only on the distance across it:
// its Jacobian is 1 (area kept), it moves no point across a tine's line, and the stroke drawn back
// (from and to swapped) undoes it exactly.
//
// A wavy comb's tines are sine waves: the plane is waved across the stroke, combed straight and
// unwaved (Jaffer's wavy lines), each step a shear, so the map still keeps areas and has an inverse.
#include "sim/Geometry.h"

#include <optional>

namespace vf::sim {

struct Comb {
    Vec2 from{0.0}, to{0.0};
    int tines = 1;
    double spacing = 0.0;    // between neighbouring tines, canvas units
    double sharpness = 0.0;  // u, canvas units: the distance at which a tine's pull has halved
    // The tines' wave: amplitude·sin(2π·t/wavelength + phase) across the stroke (along n, below) at t
    // along it from the stroke's middle. Amplitude 0: straight tines.
    double amplitude = 0.0, wavelength = 1.0, phase = 0.0;

    // M = (to − from)/|to − from| and z = |to − from|; tine k (k = 0 … tines − 1) is the line
    // through from + (k − (tines − 1)/2)·spacing·n along M, n = M turned +90° (waved by the wave).
    Vec2 operator()(Vec2 p) const;
    // Drawn back, with its wave where it was (t and n both turn over, so the phase does).
    Comb inverse() const { return Comb{to, from, tines, spacing, sharpness, amplitude, wavelength, -phase}; }
    // How far the ink that moves most (at a tine) moves, in stroke lengths: the sum of every tine's
    // pull there, 1 for one tine and more for several (or for a spacing under the sharpness).
    double mostPull() const;
    // Where tine k starts (on the line through `from` across the stroke), before the wave.
    Vec2 tineStart(int k) const;
    // Where the segment a–b crosses a tine, the one crossing nearest its middle, as a fraction along
    // it: the map is not smooth there (d has a corner). For a wavy comb the wave is taken as
    // straight between a and b, which for the short edges of a contour places the crossing to
    // within a small part of the edge (a split there finds it closer still).
    std::optional<double> tineCrossing(Vec2 a, Vec2 b) const;

private:
    // Across the stroke by the wave at p, sign −1 to wave the plane and +1 to unwave it.
    Vec2 waved(Vec2 p, double sign) const;
};

} // namespace vf::sim
