#pragma once
// One entry point for every export format; the format follows the file suffix.
#include "model/AtomicFile.h"
#include "model/Drawing.h"

#include <QString>

namespace vf::render {

struct ExportOptions {
    bool bezier = true;          // fit cubic Béziers (SVG/PDF/EPS); false writes vertices as they are
    double bezierTolerance = 0;  // canvas units; 0 picks the documented default
    double pageWidth = 576.0;    // points (1/72 in)
    double pageHeight = 0.0;     // points; 0: the canvas's aspect. Another aspect centres the canvas on the page
    double dpi = 150.0;          // PNG pixels per inch of the page
    bool background = true;      // paint the canvas background
};

// Writes `drawing` to `path` (.svg .pdf .eps .png), atomically: a temporary file renamed into
// place only when complete. Returns an empty string, or one line saying what went wrong.
[[nodiscard]] QString exportDrawing(const model::Drawing& drawing, const QString& path, const ExportOptions& options);
// The same into `batch`: the file is put in place only when the batch commits.
[[nodiscard]] QString exportDrawing(const model::Drawing& drawing, const QString& path, const ExportOptions& options,
                      model::FileBatch& batch);

bool isExportSuffix(const QString& path);

// The size of a PNG export in pixels, as doubles: sizes beyond what an image can hold are
// reported, not wrapped.
struct RasterSize {
    double width = 0;
    double height = 0;
};
RasterSize pngPixels(const model::Drawing& drawing, const ExportOptions& options);

} // namespace vf::render
