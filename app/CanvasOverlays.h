#pragma once
// What the canvas can draw over the ink (Canvas's overlay toggles), in device pixels.
#include "app/ContourLod.h"
#include "sim/FluidSolver.h"

#include <QPolygonF>

class QPainter;

namespace vf::app {

// The lines between the fluid's cells, where they are far enough apart to tell cells apart.
void paintGrid(QPainter& painter, const sim::MacVelocity& field, const PixelMapping& toDevice,
               const QRectF& visible, double devicePixelRatio);

// Arrows on a lattice fixed on screen (so their density does not change with the zoom), each the
// velocity sampled at its foot, scaled so the fastest reaches the next lattice point.
void paintVelocity(QPainter& painter, const sim::MacVelocity& field, const PixelMapping& toDevice,
                   const QRectF& visible, double devicePixelRatio);

// The vertices as small dots (the paper's Fig. 3).
void paintVertexDots(QPainter& painter, const QPolygonF& dots, double devicePixelRatio);

} // namespace vf::app
