#include "model/JsonFormat.h"

#include <cmath>

namespace vf::model::json {

using namespace Qt::StringLiterals;

QString quoted(const QString& text)
{
    constexpr qsizetype kMaxShown = 40;
    return u'"' + (text.size() > kMaxShown ? text.left(kMaxShown) + u"…"_s : text) + u'"';
}

QString describe(const QJsonValue& value)
{
    switch (value.type()) {
    case QJsonValue::Null: return u"null"_s;
    case QJsonValue::Bool: return value.toBool() ? u"true"_s : u"false"_s;
    case QJsonValue::Double: return u"the number %1"_s.arg(value.toDouble());
    case QJsonValue::String: return u"the string "_s + quoted(value.toString());
    case QJsonValue::Array: return u"an array"_s;
    case QJsonValue::Object: return u"an object"_s;
    case QJsonValue::Undefined: break;
    }
    return u"nothing"_s;
}

QJsonObject Field::object() const
{
    expectType(QJsonValue::Object, u"an object"_s);
    return m_value.toObject();
}

QJsonArray Field::array(qsizetype minSize, qsizetype maxSize) const
{
    expectType(QJsonValue::Array, u"an array"_s);
    const QJsonArray array = m_value.toArray();
    if (minSize == maxSize && array.size() != minSize)
        fail(u"must have exactly %1 elements, has %2"_s.arg(minSize).arg(array.size()));
    if (array.size() < minSize)
        fail(u"must have at least %1 elements, has %2"_s.arg(minSize).arg(array.size()));
    if (array.size() > maxSize)
        fail(u"must have at most %1 elements, has %2"_s.arg(maxSize).arg(array.size()));
    return array;
}

QString Field::string() const
{
    expectType(QJsonValue::String, u"a string"_s);
    return m_value.toString();
}

QString Field::name() const
{
    const QString text = string();
    if (text.trimmed().isEmpty())
        fail(u"must not be empty"_s);
    return text;
}

bool Field::boolean() const
{
    expectType(QJsonValue::Bool, u"true or false"_s);
    return m_value.toBool();
}

// JSON has no NaN or infinity literal and Qt refuses numbers that overflow ("NaN" as a string
// fails the type check), so the finiteness check guards against a future parser, not the file.
double Field::number() const
{
    expectType(QJsonValue::Double, u"a number"_s);
    const double value = m_value.toDouble();
    if (!std::isfinite(value))
        fail(u"must be a finite number"_s);
    return value;
}

double Field::number(double min, double max) const
{
    const double value = number();
    if (value < min || value > max)
        fail(u"must be in [%1, %2], is %3"_s.arg(min).arg(max).arg(value));
    return value;
}

double Field::nonNegative() const
{
    const double value = number();
    if (value < 0.0)
        fail(u"must not be negative, is %1"_s.arg(value));
    return value;
}

double Field::positive(double max) const
{
    const double value = number();
    if (value <= 0.0)
        fail(u"must be positive, is %1"_s.arg(value));
    if (value > max)
        fail(u"must be at most %1, is %2"_s.arg(max).arg(value));
    return value;
}

std::int64_t Field::integer(std::int64_t min, std::int64_t max) const
{
    const double value = number();
    if (std::floor(value) != value)
        fail(u"must be a whole number, is %1"_s.arg(value));
    if (value < static_cast<double>(min) || value > static_cast<double>(max))
        fail(u"must be in [%1, %2], is %3"_s.arg(min).arg(max).arg(value));
    return static_cast<std::int64_t>(value);
}

void Field::expectType(QJsonValue::Type type, const QString& wanted) const
{
    if (m_value.type() != type)
        fail(u"must be %1, not %2"_s.arg(wanted, describe(m_value)));
}

namespace {

int hexDigit(QChar c)
{
    if (c >= u'0' && c <= u'9') return c.unicode() - u'0';
    if (c >= u'a' && c <= u'f') return c.unicode() - u'a' + 10;
    if (c >= u'A' && c <= u'F') return c.unicode() - u'A' + 10;
    return -1;
}

} // namespace

QColor color(const Field& field)
{
    const QString text = field.string();
    const bool shapeOk = (text.size() == 7 || text.size() == 9) && text.startsWith(u'#');
    int channels[4] = {0, 0, 0, 255};
    for (qsizetype i = 1; shapeOk && i < text.size(); i += 2) {
        const int high = hexDigit(text[i]);
        const int low = hexDigit(text[i + 1]);
        if (high < 0 || low < 0)
            field.fail(u"must be \"#rrggbb\" or \"#rrggbbaa\" in hexadecimal, not %1"_s.arg(quoted(text)));
        channels[i / 2] = high * 16 + low;
    }
    if (!shapeOk)
        field.fail(u"must be \"#rrggbb\" or \"#rrggbbaa\", not %1"_s.arg(quoted(text)));
    return QColor(channels[0], channels[1], channels[2], channels[3]);
}

QString colorText(const QColor& color)
{
    const QString rgb = color.name(QColor::HexRgb);
    return color.alpha() == 255 ? rgb : rgb + u"%1"_s.arg(color.alpha(), 2, 16, QChar(u'0'));
}

QString location(const QByteArray& json, qsizetype offset)
{
    const QByteArray before = json.left(std::clamp<qsizetype>(offset, 0, json.size()));
    const qsizetype lineStart = before.lastIndexOf('\n') + 1;
    const qsizetype column = QString::fromUtf8(before.sliced(lineStart)).size() + 1;
    return u"%1:%2"_s.arg(before.count('\n') + 1).arg(column);
}

QString oneLine(QString text)
{
    for (QChar& c : text) {
        if (c.category() == QChar::Other_Control || c == QChar::LineSeparator || c == QChar::ParagraphSeparator)
            c = u' ';
    }
    return text;
}

} // namespace vf::model::json
