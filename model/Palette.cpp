#include "model/Palette.h"

#include "model/AtomicFile.h"
#include "model/JsonFormat.h"

#include <QFile>
#include <QRegularExpression>

using namespace Qt::StringLiterals;

namespace vf::model {

namespace {

struct GplError {
    QString what;
};

// A name as the file holds it, on one line and without tabs (which separate fields): line breaks
// and tabs become spaces, and the ends are trimmed. Read names are cleaned the same way, so a
// palette written and read again is the same.
QString cleanName(QString name)
{
    for (QChar& c : name)
        if (c == u'\n' || c == u'\r' || c == u'\t')
            c = u' ';
    return name.trimmed();
}

// "R G B" and the name after them, as GIMP reads a colour line: three whole numbers separated by
// white space, the rest of the line (trimmed) the name.
PaletteColour colourLine(const QString& line)
{
    static const QRegularExpression pattern(u"^\\s*(\\S+)\\s+(\\S+)\\s+(\\S+)(?:\\s+(.*))?$"_s);
    const QRegularExpressionMatch match = pattern.match(line);
    if (!match.hasMatch())
        throw GplError{u"a colour line needs red, green and blue, 0 to 255, separated by spaces"_s};
    int channel[3];
    const char* const names[3] = {"red", "green", "blue"};
    for (int k = 0; k < 3; ++k) {
        bool ok = false;
        channel[k] = match.captured(k + 1).toInt(&ok);
        if (!ok || channel[k] < 0 || channel[k] > 255)
            throw GplError{u"%1 '%2' is not a whole number from 0 to 255"_s.arg(QLatin1String(names[k]), match.captured(k + 1))};
    }
    return {QColor(channel[0], channel[1], channel[2]), cleanName(match.captured(4))};
}

Palette readGpl(const QByteArray& bytes)
{
    QString text = QString::fromUtf8(bytes);
    if (text.startsWith(QChar(0xfeff)))  // a byte order mark, as some editors write
        text.remove(0, 1);
    const QStringList lines = text.split(u'\n');
    if (!lines.front().startsWith(u"GIMP Palette"_s))
        throw GplError{u"line 1: not a GIMP palette (the first line must be 'GIMP Palette')"_s};
    Palette palette;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QString line = QString(lines[i]).remove(u'\r');
        const QString trimmed = line.trimmed();
        const auto at = [i](const QString& what) { return GplError{u"line %1: %2"_s.arg(i + 1).arg(what)}; };
        try {
            if (trimmed.isEmpty() || trimmed.startsWith(u'#'))
                continue;
            if (trimmed.startsWith(u"Name:"_s)) {
                palette.name = cleanName(trimmed.mid(5));
            } else if (trimmed.startsWith(u"Columns:"_s)) {
                bool ok = false;
                palette.columns = trimmed.mid(8).trimmed().toInt(&ok);
                if (!ok || palette.columns < 0 || palette.columns > limits::maxPaletteColumns)
                    throw GplError{u"Columns must be a whole number from 0 to %1"_s.arg(limits::maxPaletteColumns)};
            } else {
                if (int(palette.colours.size()) == limits::maxPaletteColours)
                    throw GplError{u"more than %L1 colours"_s.arg(limits::maxPaletteColours)};
                palette.colours.push_back(colourLine(line));
            }
        } catch (const GplError& e) {
            throw at(e.what);
        }
    }
    return palette;
}

} // namespace

PaletteReadResult parseGpl(const QByteArray& bytes, const QString& sourceName)
{
    try {
        return {readGpl(bytes), {}};
    } catch (const GplError& e) {
        return {Palette(), json::oneLine(u"%1: %2"_s.arg(sourceName, e.what))};
    }
}

PaletteReadResult readPaletteFile(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {Palette(), json::oneLine(u"%1: cannot open: %2"_s.arg(path, file.errorString()))};
    if (file.size() > limits::maxPaletteBytes)
        return {Palette(), json::oneLine(u"%1: larger than a palette can be (%L2 bytes at most)"_s.arg(path).arg(limits::maxPaletteBytes))};
    const QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError)
        return {Palette(), json::oneLine(u"%1: cannot read: %2"_s.arg(path, file.errorString()))};
    return parseGpl(bytes, path);
}

QByteArray gplBytes(const Palette& palette)
{
    QByteArray out = "GIMP Palette\nName: " + cleanName(palette.name).toUtf8() + "\nColumns: " +
                     QByteArray::number(palette.columns) + "\n#\n";
    for (const PaletteColour& c : palette.colours) {
        const QColor rgb = c.colour.toRgb();
        out += QString::asprintf("%3d %3d %3d\t", rgb.red(), rgb.green(), rgb.blue()).toUtf8() + cleanName(c.name).toUtf8() + '\n';
    }
    return out;
}

QString writePaletteFile(const Palette& palette, const QString& path)
{
    const QByteArray bytes = gplBytes(palette);
    return saveAtomically(path, [&bytes](QIODevice& file) { return writeAll(file, bytes); });
}

const std::vector<Palette>& builtInPalettes()
{
    static const std::vector<Palette> palettes = [] {
        auto palette = [](const char* name, std::initializer_list<std::pair<const char*, QRgb>> colours) {
            Palette p{QString::fromUtf8(name), 4, {}};
            for (const auto& [colourName, rgb] : colours)
                p.colours.push_back({QColor::fromRgb(rgb), QString::fromUtf8(colourName)});
            return p;
        };
        return std::vector<Palette>{
            // Inks of Turkish ebru and European marbled papers: earth pigments, indigo, madder.
            palette("Classic marbling", {{"Prussian blue", 0x1d3557},
                                         {"Indigo", 0x2d4a74},
                                         {"Slate blue", 0x457b9d},
                                         {"Madder red", 0xe63946},
                                         {"Vermilion", 0xc2452d},
                                         {"Yellow ochre", 0xe9c46a},
                                         {"Burnt orange", 0xf4a261},
                                         {"Sienna", 0xe76f51},
                                         {"Verdigris", 0x2a9d8f},
                                         {"Deep teal", 0x264653},
                                         {"Aubergine", 0x8a3f7a},
                                         {"Lamp black", 0x1f1d1b}}),
            // Suminagashi: sumi ink in washes on water, with indigo and a red seal.
            palette("Sumi-nagashi", {{"Sumi", 0x1f1d1b},
                                     {"Dark wash", 0x4a4642},
                                     {"Mid wash", 0x7a756e},
                                     {"Pale wash", 0xb3ada4},
                                     {"Indigo", 0x2d4a74},
                                     {"Pale indigo", 0x5b8fb9},
                                     {"Seal red", 0xc2452d},
                                     {"Paper", 0xf4eee2}}),
        };
    }();
    return palettes;
}

} // namespace vf::model
