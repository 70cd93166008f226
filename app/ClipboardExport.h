#pragma once
// Edit > Copy as SVG: the picture on the clipboard for pasting into a vector editor.
#include "model/Drawing.h"

#include <QString>

namespace vf::app {

// Puts the drawing's SVG (default export options: Bézier curves, background) on the clipboard as
// "image/svg+xml" and, for editors that only take text, as text/plain. Needs a QGuiApplication.
// Returns an empty string, or one line saying why nothing was copied.
[[nodiscard]] QString copyAsSvg(const model::Drawing& drawing);

} // namespace vf::app
