#include "model/SvgPathData.h"

#include "model/SvgSyntax.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace vf::model::svg {
namespace {

using namespace Qt::StringLiterals;

Segment line(Vec2 to) { return {Segment::Kind::Line, {}, {}, to, {}}; }
Segment cubic(Vec2 c1, Vec2 c2, Vec2 to) { return {Segment::Kind::Cubic, c1, c2, to, {}}; }

// A quadratic Bézier is exactly the cubic with controls 2/3 of the way to its control point.
Segment quadratic(Vec2 from, Vec2 control, Vec2 to)
{
    return cubic(from + 2.0 / 3.0 * (control - from), to + 2.0 / 3.0 * (control - to), to);
}

bool isCommand(QChar c) { return QStringView(u"MmLlHhVvCcSsQqTtAaZz").contains(c); }

// Walks the path data command by command, keeping SVG's current point and the last control
// points that S and T reflect.
class PathParser {
public:
    explicit PathParser(QStringView d) : m_scanner(d) {}

    std::optional<Outline> parse(QString& reason)
    {
        m_scanner.skipSpace();
        while (!m_scanner.atEnd()) {
            if (isCommand(m_scanner.peek())) {
                m_command = m_scanner.peek().toLatin1();
                m_scanner.advance();
            } else if (m_command == 0 || m_command == 'Z' || m_command == 'z') {
                reason = u"expected a command "_s + m_scanner.where();
                return std::nullopt;
            }
            if (m_outline.empty() && m_command != 'M' && m_command != 'm') {
                reason = u"path data must start with a moveto, not '%1'"_s.arg(QChar::fromLatin1(m_command));
                return std::nullopt;
            }
            if (!command()) {
                reason = u"bad arguments to '%1' "_s.arg(QChar::fromLatin1(m_command)) + m_scanner.where();
                return std::nullopt;
            }
            m_scanner.skipSeparator();
        }
        return std::move(m_outline);
    }

private:
    bool relative() const { return m_command >= 'a'; }

    std::optional<double> coordinate(double origin)
    {
        m_scanner.skipSeparator();
        const std::optional<double> value = m_scanner.number();
        return value ? std::optional(*value + (relative() ? origin : 0.0)) : std::nullopt;
    }
    std::optional<Vec2> point()
    {
        const auto x = coordinate(m_current.x);
        const auto y = x ? coordinate(m_current.y) : std::nullopt;
        return y ? std::optional(Vec2(*x, *y)) : std::nullopt;
    }
    std::optional<double> plain()
    {
        m_scanner.skipSeparator();
        return m_scanner.number();
    }
    std::optional<bool> flag()
    {
        m_scanner.skipSeparator();
        return m_scanner.flag();
    }

    // After Z, a drawing command continues from the closed subpath's start in a new subpath.
    void add(const Segment& segment, Vec2 to, char kind)
    {
        if (m_outline.empty() || m_closed) {
            m_outline.push_back({m_current, {}});
            m_closed = false;
        }
        m_outline.back().segments.push_back(segment);
        m_current = to;
        m_previousKind = kind;
    }

    bool lineTo(std::optional<Vec2> to, char kind)
    {
        if (!to)
            return false;
        add(line(*to), *to, kind);
        return true;
    }

    // Reads one set of the current command's arguments and adds its segment.
    bool command()
    {
        const char kind = static_cast<char>(m_command & ~0x20);  // upper case
        const Vec2 from = m_current;
        switch (kind) {
        case 'M': {
            const auto p = point();
            if (!p)
                return false;
            m_outline.push_back({*p, {}});
            m_closed = false;
            m_current = m_subpathStart = *p;
            m_previousKind = 'M';
            m_command = relative() ? 'l' : 'L';  // further pairs are implicit line-tos
            return true;
        }
        case 'Z':
            m_current = m_subpathStart;
            m_closed = true;
            m_previousKind = 'Z';
            return true;
        case 'L':
            return lineTo(point(), kind);
        case 'H': {
            const auto x = coordinate(from.x);
            return lineTo(x ? std::optional(Vec2(*x, from.y)) : std::nullopt, kind);
        }
        case 'V': {
            const auto y = coordinate(from.y);
            return lineTo(y ? std::optional(Vec2(from.x, *y)) : std::nullopt, kind);
        }
        case 'C': {
            const auto c1 = point(), c2 = c1 ? point() : std::nullopt, p = c2 ? point() : std::nullopt;
            if (!p)
                return false;
            add(cubic(*c1, *c2, *p), *p, kind);
            m_lastControl = *c2;
            return true;
        }
        case 'S': {
            const Vec2 c1 = m_previousKind == 'C' || m_previousKind == 'S' ? 2.0 * from - m_lastControl : from;
            const auto c2 = point(), p = c2 ? point() : std::nullopt;
            if (!p)
                return false;
            add(cubic(c1, *c2, *p), *p, kind);
            m_lastControl = *c2;
            return true;
        }
        case 'Q': {
            const auto q = point(), p = q ? point() : std::nullopt;
            if (!p)
                return false;
            add(quadratic(from, *q, *p), *p, kind);
            m_lastControl = *q;
            return true;
        }
        case 'T': {
            const Vec2 q = m_previousKind == 'Q' || m_previousKind == 'T' ? 2.0 * from - m_lastControl : from;
            const auto p = point();
            if (!p)
                return false;
            add(quadratic(from, q, *p), *p, kind);
            m_lastControl = q;
            return true;
        }
        case 'A': {
            const auto rx = plain(), ry = rx ? plain() : std::nullopt, angle = ry ? plain() : std::nullopt;
            const auto large = angle ? flag() : std::nullopt, sweep = large ? flag() : std::nullopt;
            const auto p = sweep ? point() : std::nullopt;
            if (!p)
                return false;
            if (const auto segment = arcSegment(from, {*rx, *ry}, *angle, *large, *sweep, *p))
                add(*segment, *p, kind);
            m_previousKind = kind;
            return true;
        }
        }
        return false;
    }

