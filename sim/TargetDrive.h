#pragma once
// Target-driven design (paper §5.3; Fattal and Lischinski, "Target-Driven Smoke Animation", 2004):
// a force that guides the ink into a target shape. The target is rasterised on the fluid grid and
// blurred once; before each step the ink is rasterised and blurred the same way, and the fluid
// gains the driving force
//     F = v_f · σ² · ρ̃ ∇ρ̃* / ρ̃*  (+ the gathering term below)
// (ρ̃ the blurred ink, ρ̃* the blurred target) and loses velocity at the rate v_d (the paper's
// attenuation, −v_d u), before the usual projection. The σ² makes v_f a spring constant: in the
// tail of a Gaussian blob σ² ∇ρ̃* / ρ̃* is the way to the blob's centre, so ink there accelerates
// toward it at v_f times its distance (times its density) and v_d damps the swing.
//
// So that ink far from the target is pulled too, the target T is blurred at σ_k = 2^k σ, k = 0, 1,
// ..., up to half the canvas: ρ̃* = Σ w_k G_k*T and the gradient taken is that of
// P = Σ w_k (σ_k/σ)² G_k*T, so σ² ∇P / ρ̃* = Σ w_k σ_k² ∇(G_k*T) / Σ w_k G_k*T: each blur's own
// spring, weighted by w_k = (σ/σ_k)⁴ times its blurred target. Where one blur leads both sums,
// its spring acts: far from the shape the widest (the narrow ones' tails have died out), near it
// the narrowest (the weights favour it), which follows the shape's detail. So ink anywhere on the
// canvas is drawn in, and near the shape it is drawn into the shape itself.
//
// Fattal and Lischinski's gathering term moves smoke density into the target's interior. The paper
// leaves it out (vector ink does not diffuse), and the driving force alone leaves water inside the
// target: where the blurred target is flat (inside a bold letter) it pushes nothing, so water
// caught between the ink as it arrives stays, and ink far from every blur's reach stays out. So a
// gathering term of another kind is added: the ink is lighter than the water in the potential
//     Φ = the target's signed depth (distance to its outline, positive inside, negative outside),
// which adds v_g · ρ̃ ∇Φ. Like buoyancy it moves nothing where the ink is everywhere or nowhere
// (there it is a gradient, or zero, which the projection removes); where an edge between ink and
// water crosses Φ's level lines it turns them over, ink towards the target's core and water out,
// until the ink fills the deepest part of the target, its own area's worth.
#include "sim/DistanceField.h"
#include "sim/FluidSolver.h"

#include <vector>

namespace vf::sim {

struct TargetDriveSettings {
    double strength = 400.0;  // v_f, 1/s²
    double attenuation = 10.0; // v_d, 1/s
    // σ, canvas units: the ink's blur and the target's narrowest. The ink's blur sets the scale at
    // which the gathering term can turn ink and water over: at a cell or less, water caught between
    // inks inside the target drains, where at a few cells it stays (docs/BENCHMARKS.md,
    // "Target-driven design").
    double blur = 0.002;
    double gathering = 5.0;   // v_g, canvas units/s²: the gathering term's pull (see the top)

    friend bool operator==(const TargetDriveSettings&, const TargetDriveSettings&) = default;
};

// Throws std::invalid_argument (one line) for settings a drive cannot use.
void validateDriveSettings(const TargetDriveSettings& settings);

class TargetDrive {
public:
    // `target`: shapes, each closed contours filled together even-odd, in canvas units; on the
    // grid of `fluid`. Throws std::invalid_argument for invalid settings or a target that covers
    // no cell.
    TargetDrive(const std::vector<std::vector<Polygon>>& target, const FluidSettings& fluid,
                const TargetDriveSettings& settings);

    // The force for the next step, given the ink now (every region's contours).
    BodyForce force(const std::vector<std::vector<Polygon>>& ink) const;

    const TargetDriveSettings& settings() const { return m_settings; }
    // What it was made from, so that it can be written down and made again (a project's journal).
    const std::vector<std::vector<Polygon>>& target() const { return m_target; }
    FluidSettings grid() const { return {m_cells.cols, m_cells.rows, m_cells.width, m_cells.height}; }

private:
    TargetDriveSettings m_settings;
    std::vector<std::vector<Polygon>> m_target;
    CellLattice m_cells;
    std::vector<double> m_blurredTarget;  // ρ̃* on the cells, floored
    std::vector<double> m_pull;           // P, whose gradient over ρ̃* leads the ink (see the top)
    std::vector<double> m_depth;          // Φ, the target's signed depth
};

} // namespace vf::sim
