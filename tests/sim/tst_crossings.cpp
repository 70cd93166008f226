// The exact crossing tests of sim/Crossings: the orientation predicate where plain floating point
// gets the sign wrong, and crossings found, placed and counted over many polygons.
#include "sim/Crossings.h"

#include <QTest>

#include <cmath>
#include <cstdint>
#include <numbers>

using namespace vf;
using sim::Polygon;
using sim::Vec2;

namespace {

// The contact rule of isSimple, pair by pair and in plain arithmetic: exact for small whole
// coordinates, and independent of the sweep and of orientation().
double cross(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }
bool onClosedSegment(Vec2 p, Vec2 a, Vec2 b)
{
    return cross(a, b, p) == 0.0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}
bool segmentsMeet(Vec2 a, Vec2 b, Vec2 c, Vec2 d)
{
    const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    return onClosedSegment(c, a, b) || onClosedSegment(d, a, b) || onClosedSegment(a, c, d) || onClosedSegment(b, c, d);
}
bool simpleByAllPairs(const std::vector<Polygon>& polygons)
{
    struct E { Vec2 a, b; std::size_t polygon, index, count; };
    std::vector<E> edges;
    for (std::size_t p = 0; p < polygons.size(); ++p)
        for (std::size_t i = 0; i < polygons[p].size(); ++i)
            edges.push_back({polygons[p][i], polygons[p][(i + 1) % polygons[p].size()], p, i, polygons[p].size()});
    for (const E& e : edges)
        if (e.a == e.b)
            return false;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        for (std::size_t j = i + 1; j < edges.size(); ++j) {
            const E &s = edges[i], &t = edges[j];
            const bool follows = s.polygon == t.polygon && ((s.index + 1) % s.count == t.index || (t.index + 1) % t.count == s.index);
            if (follows) {
                const E& first = (s.index + 1) % s.count == t.index ? s : t;
                const E& second = &first == &s ? t : s;
                const Vec2 u = first.b - first.a, v = second.b - second.a;
                if (s.count > 3 && cross(first.a, first.b, second.b) == 0.0 && u.x * v.x + u.y * v.y < 0.0)
                    return false;  // folds back
            } else if (segmentsMeet(s.a, s.b, t.a, t.b)) {
                return false;
            }
        }
    }
    return true;
}

} // namespace

class TestCrossings : public QObject {
    Q_OBJECT

private slots:
    void orientationOfPlainTurns()
    {
        QCOMPARE(sim::orientation({0, 0}, {1, 0}, {0, 1}), 1);
        QCOMPARE(sim::orientation({0, 0}, {0, 1}, {1, 0}), -1);
        QCOMPARE(sim::orientation({0, 0}, {1, 1}, {2, 2}), 0);
    }

    // Shewchuk's example: p = (0.5 + i·u, 0.5 + j·u), u = 2⁻⁵³ (the spacing of doubles there), turning
    // through (12, 12) and (24, 24) on the line y = x: the exact sign is that of j − i, and the plain
    // floating-point determinant gets it wrong for many of them.
    void orientationIsExactNearCollinear()
    {
        const Vec2 q(12.0, 12.0), r(24.0, 24.0);
        const double u = std::ldexp(1.0, -53);
        int naiveWrong = 0;
        for (int i = 0; i < 64; ++i) {
            for (int j = 0; j < 64; ++j) {
                const Vec2 p(0.5 + i * u, 0.5 + j * u);
                const int exact = j > i ? 1 : j < i ? -1 : 0;
                QCOMPARE(sim::orientation(p, q, r), exact);
                QCOMPARE(sim::orientation(q, r, p), exact);
                const double d = (p.x - r.x) * (q.y - r.y) - (p.y - r.y) * (q.x - r.x);
                naiveWrong += (d > 0 ? 1 : d < 0 ? -1 : 0) != exact;
            }
        }
        QVERIFY2(naiveWrong > 0, "the points must be hard enough that plain doubles fail on some");
    }

    void crossingFoundWithItsPlace()
    {
        const Polygon square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        const Polygon bar{{0.5, -0.5}, {0.6, -0.5}, {0.6, 0.25}, {0.5, 0.25}};
        const auto crossings = sim::findCrossings({&square, &bar});
        QCOMPARE(crossings.size(), std::size_t(2));  // both sides of the bar cross the square's edge 0
        for (const sim::EdgeCrossing& c : crossings) {
            QCOMPARE(c.polygonA, std::size_t(0));
            QCOMPARE(c.edgeA, std::size_t(0));
            QCOMPARE(c.polygonB, std::size_t(1));
            QVERIFY(std::abs(c.point.y) < 1e-15);
        }
        QCOMPARE(crossings[0].edgeB, std::size_t(1));
        QCOMPARE(crossings[1].edgeB, std::size_t(3));
        QCOMPARE(crossings[0].point.x, 0.6);
        QCOMPARE(crossings[1].point.x, 0.5);
        QCOMPARE(sim::findCrossings({&square, &bar}, 1).size(), std::size_t(1));
    }

