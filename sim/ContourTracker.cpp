#include "sim/ContourTracker.h"

#include "sim/AreaCorrection.h"
#include "sim/CrossedChords.h"
#include "sim/Crossings.h"
#include "sim/Pinches.h"
#include "sim/SpacingField.h"
#include "sim/TightGrowth.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vf::sim {

Vec2 rungeKutta4(const Flow& flow, Vec2 p, double t, double dt)
{
    const double half = 0.5 * dt;
    const Vec2 k1 = flow.velocity(p, t);
    const Vec2 k2 = flow.velocity(p + half * k1, t + half);
    const Vec2 k3 = flow.velocity(p + half * k2, t + half);
    const Vec2 k4 = flow.velocity(p + dt * k3, t + dt);
    return p + (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

bool isThinTip(Vec2 before, Vec2 at, Vec2 after, double spacingBefore, double spacing, double spacingAfter)
{
    const Vec2 in = at - before, out = after - at;
    if (glm::dot(in, out) > 0.0)  // most vertices: no lengths needed
        return false;
    const double longest = std::max({glm::length(in), glm::length(out), glm::distance(before, after)});
    return glm::distance(before, after) <= 0.5 * (spacingBefore + spacingAfter) &&
           std::abs(in.x * out.y - in.y * out.x) <= tipWidth * spacing * longest;
}

double recentredFraction(double s, double toA, double toB, double needA, double needB)
{
    const double length = toA + toB;
    if (!(length > 0.0))
        return s;
    const double place = toA / length;
    const double lo = needA / length, hi = 1.0 - needB / length;
    const double wanted = lo <= hi ? std::clamp(0.5, lo, hi) : needA / (needA + needB);
    return std::clamp(s + (wanted - place), 0.0, 1.0);
}

namespace {

// A contour as a doubly linked ring during refinement, so a split or a collapse costs O(1)
// wherever it happens. Compacted back into the contour's arrays at the end, in ring order. Its
// vertices are kept current in `grid`, which holds every other contour's too.
class Ring {
public:
    Ring(const Contour& c, bool timeRewinding, VertexGrid& grid)
        : m_position(c.positions), m_previous(c.previous), m_spacing(c.spacing), m_rewind(timeRewinding),
          m_grid(grid)
    {
        const int n = int(m_position.size());
        m_next.resize(n);
        m_before.resize(n);
        for (int i = 0; i < n; ++i) {
            m_next[i] = (i + 1) % n;
            m_before[i] = (i + n - 1) % n;
        }
        m_alive = n;
    }

    int alive() const { return m_alive; }
    int next(int v) const { return m_next[v]; }
    int before(int v) const { return m_before[v]; }

    bool thinTip(int v) const
    {
        const int a = m_before[v], b = m_next[v];
        return isThinTip(m_position[a], m_position[v], m_position[b], m_spacing[a], m_spacing[v], m_spacing[b]);
    }
    double length(int a, int b) const { return glm::distance(m_position[a], m_position[b]); }
    // The spacing an edge must respect: the mean of its endpoints' d_i.
    double spacing(int a, int b) const { return 0.5 * (m_spacing[a] + m_spacing[b]); }
    // A vertex placed between a and b takes the smaller d: with the mean, one of the two halves of
    // an edge just over its spacing would fall under half of its own, and split and collapse would
    // undo each other forever.
    double insertedSpacing(int a, int b) const { return std::min(m_spacing[a], m_spacing[b]); }

    double turning(int v) const
    {
        const Vec2 e0 = m_position[v] - m_position[m_before[v]];
        const Vec2 e1 = m_position[m_next[v]] - m_position[v];
        return std::abs(std::atan2(e0.x * e1.y - e0.y * e1.x, glm::dot(e0, e1)));
    }

    // Where the edge after a needs a vertex, as a fraction along it at the start of the motion: in
    // the middle when it is longer than its spacing; for an exact motion also at a crease inside it
    // (a vertex on the crease: where the map folds a contour into a hairpin, the two sides near the
    // tip lie closer than any tolerance, and only a vertex at the tip keeps its chords apart), and
    // where its chord strays from the mapped curve by more than the tolerance.
    std::optional<double> splitPoint(int a, const ExactMotion& motion) const
    {
        const int b = m_next[a];
        if (m_rewind && motion.chordTolerance > 0.0) {
            if (motion.crease)
                if (const std::optional<double> s = motion.crease(m_previous[a], m_previous[b]);
                    s && (creaseInside(a, *s) || strays(a, *s, motion)))
                    return s;
            if (length(a, b) > spacing(a, b) || strays(a, 0.5, motion))
                return 0.5;
            return std::nullopt;
        }
        return length(a, b) > spacing(a, b) ? std::optional(0.5) : std::nullopt;
    }

    // Whether v lies farther than an exact motion's tolerance from the chord that its removal would
    // leave.
    bool holdsShape(int v, const ExactMotion& motion) const
    {
        if (!m_rewind || !(motion.chordTolerance > 0.0))
            return false;
        const int a = m_before[v], b = m_next[v];
        const auto [now, before] = chordTolerances(a, b, motion);
        return squaredDistanceToSegment(m_position[v], m_position[a], m_position[b]) > now * now ||
               squaredDistanceToSegment(m_previous[v], m_previous[a], m_previous[b]) > before * before;
    }

    // How far the chord a–b may stray from the curve, in the positions now and in those at the start
    // of the motion. A map that keeps areas widens a stray across an edge by as much as it presses
    // the edge along (its stretch k = |F(b) − F(a)| / |b − a| below 1), so where a vertex is placed
    // on the chord as it was (recentred), the chord then must stray k times less; and the map's
    // inverse widens a stray across the edge now by k above 1, so for the inverse to return the
    // ink within the tolerance the chord now must stray k times less (at least an eighth of the
    // tolerance, so the tip of a hairpin, stretched without bound, is not split without end).
    std::pair<double, double> chordTolerances(int a, int b, const ExactMotion& motion) const
    {
        const double tolerance = motion.chordTolerance, before = glm::distance(m_previous[a], m_previous[b]);
        if (!motion.keepsAreas || !(before > 0.0))
            return {tolerance, tolerance};
        const double stretch = length(a, b) / before;
        return {tolerance / std::clamp(stretch, 1.0, 8.0), tolerance * std::min(stretch, 1.0)};
    }

    // Eq. 2: the new vertex is the point at fraction s of the edge *at the start of the motion*
    // (its midpoint unless a crease is there), moved by it.
    int splitAfter(int a, double s, const MotionMap& map)
    {
        const int b = m_next[a];
        const Vec2 start = m_previous[a] + s * (m_previous[b] - m_previous[a]);
        const int m = int(m_position.size());
        m_position.push_back(m_rewind ? map(start) : 0.5 * (m_position[a] + m_position[b]));
        m_previous.push_back(start);
        m_spacing.push_back(insertedSpacing(a, b));
        m_next.push_back(b);
        m_before.push_back(a);
        m_next[a] = m;
        m_before[b] = m;
        ++m_alive;
        m_grid.insert(m_position[m]);
        return m;
    }

    // Whether removing v, so that its neighbours join, would sweep its edges over a vertex of any
    // contour: only then could the joining edge cross one (VertexGrid::anyInside).
    bool removalSweepsInk(int v) const
    {
        const int a = m_before[v], b = m_next[v];
        return m_grid.anyInside(m_position[a], m_position[v], m_position[b], VertexGrid::Change::RemovePb);
    }

    // Whether fraction s of the edge after a lies farther from both its ends, at the start of the
    // motion, than 2^-32 of its coordinates: a crease not yet on a vertex. (A crease found again on
    // a vertex placed on it lies some roundings off: those must not be split again and again.)
    bool creaseInside(int a, double s) const
    {
        const Vec2 p = m_previous[a], q = m_previous[m_next[a]];
        const double reach = std::max({std::abs(p.x), std::abs(p.y), std::abs(q.x), std::abs(q.y)});
        return std::min(s, 1.0 - s) * glm::distance(p, q) > 0x1p-32 * reach;
    }

    // Whether the point at fraction s of the edge after a, moved by the motion, lies farther than its
    // tolerance from the edge's chord.
    bool strays(int a, double s, const ExactMotion& motion) const
    {
        const int b = m_next[a];
        const Vec2 x = motion.map(m_previous[a] + s * (m_previous[b] - m_previous[a]));
        const double tolerance = chordTolerances(a, b, motion).first;
        return squaredDistanceToSegment(x, m_position[a], m_position[b]) > tolerance * tolerance;
    }

    void unlink(int v)
    {
        m_grid.erase(m_position[v]);
        m_next[m_before[v]] = m_next[v];
        m_before[m_next[v]] = m_before[v];
        --m_alive;
    }

    // Moves v to the time-rewound midpoint of its neighbours (eq. 2), as if v had been removed and
    // the merged edge split again. Where the curve between them is lopsided, so that one half would
    // come out short, a few corrections move the rewound point along the edge by how far the moved
    // one falls from the middle of what both ends allow (recentredFraction; at most
    // recentreCorrections + 1 motions, not a search). Only where that leaves both of v's edges at
    // least half their spacing, and neither v's removal nor the new point's insertion sweeps over
    // ink, does v move (true); else the short edge stays, rather than v being moved to the same
    // place round after round.
    bool recentre(int v, const MotionMap& map)
    {
        const int a = m_before[v], b = m_next[v];
        const Vec2 pa = m_position[a], pb = m_position[b];
        const double dv = insertedSpacing(a, b);
        const double needA = 0.25 * (m_spacing[a] + dv), needB = 0.25 * (m_spacing[b] + dv);
        auto at = [&](double s) { return m_previous[a] + s * (m_previous[b] - m_previous[a]); };
        auto place = [&](double s) { return m_rewind ? map(at(s)) : pa + s * (pb - pa); };
        double s = 0.5;
        Vec2 x = place(s);
        for (int k = 0;; ++k) {
            const double toA = glm::distance(x, pa), toB = glm::distance(x, pb);
            if (toA >= needA && toB >= needB)
                break;
            if (k == recentreCorrections)
                return false;
            s = recentredFraction(s, toA, toB, needA, needB);
            x = place(s);
        }
        if (removalSweepsInk(v))
            return false;
        m_grid.erase(m_position[v]);
        m_grid.insert(x);
        if (m_grid.anyInside(pa, x, pb, VertexGrid::Change::InsertPb)) {
            m_grid.erase(x);
            m_grid.insert(m_position[v]);
            return false;
        }
        m_previous[v] = at(s);
        m_position[v] = x;
        m_spacing[v] = dv;
        return true;
    }

    void writeTo(Contour& c, int start) const
    {
        c.positions.clear();
        c.previous.clear();
        c.spacing.clear();
        reserveTight(c.positions, std::size_t(m_alive));
        reserveTight(c.previous, std::size_t(m_alive));
        reserveTight(c.spacing, std::size_t(m_alive));
        int v = start;
        do {
            c.positions.push_back(m_position[v]);
            c.previous.push_back(m_previous[v]);
            c.spacing.push_back(m_spacing[v]);
            v = m_next[v];
        } while (v != start);
    }

private:
    std::vector<Vec2> m_position, m_previous;
    std::vector<double> m_spacing;
    std::vector<int> m_next, m_before;
    int m_alive = 0;
    bool m_rewind = true;
    VertexGrid& m_grid;
};

// Splits every edge longer than its spacing, recursively. False when `budget` vertices are reached.
bool splitPass(Ring& ring, int start, const ExactMotion& motion, std::size_t budget, bool& changed)
{
    int v = start;
    do {
        for (std::optional<double> s = ring.splitPoint(v, motion); s; s = ring.splitPoint(v, motion)) {
            if (std::size_t(ring.alive()) >= budget)
                return false;
            ring.splitAfter(v, *s, motion.map);
            changed = true;
        }
        v = ring.next(v);
    } while (v != start);
    return true;
}

// Removes a vertex of every edge shorter than half its spacing: the straighter endpoint, so corners
// and curl tips survive. Where removal would leave an edge longer than its spacing, the vertex is
// recentred instead. Removes thin needle tips (isThinTip). Nothing is removed or moved where its
// edges would sweep over a vertex of any contour. Returns the (possibly new) start vertex.
int collapsePass(Ring& ring, int start, const ExactMotion& motion, bool& changed)
{
    int v = start;
    for (int steps = ring.alive(); steps > 0 && ring.alive() > 3; --steps) {
        const int w = ring.next(v);
        if (ring.thinTip(w) && !ring.removalSweepsInk(w)) {
            // v may be the next tip.
            ring.unlink(w);
            if (w == start)
                start = ring.next(v);
            changed = true;
            v = ring.before(v);
            continue;
        }
        if (ring.length(v, w) >= 0.5 * ring.spacing(v, w)) {
            v = w;
            continue;
        }
        const int victim = ring.turning(v) < ring.turning(w) ? v : w;
        if (ring.holdsShape(victim, motion)) {
            v = w;
            continue;
        }
        const int a = ring.before(victim), b = ring.next(victim);
        const bool removable = ring.length(a, b) <= ring.spacing(a, b) && !ring.removalSweepsInk(victim);
        if (removable) {
            ring.unlink(victim);
            if (victim == start)
                start = b;
        } else if (!ring.recentre(victim, motion.map)) {
            v = w;
            continue;
        }
        changed = true;
        v = b;
    }
    return start;
}

void requireFinite(const Contour& c)
{
    for (const Vec2& p : c.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            throw std::runtime_error("the flow moved a contour vertex to a non-finite position");
}

} // namespace

ContourTracker::ContourTracker(const TrackingSettings& settings)
    : m_settings(settings)
{
}

void ContourTracker::addContour(int region, const Polygon& polygon)
{
    Contour c;
    c.region = region;
    c.positions = resample(polygon, m_settings.maxSpacing);
    c.previous = c.positions;
    c.spacing.assign(c.positions.size(), m_settings.maxSpacing);
    c.targetArea = signedArea(c.positions);
    m_vertexCount += c.positions.size();
    m_contours.push_back(std::move(c));
}

void ContourTracker::growTargetAreasAround(Vec2 p, double area)
{
    for (Contour& c : m_contours)
        c.targetArea += windingNumber(c.positions, p) * area;
}

void ContourTracker::setContours(std::vector<Contour> contours)
{
    m_contours = std::move(contours);
    m_vertexCount = 0;
    for (const Contour& c : m_contours)
        m_vertexCount += c.positions.size();
}

double ContourTracker::strainInSpacings(const Flow& flow, double t, double dt) const
{
    double worst = 0.0;
    std::vector<Vec2> velocity;
    for (const Contour& c : m_contours) {
        const std::size_t n = c.positions.size();
        velocity.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            velocity[i] = flow.velocity(c.positions[i], t);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            const double spacing = 0.5 * (c.spacing[i] + c.spacing[j]);
            worst = std::max(worst, glm::distance(velocity[i], velocity[j]) * dt / spacing);
        }
    }
    return worst;
}

bool ContourTracker::advect(const Flow& flow, double t, double dt)
{
    {
        const PhaseClock::Scope timing(m_clock, Phase::Advect);
        for (Contour& c : m_contours) {
            c.previous = c.positions;
            for (std::size_t i = 0; i < c.positions.size(); ++i)
                c.positions[i] = rungeKutta4(flow, c.previous[i], t, dt);
            requireFinite(c);
        }
    }
    return refineAll({[&flow, t, dt](Vec2 p) { return rungeKutta4(flow, p, t, dt); }, {}, 0.0}, flow, t + dt);
}

std::size_t ContourTracker::cutPinches()
{
    const std::size_t cuts = sim::cutPinches(m_contours, m_pinchGrid);
    if (cuts > 0) {
        m_vertexCount = 0;
        for (const Contour& c : m_contours)
            m_vertexCount += c.positions.size();
    }
    return cuts;
}

ExactMotion exactMotion(const ExactMap& map, double chordTolerance)
{
    return {[&map](Vec2 p) { return mapped(map, p); }, [&map](Vec2 a, Vec2 b) { return creaseCrossing(map, a, b); },
            chordTolerance, true};
}

ExactMotion exactMotion(const DropPush& push, double chordTolerance)
{
    return {push, {}, chordTolerance};
}

bool ContourTracker::drop(const DropPush& push, const Flow& flow, double t)
{
    return applyMotion(exactMotion(push, m_settings.chordTolerance), flow, t, true);
}

bool ContourTracker::applyMap(const ExactMap& map, const Flow& flow, double t)
{
    return applyMotion(exactMotion(map, m_settings.chordTolerance), flow, t);
}

bool ContourTracker::applyMotion(const ExactMotion& motion, const Flow& flow, double t, bool cutFirst)
{
    for (Contour& c : m_contours) {
        c.previous = c.positions;
        for (std::size_t i = 0; i < c.positions.size(); ++i)
            c.positions[i] = motion.map(c.previous[i]);
        requireFinite(c);
    }
    // A drop's push can press a layer of one contour within a float spacing, its two sides'
    // vertices interleaved, and the refinement's removals there crossed them (bouquet seed 11 on
    // OpenCL, docs/method.md): its crossed chords are split and such layers cut first. Not after a
    // map, whose inverse must undo it.
    if (cutFirst) {
        {
            const PhaseClock::Scope timing(m_clock, Phase::Split);
            m_vertexCount += splitCrossedChords(m_contours, motion, false);
        }
        const PhaseClock::Scope timing(m_clock, Phase::Pinches);
        cutPinches();
    }
    return refineAll(motion, flow, t);
}

bool ContourTracker::refineAll(const ExactMotion& motion, const Flow& flow, double t)
{
    computeSpacing(m_contours, flow, t, m_settings, m_grid, m_clock);
    {
        const PhaseClock::Scope timing(m_clock, Phase::Collapse);
        m_vertexGrid.build(m_contours, m_settings.maxSpacing);
    }
    bool withinBudget = true;
    std::size_t total = m_vertexCount;
    for (Contour& c : m_contours) {
        total -= c.positions.size();
        const std::size_t budget = m_settings.maxVertices > total ? m_settings.maxVertices - total : 0;
        withinBudget = refine(c, motion, budget) && withinBudget;
        requireFinite(c);  // split and recentred vertices come from the motion too
        total += c.positions.size();
    }
    if (motion.chordTolerance > 0.0) {  // an exact motion: its curves do not cross, nor must its chords
        const PhaseClock::Scope timing(m_clock, Phase::Split);
        total += splitCrossedChords(m_contours, motion, false);
    }
    m_vertexCount = total;
    if (m_settings.areaCorrection)
        correctAreas();
    return withinBudget;
}

void ContourTracker::correctAreas()
{
    const PhaseClock::Scope timing(m_clock, Phase::Area);
    m_grid.build(m_contours, m_settings.proximityRadius(), m_settings.proximityCell());
    std::vector<bool> held;
    for (std::size_t k = 0; k < m_contours.size(); ++k) {
        Contour& c = m_contours[k];
        held.resize(c.positions.size());
        for (std::size_t i = 0; i < held.size(); ++i)
            held[i] = m_grid.nearestOtherPart(k, i) < m_settings.areaHoldDistance();
        correctArea(c.positions, c.targetArea, m_settings.minSpacing(), held, m_settings.areaCorrectionStep());
    }
}

bool ContourTracker::refine(Contour& contour, const ExactMotion& motion, std::size_t budget)
{
    // Split and collapse alternate until neither changes anything: a collapse can leave a long edge
    // and a split a short one, and a few rounds settle both. Should a contour still oscillate after
    // maxRounds, a last split pass keeps the upper bound, which topology depends on.
    constexpr int maxRounds = 16;
    Ring ring(contour, m_settings.timeRewinding, m_vertexGrid);
    int start = 0;
    bool withinBudget = true;
    bool settled = false;
    for (int round = 0; round < maxRounds && withinBudget && !settled; ++round) {
        bool changed = false;
        {
            const PhaseClock::Scope timing(m_clock, Phase::Split);
            withinBudget = splitPass(ring, start, motion, budget, changed);
        }
        const PhaseClock::Scope timing(m_clock, Phase::Collapse);
        start = collapsePass(ring, start, motion, changed);
        settled = !changed;
    }
    if (!settled && withinBudget) {
        const PhaseClock::Scope timing(m_clock, Phase::Split);
        bool changed = false;
        withinBudget = splitPass(ring, start, motion, budget, changed);
    }
    ring.writeTo(contour, start);
    return withinBudget;
}

} // namespace vf::sim
