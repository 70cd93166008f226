#include "model/Patterns.h"

#include "model/SplitMix64.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vf::model {

namespace {

using Kind = PatternStroke::Kind;

// Parallel lines across the tray, `step` apart from `first` on, up to `extent`: how many, and
// where their middle is.
struct Lines {
    double first, step, extent;
    double count() const { return std::max(1.0, std::ceil((extent - first) / step)); }
    double middle() const { return first + (count() - 1.0) * step / 2.0; }
};

// The stone's drops, of mean area about π r², add up to about the tray's area: each pushes the
// ink before it aside (some of it over the edges), squeezing the earlier drops into veins.
double stoneDropCount(const PatternStroke& p, const Canvas& canvas)
{
    return std::ceil(canvas.width * canvas.height / (std::numbers::pi * p.dropRadius * p.dropRadius));
}

// The passes after the stone: gel-git's two combs drawn across (one each way, their tines
// interleaved, so every line is drawn once, alternately forth and back), then the comb the
// pattern adds along the canvas's height.
struct Pass {
    bool across;   // tines along x, moving along ±x; else along y, moving along ±y
    bool forward;  // +x or +y
    Lines lines;   // where the tines are, across their motion
    double amplitude = 0.0, wavelength = 0.0;
};

std::vector<Pass> passes(const PatternStroke& p, const Canvas& canvas)
{
    const double s = p.spacing, f = p.fineSpacing;
    std::vector<Pass> out;
    if (p.kind == Kind::Stone)
        return out;
    out.push_back({true, true, {s / 2.0, 2.0 * s, canvas.height}});
    if (1.5 * s < canvas.height)
        out.push_back({true, false, {1.5 * s, 2.0 * s, canvas.height}});
    if (p.kind == Kind::Chevron)
        out.push_back({false, true, {s, 2.0 * s, canvas.width}});
    if (p.kind == Kind::Nonpareil || p.kind == Kind::Bouquet)
        out.push_back({false, true, {f / 2.0, f, canvas.width}});
    if (p.kind == Kind::Bouquet)
        out.push_back({false, false, {s / 2.0, s, canvas.width}, s / 4.0, s});
    return out;
}

CombStroke comb(const PatternStroke& p, const Canvas& canvas, const Pass& pass, double time)
{
    CombStroke c;
    c.mode = p.mode;
    c.time = time;
    c.tines = int(pass.lines.count());
    c.spacing = pass.lines.step;
    // A comb's tines add their pulls, so a comb finer than the gel-git's lines drags each less, and
    // more sharply: shift and sharpness shrink with its spacing (else a fine comb would carry the
    // whole picture along with it).
    const double scale = std::min(1.0, pass.lines.step / p.spacing);
    c.sharpness = p.sharpness * scale;
    c.duration = p.duration;
    c.radius = std::min(c.radius, pass.lines.step / 4.0);  // tines in the water stay apart
    c.amplitude = pass.amplitude;
    c.wavelength = pass.amplitude > 0.0 ? pass.wavelength : c.wavelength;
    const sim::Vec2 along = pass.across ? sim::Vec2(1.0, 0.0) : sim::Vec2(0.0, 1.0);
    const sim::Vec2 middle = pass.across ? sim::Vec2(canvas.width / 2.0, pass.lines.middle())
                                         : sim::Vec2(pass.lines.middle(), canvas.height / 2.0);
    const double sign = pass.forward ? 1.0 : -1.0;
    // Exact: the map's shift is |to - from|. In the water the tines cross the whole tray.
    const double half = p.mode == CombStroke::Mode::Exact ? p.shift * scale / 2.0
                                                          : (pass.across ? canvas.width : canvas.height) / 2.0;
    c.from = middle - sign * half * along;
    c.to = middle + sign * half * along;
    return c;
}

} // namespace

QString patternName(Kind kind)
{
    switch (kind) {
    case Kind::Stone:
        return QStringLiteral("stone");
    case Kind::GelGit:
        return QStringLiteral("gel-git");
    case Kind::Chevron:
        return QStringLiteral("chevron");
    case Kind::Nonpareil:
        return QStringLiteral("nonpareil");
    case Kind::Bouquet:
        break;
    }
    return QStringLiteral("bouquet");
}

PatternSize patternSize(const PatternStroke& p, const Canvas& canvas)
{
    return {stoneDropCount(p, canvas), passes(p, canvas).size()};
}

std::optional<PatternProblem> patternProblem(const PatternStroke& p, const Canvas& canvas)
{
    if (const double drops = stoneDropCount(p, canvas); drops > limits::maxSpatterDrops)
        return PatternProblem{QStringLiteral("drop_radius"),
                              QStringLiteral("drops of radius %1 cover this canvas in %2 drops, more than %3")
                                  .arg(p.dropRadius)
                                  .arg(drops, 0, 'g', 6)
                                  .arg(limits::maxSpatterDrops)};
    for (const Pass& pass : passes(p, canvas))
        if (const double tines = pass.lines.count(); tines > limits::maxTines)
            return PatternProblem{pass.lines.step == p.fineSpacing ? QStringLiteral("fine_spacing") : QStringLiteral("spacing"),
                                  QStringLiteral("tines %1 apart make a comb of %2 tines across this canvas, more than %3")
                                      .arg(pass.lines.step)
                                      .arg(tines, 0, 'g', 6)
                                      .arg(limits::maxTines)};
    return std::nullopt;
}

std::vector<Stroke> patternStrokes(const PatternStroke& p, const Canvas& canvas)
{
    std::vector<Stroke> out;
    SplitMix64 random(p.seed);
    const int drops = int(stoneDropCount(p, canvas));
    for (int i = 0; i < drops; ++i) {
        const sim::Vec2 center(canvas.width * random.unit(), canvas.height * random.unit());
        const double radius = p.dropRadius * (0.75 + 0.5 * random.unit());
        const auto pick = std::min(std::size_t(random.unit() * double(p.colors.size())), p.colors.size() - 1);
        out.push_back(DropStroke{p.time + i * dropInterval, center, radius, p.colors[pick], QString()});
    }
    const double gap = p.mode == CombStroke::Mode::Exact ? dropInterval : p.duration;
    double time = p.time + drops * dropInterval;
    for (const Pass& pass : passes(p, canvas)) {
        out.push_back(comb(p, canvas, pass, time));
        time += gap;
    }
    return out;
}

} // namespace vf::model