    // Touching is not crossing: a vertex on another edge, collinear overlap, shared corners.
    void touchingIsNotCrossing()
    {
        const Polygon a{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        const Polygon b{{1, 0.25}, {2, 0.25}, {2, 0.75}, {1, 0.75}};  // shares part of an edge
        const Polygon c{{0.5, 1}, {0.75, 2}, {0.25, 2}};             // a vertex on a's top edge
        QCOMPARE(sim::countCrossings({&a, &b, &c}), std::size_t(0));
        QVERIFY(sim::isSimple(a));
    }

    void selfCrossingsOfOneContour()
    {
        const Polygon bowTie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
        QCOMPARE(sim::countCrossings({&bowTie}), std::size_t(1));
        QVERIFY(!sim::isSimple(bowTie));
        const Polygon pinched{{0, 0}, {1, 0}, {0.5, 0.5}, {1, 1}, {0, 1}, {0.5, 0.5}};
        QCOMPARE(sim::countCrossings({&pinched}), std::size_t(0));
        QVERIFY2(!sim::isSimple(pinched), "a figure eight pinched at a vertex is not simple");
    }

    // Many fine, nearly parallel polygons 1e-9 apart (a bundle of thin filaments): none crosses,
    // then one vertex pushed across its neighbour is found, whatever the grid's cell size.
    // The sweep against every pair, on polygons with vertices on a 5×5 lattice: touching vertices,
    // collinear overlaps, vertical edges and shared corners by the thousand.
    void simpleAgreesWithAllPairs()
    {
        std::uint32_t state = 12345;
        const auto next = [&state](std::uint32_t n) {
            state = state * 1664525u + 1013904223u;
            return (state >> 8) % n;
        };
        int simple = 0;
        for (int trial = 0; trial < 20000; ++trial) {
            std::vector<Polygon> polygons(1 + next(3));
            for (Polygon& polygon : polygons) {
                polygon.resize(3 + next(5));
                for (Vec2& v : polygon)
                    v = Vec2(double(next(5)), double(next(5)));
            }
            std::vector<const Polygon*> pointers;
            for (const Polygon& polygon : polygons)
                pointers.push_back(&polygon);
            const bool expected = simpleByAllPairs(polygons);
            QVERIFY2(sim::isSimple(pointers) == expected, qPrintable(QStringLiteral("trial %1").arg(trial)));
            simple += expected ? 1 : 0;
        }
        QVERIFY2(simple > 1000, qPrintable(QStringLiteral("only %1 simple cases").arg(simple)));
    }

    // Edges lying close together by the thousand share every cell of a grid; the sweep meets
    // each only beside its neighbours along the line (tests/sim/CMakeLists.txt gives a time limit).
    // A ring with an island in its hole, and a disc apart: the hole is subtracted, the island added.
    void filledAreaSubtractsHoles()
    {
        const Polygon outer = sim::circle({0.35, 0.5}, 0.3, 0.01), hole = sim::circle({0.35, 0.5}, 0.1, 0.01);
        const Polygon island = sim::circle({0.36, 0.5}, 0.05, 0.01), apart = sim::circle({0.85, 0.5}, 0.1, 0.01);
        const double expected = sim::signedArea(outer) - sim::signedArea(hole) + sim::signedArea(island)
                              + sim::signedArea(apart);
        QCOMPARE(sim::filledArea({hole, apart, island, outer}), expected);
        QVERIFY(std::abs(expected - std::numbers::pi * (0.09 - 0.01 + 0.0025 + 0.01)) < 1e-3);
        QCOMPARE(sim::filledArea({}), 0.0);
    }

    void nestedSquaresAreSimple()
    {
        constexpr int kSquares = 1000, kPerSide = 250;
        std::vector<Polygon> squares(kSquares);
        std::vector<const Polygon*> pointers;
        for (int k = 0; k < kSquares; ++k) {
            const double lo = k * 1e-6, hi = 1.0 - k * 1e-6;
            for (int side = 0; side < 4; ++side) {
                for (int i = 0; i < kPerSide; ++i) {
                    const double f = lo + (hi - lo) * i / kPerSide;
                    const Vec2 corners[4] = {{f, lo}, {hi, f}, {hi + lo - f, hi}, {lo, hi + lo - f}};
                    squares[k].push_back(corners[side]);
                }
            }
            pointers.push_back(&squares[k]);
        }
        QVERIFY(sim::isSimple(pointers));
        squares.back()[kPerSide / 2].y -= 2e-6;  // the innermost square's bottom pokes through the next one's
        QVERIFY(!sim::isSimple(pointers));
    }

    void thinFilamentsAndOneCrossing()
    {
        std::vector<Polygon> strands;
        const int n = 4000;
        for (int s = 0; s < 20; ++s) {
            Polygon p;
            const double offset = s * 1e-9;
            for (int i = 0; i < n; ++i)
                p.emplace_back(0.1 + 0.8 * i / n, 0.5 + offset + 0.01 * std::sin(i * 0.01));
            for (int i = n - 1; i >= 0; --i)
                p.emplace_back(0.1 + 0.8 * i / n + 0.5e-9, 0.5 + offset + 0.4e-9 + 0.01 * std::sin(i * 0.01));
            strands.push_back(std::move(p));
        }
        std::vector<const Polygon*> all;
        for (const Polygon& p : strands)
            all.push_back(&p);
        QCOMPARE(sim::countCrossings(all), std::size_t(0));
        strands[7][1234].y += 1.5e-9;  // across its own far side, into strand 8
        const auto crossings = sim::findCrossings(all);
        bool self = false, other = false;
        for (const sim::EdgeCrossing& c : crossings) {
            QCOMPARE(c.polygonA, std::size_t(7));
            QVERIFY(c.edgeA == 1233 || c.edgeA == 1234);
            self = self || c.polygonB == 7;
            other = other || c.polygonB == 8;
        }
        QVERIFY(self && other);
    }
};

QTEST_APPLESS_MAIN(TestCrossings)
#include "tst_crossings.moc"
