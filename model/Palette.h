#pragma once
// Palettes of inks: the built-in ones and GIMP .gpl files, the palette format GIMP, Inkscape and
// Krita share (docs/palette-format.md). Reading refuses anything it would have to guess at, in one
// line naming the line of the file; writing follows GIMP's own layout.
#include <QByteArray>
#include <QColor>
#include <QString>

#include <vector>

namespace vf::model {

struct PaletteColour {
    QColor colour;  // opaque
    QString name;   // may be empty

    friend bool operator==(const PaletteColour&, const PaletteColour&) = default;
};

struct Palette {
    QString name;
    int columns = 0;  // how many swatches a row shows; 0: the reader's choice
    std::vector<PaletteColour> colours;

    friend bool operator==(const Palette&, const Palette&) = default;
};

struct PaletteReadResult {
    Palette palette;
    QString error;  // empty on success, else one line
    bool ok() const { return error.isEmpty(); }
};

namespace limits {
inline constexpr qint64 maxPaletteBytes = 8 << 20;
inline constexpr int maxPaletteColours = 65'536;
inline constexpr int maxPaletteColumns = 256;  // as GIMP
}

// A .gpl file's bytes; `sourceName` heads the error.
PaletteReadResult parseGpl(const QByteArray& bytes, const QString& sourceName);
PaletteReadResult readPaletteFile(const QString& path);

// GIMP's layout: the header, Name and Columns lines, then "R G B<tab>name" per colour, red, green
// and blue right-aligned in three places.
QByteArray gplBytes(const Palette& palette);
// Atomically, as every file the program writes; an empty string or one line.
[[nodiscard]] QString writePaletteFile(const Palette& palette, const QString& path);

// The palettes the app starts with: classic marbling inks, and the inks of sumi-nagashi.
const std::vector<Palette>& builtInPalettes();

} // namespace vf::model
