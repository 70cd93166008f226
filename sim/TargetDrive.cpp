#include "sim/TargetDrive.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vf::sim {
namespace {

// Points per cell side where the shapes are rasterised: enough that a thin stroke of a letter
// shows as a partial cell rather than vanishing between samples.
constexpr int kSamples = 4;
// ρ̃* is floored at this share of its largest value. Where the target's blurs fall below it (ink
// far from the shape, reached only by the wide blurs, whose weights are as small as (σ/σ_k)⁴), the
// pull fades: measured on the gather-word demo (at σ = 0.01 on a 128 × 128 grid), no floor
// (1e-200) draws all the ink into the word's outline as a band, pulled to the middle of the whole
// word (overlap 0.31 to 0.34), where this floor lets the letters' own detail lead and the word
// reads.
constexpr double kTargetFloor = 1e-4;

} // namespace

void validateDriveSettings(const TargetDriveSettings& s)
{
    const auto good = [](double x) { return std::isfinite(x) && x >= 0.0; };
    if (!good(s.strength) || !good(s.attenuation) || !good(s.gathering))
        throw std::invalid_argument("target drive: strength, attenuation and gathering must be zero or positive");
    if (!(s.blur > 0.0) || !std::isfinite(s.blur))
        throw std::invalid_argument("target drive: blur must be positive");
}

TargetDrive::TargetDrive(const std::vector<std::vector<Polygon>>& target, const FluidSettings& fluid,
                         const TargetDriveSettings& settings)
    : m_settings(settings)
    , m_target(target)
    , m_cells{fluid.nx, fluid.ny, fluid.width, fluid.height}
{
    validateDriveSettings(settings);
    const std::vector<double> covered = coverage(target, m_cells, kSamples);
    m_blurredTarget.assign(m_cells.size(), 0.0);
    m_pull.assign(m_cells.size(), 0.0);
    const double widest = 0.5 * std::max(fluid.width, fluid.height);
    // Blur k (σ_k = 2^k σ) counts (σ/σ_k)⁴ in ρ̃* and (σ/σ_k)² in P (see the top).
    double weight = 1.0, pullWeight = 1.0;
    for (double sigma = settings.blur; sigma <= widest || weight == 1.0; sigma *= 2.0, weight /= 16.0, pullWeight /= 4.0) {
        const std::vector<double> blurred = gaussianBlur(covered, m_cells, sigma);
        for (std::size_t k = 0; k < blurred.size(); ++k) {
            m_blurredTarget[k] += weight * blurred[k];
            m_pull[k] += pullWeight * blurred[k];
        }
    }
    const double peak = *std::max_element(m_blurredTarget.begin(), m_blurredTarget.end());
    if (!(peak > 0.0))
        throw std::invalid_argument("target drive: the target covers none of the canvas");
    for (double& x : m_blurredTarget)
        x = std::max(x, kTargetFloor * peak);
    m_depth = signedDepth(covered, m_cells);
}

BodyForce TargetDrive::force(const std::vector<std::vector<Polygon>>& ink) const
{
    const std::vector<double> density = gaussianBlur(coverage(ink, m_cells, kSamples), m_cells, m_settings.blur);
    const int nx = m_cells.cols, ny = m_cells.rows;
    const double hx = m_cells.width / nx, hy = m_cells.height / ny;
    const double gain = m_settings.strength * m_settings.blur * m_settings.blur;  // v_f σ²
    BodyForce f{FluidSolver::atRest({nx, ny, m_cells.width, m_cells.height}), m_settings.attenuation};
    // Between cells a and b, h apart along the face's normal: ρ̃ (v_f σ² ∇P / ρ̃* + v_g ∇Φ), each
    // averaged onto the face. Wall faces stay zero.
    const auto between = [&](std::size_t a, std::size_t b, double h) {
        const double t = 0.5 * (m_blurredTarget[a] + m_blurredTarget[b]);
        const double drive = gain * (m_pull[b] - m_pull[a]) / t, gathering = m_settings.gathering * (m_depth[b] - m_depth[a]);
        return 0.5 * (density[a] + density[b]) * (drive + gathering) / h;
    };
    for (int j = 0; j < ny; ++j)
        for (int i = 1; i < nx; ++i)
            f.acceleration.u[std::size_t(j) * (nx + 1) + i] =
                between(std::size_t(j) * nx + i - 1, std::size_t(j) * nx + i, hx);
    for (int j = 1; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            f.acceleration.v[std::size_t(j) * nx + i] = between(std::size_t(j - 1) * nx + i, std::size_t(j) * nx + i, hy);
    return f;
}

} // namespace vf::sim
