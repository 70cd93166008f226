#pragma once
// The printed page an export maps the canvas onto: shared by every writer so they agree on size.
#include "model/Drawing.h"
#include "render/Exporter.h"

namespace vf::render {

struct Page {
    double width = 0;          // points (1/72 in)
    double height = 0;         // points; keeps the canvas aspect
    double pointsPerUnit = 0;  // canvas units → points, the same along both axes
};

inline Page pageFor(const model::Drawing& drawing, const ExportOptions& options)
{
    const double scale = options.pageWidth / drawing.width;
    return {options.pageWidth, drawing.height * scale, scale};
}

} // namespace vf::render
