#include "sessions/Sessions.h"

#include "model/TextOutlines.h"

#include <QFont>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
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

model::Scene gather(const GatherOptions& o, std::uint32_t seed)
{
    Dice dice(seed);
    model::Scene scene = baseScene(o.maxSpacing, o.dt, std::llround((o.seconds + 0.5) / o.dt));
    scene.flow.gridX = scene.flow.gridY = 128;
    scene.flow.viscosity = 0.005;
    scene.tracking.areaCorrection = true;
    // The word, set at size 1 to measure it, then fitted to 84 % of the canvas's width (at most
    // 0.45 tall) and centred about a baseline in the lower half.
    static const std::array<const char*, 5> kWords{"INK", "FLOW", "VF", "WAVE", "SWIRL"};
    model::TextTarget word;
    word.text = QString::fromLatin1(kWords[std::size_t(dice.below(int(kWords.size())))]);
    word.size = 1.0;
    sim::Vec2 lo(INFINITY), hi(-INFINITY);
    for (const sim::Polygon& p : model::targetContours(word, 0.01))
        for (const sim::Vec2& v : p) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
    word.size = std::min(0.84 / (hi.x - lo.x), 0.45 / (hi.y - lo.y)) * dice.uniform(0.9, 1.0);
    word.baseline = {0.5 - word.size * 0.5 * (lo.x + hi.x), 0.5 - word.size * 0.5 * (lo.y + hi.y)};
    model::GatherStroke g;
    g.duration = o.seconds;
    g.target = word;
    g.contours = model::targetContours(word, o.maxSpacing);
    // Ovals of aspect 1.6, upright or lying, as many as the seed says, sharing the word's area,
    // placed at random where they keep clear of each other and of the walls.
    const int count = std::max(1, int(std::lround(o.ovals * dice.uniform(0.5, 1.5))));
    const double minor = std::sqrt(sim::filledArea(g.contours) / count / (1.6 * std::numbers::pi)), major = 1.6 * minor;
    std::vector<sim::Vec2> centres;
    for (int attempt = 0; int(centres.size()) < count && attempt < 100 * count; ++attempt) {
        const sim::Vec2 c(dice.uniform(major + 0.02, 1.0 - major - 0.02), dice.uniform(major + 0.02, 1.0 - major - 0.02));
        if (std::none_of(centres.begin(), centres.end(), [&](sim::Vec2 d) { return glm::distance(c, d) < 2.4 * major; }))
            centres.push_back(c);
    }
    for (std::size_t k = 0; k < centres.size(); ++k) {
        const sim::Vec2 radii = dice.below(2) == 0 ? sim::Vec2(major, minor) : sim::Vec2(minor, major);
        scene.regions.push_back({QStringLiteral("oval %1").arg(k + 1), QColor(kInks[k % kInks.size()]), true,
                                 model::EllipseShape{centres[k], radii}});
    }
    scene.strokes.push_back(std::move(g));
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
    static const std::vector<std::string> list{"marbling", "fine-detail", "shape-design", "gather"};
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
    if (name == "gather")
        return gather({}, seed);
    return std::nullopt;
}

} // namespace vf::sessions
