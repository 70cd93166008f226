#pragma once
// The small grammars inside SVG attribute values: numbers, number lists, lengths, transform lists
// and colours. Internal to SvgImport. Failures come back as an empty optional with a reason that
// quotes the offending text, for SvgImport's one-line error.
#include <QColor>
#include <QString>
#include <QStringView>
#include <QTransform>

#include <optional>
#include <vector>

namespace vf::model::svg {

// Reads SVG's number and separator grammar from a string, left to right. Numbers need no
// separators where the grammar is unambiguous: "1.5e-3-2.1.5" is 1.5e-3, -2.1, .5.
class Scanner {
public:
    explicit Scanner(QStringView text) : m_text(text) {}

    bool atEnd() const { return m_pos >= m_text.size(); }
    QChar peek() const { return atEnd() ? QChar() : m_text[m_pos]; }
    void advance() { ++m_pos; }
    void skipSpace();
    void skipSeparator();  // spaces with at most one comma
    std::optional<double> number();
    std::optional<bool> flag();  // an arc flag: a single 0 or 1, separators optional after it
    // The reason a read failed here: "at character N: "text…"" or "at the end".
    QString where() const;

private:
    QStringView m_text;
    qsizetype m_pos = 0;
};

// Quotes text for a message, cut short enough to keep the message one readable line.
QString quoted(QStringView text);

// A whole attribute value as one number, or as a list separated by spaces and commas.
std::optional<double> parseNumber(QStringView text);
std::optional<std::vector<double>> parseNumberList(QStringView text, QString& reason);

// A length in user units: a number, optionally with "px". Other units and percentages would need a
// viewport or a DPI we do not have here, so they are refused.
std::optional<double> parseLength(QStringView text, QString& reason);

// A transform list (matrix, translate, scale, rotate with optional centre, skewX, skewY) as one
// matrix in Qt's convention: mapping a point applies the rightmost transform of the list first.
std::optional<QTransform> parseTransform(QStringView text, QString& reason);

// A CSS colour: a name, #rgb, #rrggbb, rgb(r, g, b) with numbers or percentages. Invalid on failure.
QColor parseColor(QStringView text);

} // namespace vf::model::svg
