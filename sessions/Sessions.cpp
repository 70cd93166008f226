#include "sessions/Sessions.h"

#include "model/TextOutlines.h"

#include <QFont>

#include <glm/common.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <random>

namespace vf::sessions {

namespace {

// Classic marbling inks: sumi black, indigo, vermilion, ochre, green, violet, rose, sky.
constexpr std::array<const char*, 8> kInks{"#1f1d1b", "#2d4a74", "#c2452d", "#e0b84a",
                                            "#3f7f5f", "#8a3f7a", "#d98c5f", "#5b8fb9"};

class Dice {
public:
    explicit Dice(std::uint32_t seed) : m_engine(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(m_engine); }
    int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_engine); }

private:
    std::mt19937 m_engine;
};

model::Scene baseScene(double maxSpacing, double dt, std::int64_t steps)
{
    model::Scene scene;
    scene.canvas.background = QColor("#f4eee2");
    scene.time = {dt, steps};
    scene.tracking.maxSpacing = maxSpacing;
    scene.tracking.maxVertices = 8'000'000;
    return scene;
}

// A pen path from `from` to `to` over [start, start + seconds], bowed sideways by `bow` (canvas
// units at its middle), in `pieces` straight pieces.
model::StylusStroke penPath(sim::Vec2 from, sim::Vec2 to, double start, double seconds, double radius, double bow,
                            int pieces = 10)
{
    model::StylusStroke stroke;
    stroke.radius = radius;
    const sim::Vec2 along = to - from, side = sim::Vec2(-along.y, along.x) / std::hypot(along.x, along.y);
    for (int k = 0; k <= pieces; ++k) {
        const double s = double(k) / pieces;
        stroke.points.push_back(from + s * along + bow * std::sin(std::numbers::pi * s) * side);
        stroke.times.push_back(start + s * seconds);
    }
    return stroke;
}

// One comb pass: `tines` pens in parallel across the tray, along x (`alongX`) or y, forward or back,
// each row offset by a fraction of the tine pitch; returns when it ends.
double combPass(model::Scene& scene, const MarblingOptions& o, bool alongX, bool forward, double start, Dice& dice)
{
    const double offset = dice.uniform(-0.4, 0.4), bow = dice.uniform(-0.02, 0.02);
    const double seconds = o.passSeconds * dice.uniform(0.85, 1.15);
    for (int m = 0; m < o.tines; ++m) {
        const double across = (m + 0.5 + offset) / o.tines;
        const double a = forward ? 0.02 : 0.98, b = forward ? 0.98 : 0.02;
        const sim::Vec2 from = alongX ? sim::Vec2(a, across) : sim::Vec2(across, a);
        const sim::Vec2 to = alongX ? sim::Vec2(b, across) : sim::Vec2(across, b);
        scene.strokes.push_back(penPath(from, to, start, seconds, o.tineRadius, bow));
    }
    return start + seconds;
}

} // namespace

model::Scene marbling(const MarblingOptions& o, std::uint32_t seed)
{
    Dice dice(seed);
    model::Scene scene = baseScene(o.maxSpacing, o.dt, o.steps);
    const int n = o.dropsPerSide;
    double t = 0.0;
    const int firstInk = dice.below(int(kInks.size()));
    for (int k = 0; k < n * n; ++k, t += 0.02) {
        model::DropStroke drop;
        drop.time = t;
        drop.center = {(k % n + 0.5 + dice.uniform(-0.15, 0.15)) / n, (k / n + 0.5 + dice.uniform(-0.15, 0.15)) / n};
        drop.radius = o.dropRadius * dice.uniform(0.85, 1.15);
        drop.color = QColor(kInks[std::size_t(firstInk + k) % kInks.size()]);
        scene.strokes.push_back(drop);
    }
    t += 0.05;
    for (int p = 0; p < o.combPasses + o.crossPasses; ++p)
        t = combPass(scene, o, p < o.combPasses, p % 2 == 0, t, dice) + 0.1 * dice.uniform(0.5, 1.5);
    return scene;
}

