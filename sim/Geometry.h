#pragma once
// Plain polygon geometry shared by the engine, the document and the tests.
#include <glm/vec2.hpp>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace vf::sim {

using Vec2 = glm::dvec2;

// A closed contour: the last vertex connects back to the first. Canvas units, y down.
using Polygon = std::vector<Vec2>;
// A closed contour's vertices where they lie, such as a run of an array read back from a device.
using Outline = std::span<const Vec2>;

// The shoelace formula on the raw coordinates. Every contour the engine creates has positive area,
// which with y pointing down means the vertices run clockwise as seen on screen.
double signedArea(const Polygon& polygon);
double perimeter(const Polygon& polygon);

// How many times the polygon winds around p, counter-clockwise in raw coordinates positive.
int windingNumber(const Polygon& polygon, Vec2 p);

// For contours that do not cross: calls enclosedBy(inner, outer) for every pair where contour
// `outer` encloses contour `inner` (tested at inner's first vertex, bounding boxes first). Contours
// nested by the thousand pass every box, so the vertices visited are counted: past `budget` it
// stops and returns false.
bool visitEnclosures(const std::vector<Polygon>& contours, std::size_t budget,
                     const std::function<void(std::size_t inner, std::size_t outer)>& enclosedBy);

// The area the contours cover filled together with the even-odd rule, for contours that do not
// cross (a region's): each contour's area counts positive when as many others enclose it as an
// even number, negative when odd, so holes are subtracted.
double filledArea(const std::vector<Polygon>& contours);

// Splits every edge into equal pieces no longer than maxSpacing; the original vertices stay.
Polygon resample(const Polygon& polygon, double maxSpacing);

// A circle sampled with edges no longer than maxSpacing (at least 8 vertices), positive area.
Polygon circle(Vec2 center, double radius, double maxSpacing);

// An axis-aligned box of the canvas: where a search looks.
struct Window {
    Vec2 low, high;

    bool holds(Vec2 p) const { return p.x >= low.x && p.y >= low.y && p.x <= high.x && p.y <= high.y; }
    // Whether the box of a and b, widened by `margin`, meets this one.
    bool meets(Vec2 a, Vec2 b, double margin) const
    {
        return std::max(a.x, b.x) + margin >= low.x && std::min(a.x, b.x) - margin <= high.x &&
               std::max(a.y, b.y) + margin >= low.y && std::min(a.y, b.y) - margin <= high.y;
    }
};

double squaredDistanceToSegment(Vec2 p, Vec2 a, Vec2 b);

// p as a store keeps it: in single precision (a device's), the nearest position a pair of floats
// holds, so that what the host checks is what the device will keep.
Vec2 storedPosition(Vec2 p, bool singlePrecision);

// Where w, linear from wa to wb over [0, 1], passes strictly a whole number in [0, last], the one
// nearest the middle, as the fraction there: where a segment crosses one of a map's creases
// (a comb's tines, numbered by w).
std::optional<double> wholeCrossing(double wa, double wb, double last);
// Largest distance from a vertex of `from` to the closed polyline `to`.
double directedHausdorffDistance(const Polygon& from, const Polygon& to);
// Symmetric Hausdorff distance between two closed polylines (vertex-to-segment, both ways).
double hausdorffDistance(const Polygon& a, const Polygon& b);

} // namespace vf::sim
