#include "sim/SpacingField.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>

namespace vf::sim {

std::vector<double> gaussianWeights(int radius)
{
    const double sigma = std::max(0.5, radius / 2.0);
    std::vector<double> w(2 * radius + 1);
    double sum = 0.0;
    for (int n = -radius; n <= radius; ++n)
        sum += w[n + radius] = std::exp(-0.5 * n * n / (sigma * sigma));
    for (double& x : w)
        x /= sum;
    return w;
}

double discreteCurvature(Vec2 before, Vec2 at, Vec2 after)
{
    // Menger curvature, 1 / radius of the circle through the three points: exact on circles, and
    // one square root instead of an atan2 in the hottest loop of the spacing.
    const Vec2 e0 = at - before, e1 = after - at, chord = after - before;
    const double denominator = std::sqrt(glm::dot(e0, e0) * glm::dot(e1, e1) * glm::dot(chord, chord));
    return denominator > 0.0 ? 2.0 * std::abs(e0.x * e1.y - e0.y * e1.x) / denominator : 0.0;
}

double roundedSpacing(double d)
{
    // In the bits: adding half of the last kept bit's value and clearing the rest rounds to nearest
    // (a carry into the exponent gives the next power of two, as it should).
    constexpr int dropped = 52 - spacingFractionBits;
    const auto bits = std::bit_cast<std::uint64_t>(d);
    return std::bit_cast<double>((bits + (std::uint64_t(1) << (dropped - 1))) & ~((std::uint64_t(1) << dropped) - 1));
}

namespace {

// Eq. 6, cyclic along the closed contour. The contour is copied with `radius` values wrapped on
// each side, so the window itself needs no index arithmetic.
void smoothAlongContour(std::vector<double>& d, const std::vector<double>& weights, std::vector<double>& padded)
{
    const int n = int(d.size());
    const int radius = int(weights.size() / 2);
    padded.resize(n + 2 * radius);
    for (int k = 0; k < radius; ++k) {
        padded[k] = d[((k - radius) % n + n) % n];
        padded[n + radius + k] = d[k % n];
    }
    std::copy(d.begin(), d.end(), padded.begin() + radius);
    for (int i = 0; i < n; ++i) {
        double s = 0.0;
        for (int k = 0; k <= 2 * radius; ++k)
            s += weights[k] * padded[i + k];
        d[i] = s;
    }
}

} // namespace

void computeSpacing(std::vector<Contour>& contours, const Flow& flow, double t,
                    const TrackingSettings& settings, ProximityGrid& grid, PhaseClock* clock)
{
    const double dMax = settings.maxSpacing;
    if (!settings.adaptive) {
        for (Contour& c : contours)
            c.spacing.assign(c.positions.size(), dMax);
        return;
    }
    for (Contour& c : contours)
        c.spacing.resize(c.positions.size());
    if (settings.proximity) {
        // Each vertex's distance to another part, kept in its spacing until the factor replaces it.
        const PhaseClock::Scope timing(clock, Phase::Proximity);
        grid.build(contours, settings.proximityRadius(), settings.proximityCell());
        for (std::size_t ci = 0; ci < contours.size(); ++ci)
            for (std::size_t i = 0; i < contours[ci].spacing.size(); ++i)
                contours[ci].spacing[i] = grid.nearestOtherPart(ci, i);
    }
    const PhaseClock::Scope timing(clock, Phase::Spacing);

    const double curvatureLength = settings.curvatureLength();
    const double proximityLength = settings.proximityLength();
    const double vorticityScale = settings.vorticityScale;
    const double epsilon = settings.minSpacing();
    const std::vector<double> weights = gaussianWeights(settings.smoothingRadius);
    std::vector<double> scratch;
    for (Contour& c : contours) {
        const auto& p = c.positions;
        const std::size_t n = p.size();
        for (std::size_t i = 0; i < n; ++i) {
            const double kappa = discreteCurvature(p[(i + n - 1) % n], p[i], p[(i + 1) % n]);
            // exp(-a)·exp(-b) of eqs. 4 and 5 as one exponential.
            double factor = std::exp(-kappa * curvatureLength - std::abs(flow.vorticity(p[i], t)) / vorticityScale);
            if (settings.proximity && c.spacing[i] < INFINITY)
                factor *= 1.0 - std::exp(-c.spacing[i] / proximityLength);
            c.spacing[i] = dMax * factor;
        }
        smoothAlongContour(c.spacing, weights, scratch);
        for (double& d : c.spacing)
            d = std::min(dMax, roundedSpacing(d + epsilon));
    }
}

} // namespace vf::sim
