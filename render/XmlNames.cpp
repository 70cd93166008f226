#include "render/XmlNames.h"

namespace vf::render {
namespace {

bool isAsciiLetter(QChar c)
{
    return (c >= u'a' && c <= u'z') || (c >= u'A' && c <= u'Z');
}

bool isIdCharacter(QChar c)
{
    return isAsciiLetter(c) || (c >= u'0' && c <= u'9') || c == u'-' || c == u'_' || c == u'.';
}

} // namespace

QString sanitizedXmlId(const QString& name)
{
    QString id;
    id.reserve(name.size());
    for (const QChar c : name)
        id += isIdCharacter(c) ? c : QChar(u'_');
    if (id.isEmpty())
        return QStringLiteral("region");
    if (!isAsciiLetter(id.front()) && id.front() != u'_')
        id.prepend(QStringLiteral("region-"));
    return id;
}

QString UniqueXmlIds::claim(const QString& wanted)
{
    QString id = wanted;
    for (int suffix = 2; m_taken.contains(id); ++suffix)
        id = wanted + u'-' + QString::number(suffix);
    m_taken.insert(id);
    return id;
}

QString escapedXmlAttribute(const QString& text)
{
    QString escaped;
    escaped.reserve(text.size());
    for (const QChar c : text) {
        switch (c.unicode()) {
        case u'&': escaped += QStringLiteral("&amp;"); break;
        case u'<': escaped += QStringLiteral("&lt;"); break;
        case u'>': escaped += QStringLiteral("&gt;"); break;
        case u'"': escaped += QStringLiteral("&quot;"); break;
        // Attribute-value normalisation would turn literal whitespace into spaces.
        case u'\t': escaped += QStringLiteral("&#9;"); break;
        case u'\n': escaped += QStringLiteral("&#10;"); break;
        case u'\r': escaped += QStringLiteral("&#13;"); break;
        default:
            if (c.unicode() >= 0x20 && c.unicode() != 0xFFFE && c.unicode() != 0xFFFF)
                escaped += c;
        }
    }
    return escaped;
}

} // namespace vf::render