model::Scene fineDetail(const FineDetailOptions& o, std::uint32_t seed)
{
    Dice dice(seed);
    model::Scene scene = baseScene(o.spacing, o.dt, o.steps);
    scene.tracking.adaptive = false;
    const int n = o.circlesPerSide;
    for (int k = 0; k < n * n; ++k) {
        const sim::Vec2 centre((k % n + 0.5 + dice.uniform(-0.1, 0.1)) / n, (k / n + 0.5 + dice.uniform(-0.1, 0.1)) / n);
        scene.regions.push_back({QStringLiteral("circle %1").arg(k), QColor(kInks[std::size_t(k) % kInks.size()]), true,
                                 model::CircleShape{centre, o.radius * dice.uniform(0.9, 1.1)}});
    }
    const sim::Vec2 from(0.05, dice.uniform(0.05, 0.3)), to(0.95, dice.uniform(0.7, 0.95));
    scene.strokes.push_back(penPath(from, to, 0.02, o.strokeSeconds, 0.05, dice.uniform(-0.1, 0.1)));
    return scene;
}

model::Scene shapeDesign(const ShapeDesignOptions& o, const std::vector<sim::Polygon>& letters, std::uint32_t seed)
{
    Dice dice(seed);
    model::Scene scene = baseScene(o.maxSpacing, o.dt, o.steps);
    scene.flow.viscosity = o.viscosity;
    std::vector<std::pair<sim::Vec2, sim::Vec2>> boxes;
    for (std::size_t k = 0; k < letters.size(); ++k) {
        scene.regions.push_back({QStringLiteral("letter %1").arg(k), QColor(kInks[k % kInks.size()]), true,
                                 model::PolygonShape{letters[k]}});
        sim::Vec2 lo(INFINITY), hi(-INFINITY);
        for (const sim::Vec2& p : letters[k]) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        boxes.emplace_back(lo, hi);
    }
    // Each stroke runs through a letter, then the motion dies out before the next.
    const double span = o.steps * o.dt;
    for (int k = 0; k < o.strokes && !boxes.empty(); ++k) {
        const auto& [lo, hi] = boxes[std::size_t(dice.below(int(boxes.size())))];
        const sim::Vec2 centre = 0.5 * (lo + hi);
        const double angle = dice.uniform(0.0, 2.0 * std::numbers::pi), length = dice.uniform(0.15, 0.3);
        const sim::Vec2 half = 0.5 * length * sim::Vec2(std::cos(angle), std::sin(angle));
        const double start = 0.05 + k * span / o.strokes;
        scene.strokes.push_back(penPath(centre - half, centre + half, start, dice.uniform(0.1, 0.25),
                                        dice.uniform(0.03, 0.06), dice.uniform(-0.05, 0.05)));
    }
    return scene;
}

std::vector<sim::Polygon> designLetters(double maxSpacing)
{
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setBold(true);
    std::vector<sim::Polygon> letters;
    const auto line = [&](const QString& text, double x, double baseline) {
        for (const QChar letter : text) {  // one at a time, so that neighbours never touch
            for (sim::Polygon& p : model::textContours(letter, font, {x, baseline}, 0.22, maxSpacing))
                letters.push_back(std::move(p));
            x += 0.18;
        }
    };
    line(QStringLiteral("STYLE"), 0.07, 0.42);
    line(QStringLiteral("FLUX"), 0.16, 0.8);
    return letters;
}

const std::vector<std::string>& names()
{
    static const std::vector<std::string> list{"marbling", "fine-detail", "shape-design"};
    return list;
}

std::optional<model::Scene> byName(const std::string& name, std::uint32_t seed)
{
    if (name == "marbling")
        return marbling({}, seed);
    if (name == "fine-detail")
        return fineDetail({}, seed);
    if (name == "shape-design")
        return shapeDesign({}, designLetters(ShapeDesignOptions{}.maxSpacing), seed);
    return std::nullopt;
}

} // namespace vf::sessions
