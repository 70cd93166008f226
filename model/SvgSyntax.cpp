#include "model/SvgSyntax.h"

#include <cmath>
#include <numbers>

namespace vf::model::svg {
namespace {

using namespace Qt::StringLiterals;

bool isSpace(QChar c) { return c == u' ' || c == u'\t' || c == u'\n' || c == u'\r' || c == u'\f'; }
bool isDigit(QChar c) { return c >= u'0' && c <= u'9'; }

// Skips digits from i; returns the index after them.
qsizetype skipDigits(QStringView text, qsizetype i)
{
    while (i < text.size() && isDigit(text[i]))
        ++i;
    return i;
}

QTransform matrix(double a, double b, double c, double d, double e, double f)
{
    // SVG's matrix(a b c d e f) maps x' = a·x + c·y + e, y' = b·x + d·y + f; so does Qt's
    // QTransform(m11 = a, m12 = b, m21 = c, m22 = d, dx = e, dy = f).
    return QTransform(a, b, c, d, e, f);
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// One transform function by name from its argument list; nullopt when the count does not fit.
std::optional<QTransform> transformFunction(QStringView name, const std::vector<double>& v)
{
    const std::size_t n = v.size();
    if (name == u"matrix" && n == 6)
        return matrix(v[0], v[1], v[2], v[3], v[4], v[5]);
    if (name == u"translate" && (n == 1 || n == 2))
        return matrix(1, 0, 0, 1, v[0], n == 2 ? v[1] : 0.0);
    if (name == u"scale" && (n == 1 || n == 2))
        return matrix(v[0], 0, 0, n == 2 ? v[1] : v[0], 0, 0);
    if (name == u"rotate" && (n == 1 || n == 3)) {
        const double c = std::cos(radians(v[0])), s = std::sin(radians(v[0]));
        const double cx = n == 3 ? v[1] : 0.0, cy = n == 3 ? v[2] : 0.0;
        // translate(cx, cy) rotate(a) translate(-cx, -cy)
        return matrix(c, s, -s, c, cx - c * cx + s * cy, cy - s * cx - c * cy);
    }
    if (name == u"skewX" && n == 1)
        return matrix(1, 0, std::tan(radians(v[0])), 1, 0, 0);
    if (name == u"skewY" && n == 1)
        return matrix(1, std::tan(radians(v[0])), 0, 1, 0, 0);
    return std::nullopt;
}

// A colour channel of rgb(): 0..255, or a percentage of 255; clamped as CSS does.
std::optional<int> channel(QStringView text)
{
    text = text.trimmed();
    const bool percent = text.endsWith(u'%');
    const std::optional<double> value = parseNumber(percent ? text.chopped(1) : text);
    if (!value)
        return std::nullopt;
    return static_cast<int>(std::lround(std::clamp(percent ? *value / 100.0 * 255.0 : *value, 0.0, 255.0)));
}

} // namespace

void Scanner::skipSpace()
{
    while (!atEnd() && isSpace(m_text[m_pos]))
        ++m_pos;
}

void Scanner::skipSeparator()
{
    skipSpace();
    if (peek() == u',') {
        ++m_pos;
        skipSpace();
    }
}

std::optional<double> Scanner::number()
{
    // sign? (digits ('.' digits?)? | '.' digits) (('e' | 'E') sign? digits)?
    qsizetype i = m_pos;
    if (i < m_text.size() && (m_text[i] == u'+' || m_text[i] == u'-'))
        ++i;
    const qsizetype mantissa = i;
    i = skipDigits(m_text, i);
    bool digits = i > mantissa;
    if (i < m_text.size() && m_text[i] == u'.') {
        const qsizetype fraction = i + 1;
        i = skipDigits(m_text, fraction);
        digits = digits || i > fraction;
    }
    if (!digits)
        return std::nullopt;
    if (i < m_text.size() && (m_text[i] == u'e' || m_text[i] == u'E')) {
        qsizetype e = i + 1;
        if (e < m_text.size() && (m_text[e] == u'+' || m_text[e] == u'-'))
            ++e;
        const qsizetype end = skipDigits(m_text, e);
        if (end > e)  // else the 'e' belongs to what follows (a unit such as "em")
            i = end;
    }
    bool ok = false;
    const double value = m_text.sliced(m_pos, i - m_pos).toDouble(&ok);
    if (!ok || !std::isfinite(value))
        return std::nullopt;
    m_pos = i;
    return value;
}

std::optional<bool> Scanner::flag()
{
    if (peek() != u'0' && peek() != u'1')
        return std::nullopt;
    const bool value = peek() == u'1';
    ++m_pos;
    return value;
}

QString Scanner::where() const
{
    if (atEnd())
        return u"at the end"_s;
    return u"at character %1: %2"_s.arg(m_pos + 1).arg(quoted(m_text.sliced(m_pos)));
}

QString quoted(QStringView text)
{
    constexpr qsizetype kMaxShown = 24;
    return u'"' + (text.size() > kMaxShown ? text.first(kMaxShown).toString() + u"…"_s : text.toString()) + u'"';
}

std::optional<double> parseNumber(QStringView text)
{
    Scanner scanner(text);
    scanner.skipSpace();
    const std::optional<double> value = scanner.number();
    scanner.skipSpace();
    return scanner.atEnd() ? value : std::nullopt;
}

std::optional<std::vector<double>> parseNumberList(QStringView text, QString& reason)
{
    std::vector<double> values;
    Scanner scanner(text);
    for (scanner.skipSpace(); !scanner.atEnd(); scanner.skipSeparator()) {
        const std::optional<double> value = scanner.number();
        if (!value) {
            reason = u"expected a number "_s + scanner.where();
            return std::nullopt;
        }
        values.push_back(*value);
    }
    return values;
}

std::optional<double> parseLength(QStringView text, QString& reason)
{
    const QStringView trimmed = text.trimmed();
    const std::optional<double> value = parseNumber(trimmed.endsWith(u"px") ? trimmed.chopped(2) : trimmed);
    if (!value)
        reason = u"%1 is not a length in user units (a number, optionally with \"px\")"_s.arg(quoted(text));
    return value;
}

std::optional<QTransform> parseTransform(QStringView text, QString& reason)
{
    QTransform result;
    // Function by function: name '(' numbers ')'.
    qsizetype i = 0;
    const auto fail = [&](const QString& what) {
        reason = u"%1 in transform %2"_s.arg(what, quoted(text));
        return std::nullopt;
    };
    while (true) {
        while (i < text.size() && (isSpace(text[i]) || text[i] == u','))
            ++i;
        if (i == text.size())
            return result;
        const qsizetype open = text.indexOf(u'(', i);
        const qsizetype close = open < 0 ? -1 : text.indexOf(u')', open);
        if (close < 0)
            return fail(u"expected name(numbers)"_s);
        const QStringView name = text.sliced(i, open - i).trimmed();
        QString listReason;
        const auto arguments = parseNumberList(text.sliced(open + 1, close - open - 1), listReason);
        if (!arguments)
            return fail(listReason);
        const std::optional<QTransform> function = transformFunction(name, *arguments);
        if (!function)
            return fail(u"%1 with %2 numbers is not a transform"_s.arg(quoted(name)).arg(arguments->size()));
        // Qt maps row vectors (p·M), so the function further right, applied first, goes left.
        result = *function * result;
        i = close + 1;
    }
}

QColor parseColor(QStringView text)
{
    text = text.trimmed();
    if (text.startsWith(u"rgb(", Qt::CaseInsensitive) && text.endsWith(u')')) {
        const QList<QStringView> parts = text.sliced(4, text.size() - 5).split(u',');
        if (parts.size() != 3)
            return {};
        const auto r = channel(parts[0]), g = channel(parts[1]), b = channel(parts[2]);
        return r && g && b ? QColor(*r, *g, *b) : QColor();
    }
    // Qt reads #rgb, #rrggbb and the SVG colour names; #aarrggbb-style Qt extensions are not CSS.
    if (text.startsWith(u'#') && text.size() != 4 && text.size() != 7)
        return {};
    return QColor::fromString(text);
}

} // namespace vf::model::svg
