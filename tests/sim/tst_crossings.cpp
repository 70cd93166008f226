// The exact crossing tests of sim/Crossings: the orientation predicate where plain floating point
// gets the sign wrong, and crossings found, placed and counted over many polygons.
#include "sim/Crossings.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace vf;
using sim::Polygon;
using sim::Vec2;

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
