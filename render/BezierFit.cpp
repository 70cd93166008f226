#include "render/BezierFit.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace vf::render {
namespace {

using sim::Vec2;

// A vertex is a corner, where the curve may kink, when its edges turn by more than 30° and it
// stands out of its neighbours' chord by more than the tolerance. The second test keeps
// vertex-scale jitter (smaller than anything the fit must honour) from chopping smooth contours
// into short pieces; a corner that fails it is rounded off within the tolerance, invisibly.
constexpr double kCornerCosine = 0.8660254037844387; // cos 30°

// Newton reparameterisation pays off until the first fit is far off; beyond this multiple of the
// tolerance the piece is split straight away, which also keeps the error scan short on huge pieces.
constexpr double kNewtonRange = 16.0;
constexpr int kNewtonIterations = 10;
constexpr double kNewtonProgress = 0.95; // each step must cut the error by 5% to go on

// How closely the curve is compared with each polyline edge across the edge's parameter span
// (checking only the vertices, as Schneider does, would let the curve bulge between them).
// While searching, the span's midpoint is enough to steer; a cubic is accepted only after a
// thorough scan, in which a span that comes near the tolerance has its worst sample polished by
// a golden-section search, since a plain sample can sit a few percent below the true peak.
enum class Scan { Quick, Thorough };
constexpr int kSpanSamples = 8; // thorough scan
constexpr double kPolishAbove = 0.5;
constexpr int kPolishIterations = 16;

// What the golden-section search may still miss is far below this.
constexpr double kHeadroom = 0.99;

using Cubic = std::array<Vec2, 4>;

Vec2 pointAt(const Cubic& c, double t)
{
    const double s = 1 - t;
    return c[0] * (s * s * s) + c[1] * (3 * s * s * t) + c[2] * (3 * s * t * t) + c[3] * (t * t * t);
}

Vec2 firstDerivativeAt(const Cubic& c, double t)
{
    const double s = 1 - t;
    return ((c[1] - c[0]) * (s * s) + (c[2] - c[1]) * (2 * s * t) + (c[3] - c[2]) * (t * t)) * 3.0;
}

Vec2 secondDerivativeAt(const Cubic& c, double t)
{
    return ((c[2] - c[1] * 2.0 + c[0]) * (1 - t) + (c[3] - c[2] * 2.0 + c[1]) * t) * 6.0;
}

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

double distanceToSegment(Vec2 p, Vec2 a, Vec2 b)
{
    const Vec2 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    const double t = length2 > 0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return glm::distance(p, a + ab * t);
}

std::vector<Vec2> distinctVertices(const sim::Polygon& polygon)
{
    std::vector<Vec2> points;
    points.reserve(polygon.size());
    for (const Vec2& p : polygon) {
        if (points.empty() || p != points.back())
            points.push_back(p);
    }
    while (points.size() > 1 && points.back() == points.front())
        points.pop_back();
    return points;
}

bool isCorner(Vec2 previous, Vec2 point, Vec2 next, double tolerance)
{
    const Vec2 in = glm::normalize(point - previous);
    const Vec2 out = glm::normalize(next - point);
    return glm::dot(in, out) < kCornerCosine && distanceToSegment(point, previous, next) > tolerance;
}

std::vector<std::size_t> findCorners(const std::vector<Vec2>& points, double tolerance)
{
    const std::size_t n = points.size();
    std::vector<std::size_t> corners;
    for (std::size_t i = 0; i < n; ++i) {
        if (isCorner(points[(i + n - 1) % n], points[i], points[(i + 1) % n], tolerance))
            corners.push_back(i);
    }
    return corners;
}

// A run of the loop fitted as a unit. Both tangents point into the piece (Schneider's t̂1, t̂2).
struct Piece {
    std::size_t first;
    std::size_t last;
    Vec2 tangentFirst;
    Vec2 tangentLast;
};

class Fitter {
public:
    // `loop` repeats its first vertex at the end, so pieces are plain index ranges.
    Fitter(const std::vector<Vec2>& loop, double tolerance) : m_loop(loop), m_tolerance(tolerance) {}

