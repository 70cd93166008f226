#pragma once
// Shapes and independent measurements shared by the render tests. Brute force on purpose: the
// measurements must not share code (or shortcuts) with what they check.
#include "render/BezierFit.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>

namespace vf::test {

using sim::Polygon;
using sim::Vec2;

// Counter-clockwise on screen (y down), `count` vertices.
inline Polygon circlePolygon(Vec2 center, double radius, int count)
{
    Polygon polygon;
    for (int i = 0; i < count; ++i) {
        const double a = 2 * std::numbers::pi * i / count;
        polygon.push_back(center + radius * Vec2(std::cos(a), -std::sin(a)));
    }
    return polygon;
}

// A five-lobed star with random, uneven angular spacing and optional radial noise: like a
// simulated contour, with nothing regular for the fitter to exploit.
inline Polygon wobblyPolygon(Vec2 center, double radius, int count, unsigned seed, double noiseAmplitude = 2e-4)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> step(0.3, 1.7);
    std::uniform_real_distribution<double> noise(-noiseAmplitude, noiseAmplitude);
    std::vector<double> angles{0.0};
    for (int i = 1; i < count; ++i)
        angles.push_back(angles.back() + step(random));
    const double total = angles.back() + step(random);
    Polygon polygon;
    for (double a : angles) {
        const double t = 2 * std::numbers::pi * a / total;
        const double r = radius * (1 + 0.3 * std::sin(5 * t)) + noise(random);
        polygon.push_back(center + r * Vec2(std::cos(t), -std::sin(t)));
    }
    return polygon;
}

// The square's corners, with `perSide` vertices along each side (so the sides are straight runs).
inline Polygon squarePolygon(Vec2 corner, double side, int perSide)
{
    const Vec2 corners[] = {corner, corner + Vec2(side, 0), corner + Vec2(side, side), corner + Vec2(0, side)};
    Polygon polygon;
    for (int k = 0; k < 4; ++k) {
        for (int i = 0; i < perSide; ++i)
            polygon.push_back(glm::mix(corners[k], corners[(k + 1) % 4], double(i) / perSide));
    }
    return polygon;
}

inline double segmentDistance(Vec2 p, Vec2 a, Vec2 b)
{
    const Vec2 ab = b - a;
    const double l2 = glm::dot(ab, ab);
    const double t = l2 > 0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return glm::distance(p, a + t * ab);
}

inline Vec2 cubicPoint(Vec2 p0, const render::PathSegment& s, double t)
{
    if (s.isLine)
        return glm::mix(p0, s.end, t);
    const double u = 1 - t;
    return u * u * u * p0 + 3 * u * u * t * s.control1 + 3 * u * t * t * s.control2 + t * t * t * s.end;
}

// Distance from p to a cubic segment: the nearest of `samples`, refined by Newton steps on
// (Q(t) - p)·Q'(t) = 0. Any curve point gives an upper bound, so a failed step costs nothing.
inline double cubicDistance(Vec2 p, Vec2 p0, const render::PathSegment& s, const std::vector<Vec2>& samples)
{
    if (s.isLine)
        return segmentDistance(p, p0, s.end);
    std::size_t nearest = 0;
    for (std::size_t j = 1; j < samples.size(); ++j) {
        if (glm::distance(samples[j], p) < glm::distance(samples[nearest], p))
            nearest = j;
    }
    double best = glm::distance(samples[nearest], p);
    double t = double(nearest) / double(samples.size() - 1);
    for (int step = 0; step < 8; ++step) {
        const double u = 1 - t;
        const Vec2 d1 = 3.0 * (u * u * (s.control1 - p0) + 2 * u * t * (s.control2 - s.control1) + t * t * (s.end - s.control2));
        const Vec2 d2 = 6.0 * (u * (s.control2 - 2.0 * s.control1 + p0) + t * (s.end - 2.0 * s.control2 + s.control1));
        const Vec2 offset = cubicPoint(p0, s, t) - p;
        const double slope = glm::dot(d1, d1) + glm::dot(offset, d2);
        if (!(slope > 0))
            break;
        t = std::clamp(t - glm::dot(offset, d1) / slope, 0.0, 1.0);
        best = std::min(best, glm::distance(cubicPoint(p0, s, t), p));
    }
    return best;
}

// Index of each segment's end in the polygon, once around in polygon order starting at the
// contour's start; empty when the segments do not end on the polygon's vertices that way.
inline std::vector<std::size_t> segmentEndIndices(const render::FittedContour& contour, const Polygon& polygon)
{
    std::map<std::pair<double, double>, std::size_t> indices;
    for (std::size_t i = 0; i < polygon.size(); ++i)
        indices.emplace(std::pair(polygon[i].x, polygon[i].y), i);
    const std::size_t n = polygon.size();
    const auto indexOf = [&](Vec2 p) {
        const auto found = indices.find({p.x, p.y});
        return found == indices.end() ? n : found->second;
    };
    const std::size_t start = indexOf(contour.start);
    if (start == n || contour.segments.empty() || contour.segments.back().end != contour.start)
        return {};
    std::vector<std::size_t> ends{start};
    std::size_t previous = 0; // steps from start
    for (std::size_t k = 0; k + 1 < contour.segments.size(); ++k) {
        const std::size_t i = indexOf(contour.segments[k].end);
        const std::size_t steps = (i + n - start) % n;
        if (i == n || steps <= previous)
            return {};
        previous = steps;
        ends.push_back(i);
    }
    ends.push_back(start);
    return ends;
}

inline bool endsFollowVertices(const render::FittedContour& contour, const Polygon& polygon)
{
    return !segmentEndIndices(contour, polygon).empty();
}

// An upper bound of the symmetric deviation between a fitted contour and its polygon: each
// segment's densely sampled points against the stretch of polyline between its end vertices, and
// each vertex of that stretch against the segment.
// Comparing with the own stretch only can over-estimate, never under-estimate, the true distance.
inline double deviation(const render::FittedContour& contour, const Polygon& polygon)
{
    const std::vector<std::size_t> ends = segmentEndIndices(contour, polygon);
    if (ends.empty())
        return std::numeric_limits<double>::infinity();
    constexpr int kSamples = 256;
    const std::size_t n = polygon.size();
    double worst = 0;
    Vec2 from = contour.start;
    for (std::size_t k = 0; k < contour.segments.size(); ++k) {
        const render::PathSegment& s = contour.segments[k];
        std::vector<std::size_t> stretch{ends[k]};
        for (std::size_t i = ends[k]; i != ends[k + 1];)
            stretch.push_back(i = (i + 1) % n);
        std::vector<Vec2> samples;
        for (int j = 0; j <= kSamples; ++j)
            samples.push_back(cubicPoint(from, s, double(j) / kSamples));
        for (const Vec2& q : samples) {
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t e = 0; e + 1 < stretch.size(); ++e)
                best = std::min(best, segmentDistance(q, polygon[stretch[e]], polygon[stretch[e + 1]]));
            worst = std::max(worst, best);
        }
        for (const std::size_t v : stretch)
            worst = std::max(worst, cubicDistance(polygon[v], from, s, samples));
        from = s.end;
    }
    return worst;
}

} // namespace vf::test
