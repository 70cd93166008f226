#pragma once
// The printed page an export maps the canvas onto: shared by every writer so they agree on size.
#include "model/Drawing.h"
#include "render/Exporter.h"

#include <algorithm>

namespace vf::render {

struct Page {
    double width = 0;          // points (1/72 in)
    double height = 0;         // points
    double pointsPerUnit = 0;  // canvas units → points, the same along both axes
    // Where the canvas starts on the page, points: 0 when the page has the canvas's aspect, else
    // the margins that centre the canvas, scaled to fit, on the page.
    double left = 0;
    double top = 0;
};

inline Page pageFor(const model::Drawing& drawing, const ExportOptions& options)
{
    const double height = options.pageHeight > 0 ? options.pageHeight : drawing.height * options.pageWidth / drawing.width;
    const double scale = std::min(options.pageWidth / drawing.width, height / drawing.height);
    return {options.pageWidth, height, scale, (options.pageWidth - drawing.width * scale) / 2,
            (height - drawing.height * scale) / 2};
}

} // namespace vf::render