    Scanner m_scanner;
    Outline m_outline;
    char m_command = 0;
    char m_previousKind = 0;
    bool m_closed = false;
    Vec2 m_current{0.0}, m_subpathStart{0.0}, m_lastControl{0.0};
};

} // namespace

std::optional<Outline> parsePathData(QStringView d, QString& reason)
{
    return PathParser(d).parse(reason);
}

std::optional<Segment> arcSegment(Vec2 from, Vec2 radii, double rotationDegrees, bool largeArc, bool sweep, Vec2 to)
{
    if (from == to)
        return std::nullopt;
    double rx = std::abs(radii.x), ry = std::abs(radii.y);
    if (rx == 0.0 || ry == 0.0)
        return line(to);
    const double phi = rotationDegrees * std::numbers::pi / 180.0;
    const double c = std::cos(phi), s = std::sin(phi);
    // F.6.5.1: the midpoint difference in the ellipse's own axes.
    const Vec2 half = 0.5 * (from - to);
    const Vec2 p(c * half.x + s * half.y, -s * half.x + c * half.y);
    // F.6.6.2: radii too small to reach are scaled up just enough. `reach` is the square root of
    // the spec's Λ; the scaled radii come from the radii's ratio, which stays finite where the
    // reach itself overflows (radii far below the chord). Radii so large that the arc is within
    // 1e-9 of its chord make a line.
    const double reach = std::hypot(p.x / rx, p.y / ry);
    if (reach < 1e-9)
        return line(to);
    if (reach > 1.0) {
        const double aspect = rx / ry;
        rx = std::hypot(p.x, p.y * aspect);
        ry = std::hypot(p.x / aspect, p.y);
    }
    // F.6.5.2: the centre's distance, the spec's quotient divided through by rx²·ry² (= (1 − Λ)/Λ).
    const double lambda = std::min(reach, 1.0) * std::min(reach, 1.0);
    const double root = (largeArc == sweep ? -1.0 : 1.0) * std::sqrt((1.0 - lambda) / lambda);
    const Vec2 centerPrime(root * rx * p.y / ry, -root * ry * p.x / rx);
    const Vec2 center(c * centerPrime.x - s * centerPrime.y + 0.5 * (from.x + to.x),
                      s * centerPrime.x + c * centerPrime.y + 0.5 * (from.y + to.y));
    // F.6.5.5-6: start angle and sweep, on the unit circle of the ellipse's parameter.
    const Vec2 startUnit((p.x - centerPrime.x) / rx, (p.y - centerPrime.y) / ry);
    const Vec2 endUnit((-p.x - centerPrime.x) / rx, (-p.y - centerPrime.y) / ry);
    const double theta0 = std::atan2(startUnit.y, startUnit.x);
    double delta = std::atan2(endUnit.y, endUnit.x) - theta0;
    if (sweep && delta < 0.0)
        delta += 2.0 * std::numbers::pi;
    else if (!sweep && delta > 0.0)
        delta -= 2.0 * std::numbers::pi;
    Segment segment{Segment::Kind::Arc, {}, {}, to, {}};
    segment.arc = {center, rx * Vec2(c, s), ry * Vec2(-s, c), theta0, delta};
    const bool finite = std::isfinite(center.x) && std::isfinite(center.y) && std::isfinite(rx) && std::isfinite(ry) &&
                        std::isfinite(theta0) && std::isfinite(delta);
    return finite ? segment : line(to);
}

} // namespace vf::model::svg