    void fit(const Piece& whole, std::vector<PathSegment>& out);
    Vec2 tangentAt(std::size_t i) const;

private:
    bool fitsLine(const Piece& piece) const;
    std::optional<Cubic> fitCubic(const Piece& piece);
    void parameterizeByChordLength(const Piece& piece);
    Cubic leastSquaresCubic(const Piece& piece) const;
    double maxError(const Piece& piece, const Cubic& cubic, double giveUpAbove, Scan scan) const;
    double spanError(const Cubic& cubic, double u0, double u1, Vec2 a, Vec2 b) const;
    void reparameterize(const Piece& piece, const Cubic& cubic);
    std::pair<Piece, Piece> splitAt(const Piece& piece, std::size_t i) const;

    const std::vector<Vec2>& m_loop;
    double m_tolerance;
    std::vector<double> m_u; // curve parameter of each point of the piece being fitted
};

// A piece that fits neither a line nor a cubic is halved. Schneider splits at the point of worst
// error instead; halving measured fewer segments on our contours (4 instead of 8 to 16 cubics on
// a finely sampled circle) and keeps the work O(n log n) however long the contour is.
// An explicit stack rather than recursion, so no contour can overflow the call stack.
void Fitter::fit(const Piece& whole, std::vector<PathSegment>& out)
{
    std::vector<Piece> pending{whole};
    while (!pending.empty()) {
        const Piece piece = pending.back();
        pending.pop_back();
        if (fitsLine(piece)) {
            out.push_back({true, {}, {}, m_loop[piece.last]});
            continue;
        }
        if (m_loop[piece.first] != m_loop[piece.last]) { // a cubic cannot close a loop by itself
            if (const std::optional<Cubic> cubic = fitCubic(piece)) {
                out.push_back({false, (*cubic)[1], (*cubic)[2], (*cubic)[3]});
                continue;
            }
        }
        const auto [left, right] = splitAt(piece, piece.first + (piece.last - piece.first) / 2);
        pending.push_back(right);
        pending.push_back(left);
    }
}

// Derivative of the parabola through the vertex and its neighbours, parameterised by chord
// length: unlike Schneider's plain average it stays accurate where the spacing is uneven.
Vec2 Fitter::tangentAt(std::size_t i) const
{
    const std::size_t n = m_loop.size() - 1;
    const Vec2 previous = m_loop[i == 0 ? n - 1 : i - 1];
    const Vec2 next = m_loop[i == n ? 1 : i + 1];
    const Vec2 in = m_loop[i] - previous;
    const Vec2 out = next - m_loop[i];
    const double a = glm::length(in);
    const double b = glm::length(out);
    const Vec2 tangent = in * (b / (a * (a + b))) + out * (a / (b * (a + b)));
    const double length = glm::length(tangent);
    return length > 0 ? tangent / length : out / b;
}

// A straight run becomes one line segment: exact for drawn shapes, and cheaper than a cubic.
// Monotone projections make the chord and the polyline lie within tolerance of each other.
bool Fitter::fitsLine(const Piece& piece) const
{
    if (piece.last - piece.first == 1)
        return true;
    const Vec2 a = m_loop[piece.first];
    const Vec2 chord = m_loop[piece.last] - a;
    const double length2 = glm::dot(chord, chord);
    if (length2 == 0)
        return false;
    const double length = std::sqrt(length2);
    double previous = 0;
    for (std::size_t i = piece.first + 1; i < piece.last; ++i) {
        const Vec2 v = m_loop[i] - a;
        const double along = glm::dot(v, chord) / length2;
        if (along < previous || along > 1 || std::abs(cross(v, chord)) > m_tolerance * length)
            return false;
        previous = along;
    }
    return true;
}

std::optional<Cubic> Fitter::fitCubic(const Piece& piece)
{
    const double target = kHeadroom * m_tolerance;
    const double hopeless = kNewtonRange * m_tolerance;
    parameterizeByChordLength(piece);
    Cubic cubic = leastSquaresCubic(piece);
    double error = maxError(piece, cubic, hopeless, Scan::Quick);
    for (int k = 0; k < kNewtonIterations && error > target && error <= hopeless; ++k) {
        reparameterize(piece, cubic);
        const Cubic next = leastSquaresCubic(piece);
        const double nextError = maxError(piece, next, hopeless, Scan::Quick);
        if (nextError > kNewtonProgress * error)
            break; // stalled: on noisy input more steps rarely help, and they cost a full scan each
        cubic = next;
        error = nextError;
    }
    if (error <= target && maxError(piece, cubic, target, Scan::Thorough) <= target)
        return cubic;
    return std::nullopt;
}

void Fitter::parameterizeByChordLength(const Piece& piece)
{
    m_u.assign(piece.last - piece.first + 1, 0.0);
    for (std::size_t i = piece.first + 1; i <= piece.last; ++i)
        m_u[i - piece.first] = m_u[i - piece.first - 1] + glm::distance(m_loop[i], m_loop[i - 1]);
    const double total = m_u.back();
    for (double& u : m_u)
        u /= total;
}

// Schneider's least-squares lengths of the two tangent handles, with his fallback of a third of
// the chord when the system is singular or a handle would point backwards. Handles longer than
// the chord are refused too: they make near-loops that race between the error samples.
Cubic Fitter::leastSquaresCubic(const Piece& piece) const
{
    const Vec2 p0 = m_loop[piece.first];
    const Vec2 p3 = m_loop[piece.last];
    double c00 = 0, c01 = 0, c11 = 0, x0 = 0, x1 = 0;
    for (std::size_t i = piece.first; i <= piece.last; ++i) {
        const double u = m_u[i - piece.first];
        const double s = 1 - u;
        const double b0 = s * s * s, b1 = 3 * s * s * u, b2 = 3 * s * u * u, b3 = u * u * u;
        const Vec2 a1 = piece.tangentFirst * b1;
        const Vec2 a2 = piece.tangentLast * b2;
        const Vec2 rest = m_loop[i] - (p0 * (b0 + b1) + p3 * (b2 + b3));
        c00 += glm::dot(a1, a1);
        c01 += glm::dot(a1, a2);
        c11 += glm::dot(a2, a2);
        x0 += glm::dot(a1, rest);
        x1 += glm::dot(a2, rest);
    }
    const double chord = glm::distance(p0, p3);
    double alpha1 = chord / 3;
    double alpha2 = chord / 3;
    const double det = c00 * c11 - c01 * c01;
    if (std::abs(det) > 1e-12 * c00 * c11) {
        const double a1 = (x0 * c11 - x1 * c01) / det;
        const double a2 = (c00 * x1 - c01 * x0) / det;
        if (a1 > 1e-6 * chord && a2 > 1e-6 * chord && a1 <= chord && a2 <= chord) {
            alpha1 = a1;
            alpha2 = a2;
        }
    }
    return {p0, p0 + piece.tangentFirst * alpha1, p3 + piece.tangentLast * alpha2, p3};
}

// Two-sided: each vertex to its curve point, and the curve to the polyline edge it spans. Both
// over-estimate the true distances, so passing the check is a guarantee. Stops early once the
// answer exceeds `giveUpAbove`, when only "too far" matters.
double Fitter::maxError(const Piece& piece, const Cubic& cubic, double giveUpAbove, Scan scan) const
{
    double worst = 0;
    for (std::size_t j = piece.first; j < piece.last && worst <= giveUpAbove; ++j) {
        const double u0 = m_u[j - piece.first];
        const double u1 = m_u[j + 1 - piece.first];
        const Vec2 a = m_loop[j];
        const Vec2 b = m_loop[j + 1];
        const double span = scan == Scan::Quick ? distanceToSegment(pointAt(cubic, (u0 + u1) / 2), a, b)
                                                : spanError(cubic, u0, u1, a, b);
        worst = std::max({worst, glm::distance(pointAt(cubic, u1), b), span});
    }
    return worst;
}

double Fitter::spanError(const Cubic& cubic, double u0, double u1, Vec2 a, Vec2 b) const
{
    const auto error = [&](double t) { return distanceToSegment(pointAt(cubic, t), a, b); };
    const double step = (u1 - u0) / kSpanSamples;
    double worst = 0;
    int worstK = 0;
    for (int k = 1; k < kSpanSamples; ++k) {
        const double e = error(u0 + k * step);
        if (e > worst) {
            worst = e;
            worstK = k;
        }
    }
    if (worst <= kPolishAbove * m_tolerance)
        return worst;
    constexpr double kGolden = 0.6180339887498949; // (√5 - 1) / 2
    double lo = u0 + (worstK - 1) * step;
    double hi = u0 + (worstK + 1) * step;
    for (int i = 0; i < kPolishIterations; ++i) {
        const double left = hi - kGolden * (hi - lo);
        const double right = lo + kGolden * (hi - lo);
        if (error(left) > error(right))
            hi = right;
        else
            lo = left;
    }
    return std::max(worst, error((lo + hi) / 2));
}

// One Newton–Raphson step per point towards the parameter of its nearest curve point.
void Fitter::reparameterize(const Piece& piece, const Cubic& cubic)
{
    for (std::size_t i = piece.first + 1; i < piece.last; ++i) {
        double& u = m_u[i - piece.first];
        const Vec2 offset = pointAt(cubic, u) - m_loop[i];
        const Vec2 d1 = firstDerivativeAt(cubic, u);
        const double denominator = glm::dot(d1, d1) + glm::dot(offset, secondDerivativeAt(cubic, u));
        if (denominator != 0)
            u = std::clamp(u - glm::dot(offset, d1) / denominator, 0.0, 1.0);
    }
}

std::pair<Piece, Piece> Fitter::splitAt(const Piece& piece, std::size_t i) const
{
    const Vec2 tangent = tangentAt(i);
    return {Piece{piece.first, i, piece.tangentFirst, -tangent},
            Piece{i, piece.last, tangent, piece.tangentLast}};
}

FittedContour straightContour(const std::vector<Vec2>& points)
{
    FittedContour contour{points.front(), {}};
    if (points.size() > 1) {
        for (std::size_t i = 1; i < points.size(); ++i)
            contour.segments.push_back({true, {}, {}, points[i]});
        contour.segments.push_back({true, {}, {}, points.front()});
    }
    return contour;
}

} // namespace

FittedContour fitClosedPolygon(const sim::Polygon& polygon, double tolerance)
{
    std::vector<Vec2> loop = distinctVertices(polygon);
    if (loop.empty())
        return {};
    if (loop.size() < 3)
        return straightContour(loop);

    // Start the loop at a corner, so every piece between corners is a plain index range.
    std::vector<std::size_t> corners = findCorners(loop, tolerance);
    if (!corners.empty()) {
        const std::size_t offset = corners.front();
        std::rotate(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(offset), loop.end());
        for (std::size_t& c : corners)
            c -= offset;
    }
    const std::size_t n = loop.size();
    loop.push_back(loop.front());

    FittedContour contour{loop.front(), {}};
    Fitter fitter(loop, tolerance);
    if (corners.empty()) {
        const Vec2 tangent = fitter.tangentAt(0);
        fitter.fit({0, n, tangent, -tangent}, contour.segments);
        return contour;
    }
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const std::size_t first = corners[k];
        const std::size_t last = k + 1 < corners.size() ? corners[k + 1] : n;
        fitter.fit({first, last, glm::normalize(loop[first + 1] - loop[first]),
                    glm::normalize(loop[last - 1] - loop[last])},
                   contour.segments);
    }
    return contour;
}

} // namespace vf::render
