#include "sim/Simulation.h"

#include "sim/ReferenceSimulation.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace vf::sim {

namespace {

void require(bool condition, const char* message)
{
    if (!condition)
        throw std::invalid_argument(message);
}

template <typename T, typename Predicate>
bool all(const std::vector<T>& values, Predicate predicate)
{
    return std::all_of(values.begin(), values.end(), predicate);
}

bool finite(double x) { return std::isfinite(x); }
bool finitePoint(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }
bool positive(double x) { return std::isfinite(x) && x > 0.0; }

void requireContour(const Contour& c, std::size_t index, int regionCount)
{
    const auto fail = [index](const std::string& what) {
        throw std::invalid_argument("snapshot contour " + std::to_string(index) + " " + what);
    };
    const std::size_t n = c.positions.size();
    if (n < 3)
        fail("has " + std::to_string(n) + " vertices; a contour needs at least 3");
    if (c.previous.size() != n || c.spacing.size() != n)
        fail("has " + std::to_string(n) + " positions but " + std::to_string(c.previous.size()) +
             " previous positions and " + std::to_string(c.spacing.size()) + " spacings");
    if (c.region < 0 || c.region >= regionCount)
        fail("belongs to region " + std::to_string(c.region) + ", outside [0, " + std::to_string(regionCount) + ")");
    if (!all(c.positions, finitePoint) || !all(c.previous, finitePoint) || !std::isfinite(c.targetArea))
        fail("holds a non-finite number");
    if (!all(c.spacing, positive))
        fail("has a spacing that is not a positive number");
}

void requireFluid(const FluidState& f)
{
    const MacVelocity& v = f.velocity;
    require(v.nx >= 1 && v.ny >= 1, "snapshot fluid grid must have at least 1 x 1 cells");
    const auto nx = std::size_t(v.nx), ny = std::size_t(v.ny);
    require(v.u.size() == (nx + 1) * ny && v.v.size() == nx * (ny + 1) && f.pressure.size() == nx * ny,
            "snapshot fluid arrays do not match its grid size");
    require(positive(v.hx) && positive(v.hy), "snapshot fluid cell size must be a positive number");
    require(all(v.u, finite) && all(v.v, finite) && all(f.pressure, finite), "snapshot fluid holds a non-finite number");
}

} // namespace

std::vector<Contour> settledContours(std::vector<Contour> contours)
{
    for (Contour& c : contours)
        c.previous = c.positions;
    return contours;
}

void validateState(const SimulationState& state, std::size_t vertexLimit)
{
    require(std::isfinite(state.time), "snapshot time must be a finite number");
    require(state.regionCount >= 0, "snapshot region count must not be negative");
    std::size_t vertices = 0;
    for (std::size_t i = 0; i < state.contours.size(); ++i) {
        requireContour(state.contours[i], i, state.regionCount);
        vertices += state.contours[i].positions.size();
    }
    if (vertices > vertexLimit)
        throw std::invalid_argument("snapshot has " + std::to_string(vertices) + " vertices, more than the " +
                                    std::to_string(vertexLimit) + " this simulation can hold");
    if (state.fluid)
        requireFluid(*state.fluid);
}

const FluidState* fluidOnGrid(const SimulationState& state, const FluidSettings& fluid)
{
    if (!state.fluid || state.fluid->velocity.nx != fluid.nx || state.fluid->velocity.ny != fluid.ny)
        return nullptr;
    return &*state.fluid;
}

// Shared by every backend so they refuse exactly the same settings.
void validateSettings(const SimulationSettings& s)
{
    const TrackingSettings& t = s.tracking;
    require(std::isfinite(t.maxSpacing) && t.maxSpacing > 0.0, "tracking max_spacing must be a positive number");
    require(t.maxVertices >= 3, "tracking max_vertices must be at least 3");
    require(t.maxSubsteps >= 1, "tracking max_substeps must be at least 1");
    require(std::isfinite(s.fluid.width) && s.fluid.width > 0.0 && std::isfinite(s.fluid.height) && s.fluid.height > 0.0,
            "canvas width and height must be positive numbers");
}

int substepCount(double strain, const TrackingSettings& tracking)
{
    if (!(strain >= 0.0))  // NaN: let the step run once and the finiteness checks speak
        return 1;
    return int(std::clamp(std::ceil(strain / tracking.substepStrain), 1.0, double(tracking.maxSubsteps)));
}

DropReport Simulation::drop(Vec2 center, double radius)
{
    // A contour around the centre ends up enclosing the new drop too: π r² more, what the push adds
    // to it exactly, so the area correction has no reason to move it (a uniform shrink by the drop
    // polygon's shortfall would move it onto ink the drop has pressed against its rim). The ring it
    // shows beside the next drop is then the drop's true area. The drop's polygon lies a hair inside
    // the rim (the chord tolerance and four single-precision spacings of its coordinates, as a
    // device keeps them), so that ink the push leaves a hair outside the rim does not start out
    // crossing its chords; separateLayers then widens that hair.
    const double inside = settings().tracking.chordTolerance +
                          4.0 * double(FLT_EPSILON) * (std::max(std::abs(center.x), std::abs(center.y)) + radius);
    const Polygon dropped = circle(center, std::max(radius - inside, radius / 2.0), settings().tracking.maxSpacing);
    growTargetAreasAround(center, std::numbers::pi * radius * radius);
    // The push leaves a layer at distance d from the centre d/√(d² + r²) as thick: 3/√10 of it at
    // 3r, where it then lies at √10·r. So the widening looks within those distances, and a drop
    // into a big sheet costs little more than the push; but layers farther out are pressed by every
    // drop, so once the drops since the last widening of all the ink may have pressed them to half
    // their thickness, this one widens all of it.
    const auto around = [center](double reach) { return Window{center - Vec2(reach), center + Vec2(reach)}; };
    const double pressedOutside = 3.0 / std::sqrt(10.0);
    const bool everywhere = m_layersPressed * pressedOutside < 0.5;
    separateLayers(everywhere ? std::nullopt : std::optional(around(3.0 * radius)));
    m_layersPressed = (everywhere ? 1.0 : m_layersPressed) * pressedOutside;
    const bool refined = pushOutward(center, radius);
    DropReport report;
    report.region = addRegion({dropped});
    separateLayers(around(std::sqrt(10.0) * radius));
    report.vertexLimitReached = !refined || vertexCount() > settings().tracking.maxVertices;
    return report;
}

bool Simulation::applyMap(const ExactMap& map)
{
    separateLayers();
    const bool refined = mapContours(map);
    separateLayers();
    m_layersPressed = 1.0;  // all the ink was widened just now
    return refined;
}

void Simulation::drive(const BodyForce& force)
{
    if (settings().flow != SimulationSettings::FlowType::Fluid)
        return;
    validateForce(force, settings().fluid.nx, settings().fluid.ny);
    m_pendingForce = force;
}

std::vector<std::vector<Polygon>> Simulation::regions() const
{
    std::vector<std::vector<Polygon>> out(regionCount());
    for (Contour& c : contours())
        out[c.region].push_back(std::move(c.positions));
    return out;
}

std::unique_ptr<Simulation> makeReferenceSimulation(const SimulationSettings& settings)
{
    return std::make_unique<ReferenceSimulation>(settings);
}

} // namespace vf::sim
