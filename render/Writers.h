#pragma once
// The format writers behind exportDrawing. Each writes one whole file into `out` and returns an
// empty string or what went wrong (without the path; the caller owns the file and names it).
// They expect a drawing and options already checked by exportDrawing.
#include "model/Drawing.h"
#include "render/Exporter.h"

#include <QFileInfo>
#include <QIODevice>
#include <QImage>
#include <QString>

#include <array>
#include <cstddef>

namespace vf::render {

// The entry of `formats` (each with a `suffix`, lower case) whose suffix is the path's, or null.
template <typename Format, std::size_t N>
const Format* formatBySuffix(const std::array<Format, N>& formats, const QString& path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    for (const Format& format : formats)
        if (suffix == QLatin1String(format.suffix))
            return &format;
    return nullptr;
}

// Writers trust their input; everything they could choke on is turned away here, before a file is
// touched. Returns an empty string or what is wrong (without the path).
[[nodiscard]] QString checkExport(const model::Drawing& drawing, const ExportOptions& options);

[[nodiscard]] QString writeSvg(const model::Drawing& drawing, const ExportOptions& options, QIODevice& out);
[[nodiscard]] QString writePdf(const model::Drawing& drawing, const ExportOptions& options, QIODevice& out);
[[nodiscard]] QString writeEps(const model::Drawing& drawing, const ExportOptions& options, QIODevice& out);
[[nodiscard]] QString writePng(const model::Drawing& drawing, const ExportOptions& options, QIODevice& out);

// The picture writePng encodes (pngPixels in size, premultiplied ARGB); a null image when it is too
// large to allocate.
QImage paintedImage(const model::Drawing& drawing, const ExportOptions& options);

} // namespace vf::render
