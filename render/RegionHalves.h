#pragma once
// Cutting a region in two along a straight line, for readers that cannot take its whole outline
// at once (SvgWriter: libxml2's limit on one attribute value).
#include "model/Drawing.h"

#include <array>

namespace vf::render {

// The region cut at the median of its vertices along the axis over which they spread widest: each
// half holds every contour clipped to its side (Sutherland–Hodgman against a half-plane, which
// keeps the even-odd parity of every point on that side), so the halves filled one beside the
// other paint exactly the region. Each half has at most about half the vertices, plus two for
// each time a contour crosses the cut. Both halves keep the region's name, colour and visibility.
std::array<model::DrawnRegion, 2> cutInHalves(const model::DrawnRegion& region);

} // namespace vf::render
