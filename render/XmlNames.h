#pragma once
// Region names end up in SVG as element ids and as attribute text. Ids must be unique XML names
// (NCName); we keep them ASCII so CSS selectors, scripts and every reader accept them, and keep the
// real name, verbatim, in inkscape:label.
#include <QSet>
#include <QString>

namespace vf::render {

// A valid NCName made from `name`: other characters become '_', and a name that does not start
// with a letter or '_' gets a "region-" prefix.
QString sanitizedXmlId(const QString& name);

class UniqueXmlIds {
public:
    // `wanted` if still free, else the first free of wanted-2, wanted-3, …
    QString claim(const QString& wanted);

private:
    QSet<QString> m_taken;
};

// Text safe inside a double-quoted attribute; characters XML 1.0 cannot carry are dropped.
QString escapedXmlAttribute(const QString& text);

} // namespace vf::render
