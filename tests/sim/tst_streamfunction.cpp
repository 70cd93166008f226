// The velocity the contours move through (sim/StreamFunction): from the stream function of a
// discretely divergence-free MAC field, it has no divergence anywhere, no flow through the walls,
// a continuous gradient (where the bilinear MAC interpolation jumps, which made thin filaments
// cross), follows the MAC field, and continues it across the walls as its mirror image.
#include "sim/Crossings.h"
#include "sim/FluidSolver.h"
#include "sim/StreamFunction.h"

#include <QTest>

#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>

#include <cmath>

using namespace vf;
using sim::MacVelocity;
using sim::StreamField;
using sim::Vec2;

namespace {

// A fluid on a 24 × 16 grid over 1.5 × 1 stirred by two strokes: discretely divergence-free, with
// structure at the scale of a few cells.
MacVelocity stirredField()
{
    sim::FluidSettings s;
    s.nx = 24;
    s.ny = 16;
    s.width = 1.5;
    s.height = 1.0;
    sim::FluidSolver solver(s);
    solver.addStylus({0.2, 0.3}, {1.2, 0.5}, 0.15, 0.1);
    solver.step(0.02);
    solver.addStylus({0.9, 0.9}, {0.6, 0.2}, 0.1, 0.05);
    solver.step(0.02);
    return solver.velocity();
}

double maxSpeed(const MacVelocity& m)
{
    double speed = 0.0;
    for (double u : m.u)
        speed = std::max(speed, std::abs(u));
    for (double v : m.v)
        speed = std::max(speed, std::abs(v));
    return speed;
}

// Points spread over the canvas (and `margin` beyond it), avoiding the lattice lines themselves.
std::vector<Vec2> samplePoints(double width, double height, double margin)
{
    std::vector<Vec2> points;
    for (int k = 0; k < 997; ++k)
        points.emplace_back(-margin + (width + 2 * margin) * std::fmod(k * 0.6180339887, 1.0),
                            -margin + (height + 2 * margin) * std::fmod(k * 0.7548776662, 1.0));
    return points;
}

// The Jacobian of the velocity by central differences of step h.
glm::dmat2 jacobian(const StreamField& f, Vec2 p, double h)
{
    const Vec2 dx = (f.velocity(p + Vec2(h, 0)) - f.velocity(p - Vec2(h, 0))) / (2 * h);
    const Vec2 dy = (f.velocity(p + Vec2(0, h)) - f.velocity(p - Vec2(0, h))) / (2 * h);
    return {dx, dy};  // columns: ∂/∂x, ∂/∂y
}

} // namespace

class TestStreamFunction : public QObject {
    Q_OBJECT

private slots:
    void divergenceFreeEverywhere()
    {
        const MacVelocity m = stirredField();
        const StreamField f = StreamField::of(m);
        const double speed = maxSpeed(m);
        QVERIFY(speed > 0.1);
        for (const Vec2 p : samplePoints(1.5, 1.0, 0.2)) {
            const glm::dmat2 j = jacobian(f, p, 1e-5);
            const double divergence = j[0].x + j[1].y;
            QVERIFY2(std::abs(divergence) < 1e-6 * speed / m.hx,
                     qPrintable(QString("div %1 at (%2, %3)").arg(divergence).arg(p.x).arg(p.y)));
        }
    }

    void noFlowThroughTheWalls()
    {
        const MacVelocity m = stirredField();
        const StreamField f = StreamField::of(m);
        const double speed = maxSpeed(m);
        double tangential = 0.0;
        for (int k = 0; k <= 100; ++k) {
            const double x = 1.5 * k / 100.0, y = k / 100.0;
            QVERIFY(std::abs(f.velocity({0.0, y}).x) < 1e-12 * speed);
            QVERIFY(std::abs(f.velocity({1.5, y}).x) < 1e-12 * speed);
            QVERIFY(std::abs(f.velocity({x, 0.0}).y) < 1e-12 * speed);
            QVERIFY(std::abs(f.velocity({x, 1.0}).y) < 1e-12 * speed);
            tangential = std::max({tangential, std::abs(f.velocity({0.0, y}).y), std::abs(f.velocity({x, 1.0}).x)});
        }
        QVERIFY2(tangential > 1e-3 * speed, "free slip: the flow runs along the walls");
    }

    // Across a line through cell centres the bilinear MAC velocity's gradient jumps; the stream
    // field's does not, there or on the lines through the corners (the spline's knots).
    void gradientIsContinuous()
    {
        const MacVelocity m = stirredField();
        const StreamField f = StreamField::of(m);
        double worstJump = 0.0, worstMacJump = 0.0;
        const double h = 1e-8, d = 1e-6;  // difference step; distance either side of the line
        for (int i = 2; i < 2 * m.nx - 2; ++i) {
            for (int k = 0; k < 16; ++k) {
                const Vec2 p(0.5 * i * m.hx, (k + 0.37) * m.hy);  // v's lattice lines, then the knots
                const glm::dmat2 left = jacobian(f, p - Vec2(d, 0), h), right = jacobian(f, p + Vec2(d, 0), h);
                worstJump = std::max(worstJump, std::abs(left[0].y - right[0].y));
                const double macLeft = (m.sample(p - Vec2(d - h, 0)).y - m.sample(p - Vec2(d + h, 0)).y) / (2 * h);
                const double macRight = (m.sample(p + Vec2(d + h, 0)).y - m.sample(p + Vec2(d - h, 0)).y) / (2 * h);
                worstMacJump = std::max(worstMacJump, std::abs(macLeft - macRight));
            }
        }
        QVERIFY2(worstMacJump > 1.0, qPrintable(QString::number(worstMacJump)));  // what the test would catch
        QVERIFY2(worstJump < 1e-3 * worstMacJump, qPrintable(QString("%1 against %2").arg(worstJump).arg(worstMacJump)));
    }

    // A cubic B-spline smooths at the scale of a cell; on a field that varies over several cells
    // it follows the MAC field closely.
    void followsTheMacField()
    {
        sim::FluidSettings s;
        s.nx = s.ny = 64;
        MacVelocity m = sim::FluidSolver::atRest(s);
        // The curl of a smooth ψ that is constant on the walls: ψ = sin²(πx) sin²(πy) / π.
        const auto psi = [](double x, double y) {
            return std::pow(std::sin(M_PI * x) * std::sin(M_PI * y), 2) / M_PI;
        };
        for (int j = 0; j < s.ny; ++j)
            for (int i = 0; i <= s.nx; ++i)
                m.u[std::size_t(j) * (s.nx + 1) + i] = (psi(i * m.hx, (j + 1) * m.hy) - psi(i * m.hx, j * m.hy)) / m.hy;
        for (int j = 0; j <= s.ny; ++j)
            for (int i = 0; i < s.nx; ++i)
                m.v[std::size_t(j) * s.nx + i] = -(psi((i + 1) * m.hx, j * m.hy) - psi(i * m.hx, j * m.hy)) / m.hx;
        const StreamField f = StreamField::of(m);
        for (const Vec2 p : samplePoints(1.0, 1.0, 0.0)) {
            // This ψ curves across the walls, which the reflection of free-slip walls straightens:
            // within a cell or two of a wall the two differ.
            if (std::min({p.x, p.y, 1.0 - p.x, 1.0 - p.y}) < 2.0 * m.hx)
                continue;
            const Vec2 exact(2 * std::sin(M_PI * p.x) * std::sin(M_PI * p.x) * std::sin(M_PI * p.y) * std::cos(M_PI * p.y),
                             -2 * std::sin(M_PI * p.x) * std::cos(M_PI * p.x) * std::sin(M_PI * p.y) * std::sin(M_PI * p.y));
            // The spline smooths by (h²/6)·∇² (h the cell): about 2.5e-3 here against speeds up to 1.
            QVERIFY2(glm::distance(f.velocity(p), exact) < 4e-3, qPrintable(QString("at (%1, %2)").arg(p.x).arg(p.y)));
            QVERIFY(glm::distance(f.velocity(p), m.sample(p)) < 5e-3);
            const double omega = -2 * M_PI * (std::cos(2 * M_PI * p.x) * std::pow(std::sin(M_PI * p.y), 2) +
                                              std::pow(std::sin(M_PI * p.x), 2) * std::cos(2 * M_PI * p.y));
            QVERIFY(std::abs(f.vorticity(p) - omega) < 0.05);  // |ω| reaches 4π ≈ 12.6 here
        }
    }

    // Why the contours move through the stream function: two sides of a thin filament, 5e-5 apart,
    // edges 2e-3 long, lying across a line where the bilinear MAC velocity has a kink (v = A·|x − x₀|
    // about a v lattice line). One RK4 step moves the vertices by the flow, and the straight edge
    // between them misses the image of the true edge by dt·A·(half the edge), more than the gap:
    // the filament's sides cross. With the C¹ stream function field the miss is second order.
    void thinFilamentAcrossAKinkStaysApart()
    {
        sim::FluidSettings s;
        s.nx = s.ny = 64;
        MacVelocity m = sim::FluidSolver::atRest(s);
        const int kink = 31;  // v's lattice line x₀ = 31.5 cells
        const double a = 20.0, x0 = (kink + 0.5) * m.hx;
        for (int j = 0; j <= s.ny; ++j)
            for (int i = 0; i < s.nx; ++i)
                m.v[std::size_t(j) * s.nx + i] = a * std::abs(i - kink) * m.hx;
        const StreamField f = StreamField::of(m);
        const auto step = [](auto velocity, Vec2 p) {
            const double dt = 0.01;
            const Vec2 k1 = velocity(p), k2 = velocity(p + 0.5 * dt * k1), k3 = velocity(p + 0.5 * dt * k2);
            return p + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + velocity(p + dt * k3));
        };
        // Side A has an edge across the line, side B a vertex on it, 5e-5 further down (y grows down).
        const double y = 0.5, half = 1e-3, gap = 5e-5;
        const sim::Polygon before{{x0 - 0.01, y}, {x0 - half, y}, {x0 + half, y}, {x0 + 0.01, y},
                                  {x0 + 0.01, y + gap}, {x0, y + gap}, {x0 - 0.01, y + gap}};
        const auto crossingsAfter = [&](auto velocity) {
            sim::Polygon after;
            for (const Vec2& p : before)
                after.push_back(step(velocity, p));
            return sim::countCrossings({&after});
        };
        QCOMPARE(sim::countCrossings({&before}), std::size_t(0));
        QVERIFY(crossingsAfter([&](Vec2 p) { return m.sample(p); }) > 0);
        QCOMPARE(crossingsAfter([&](Vec2 p) { return f.velocity(p); }), std::size_t(0));
    }

    // Outside the canvas the flow is the mirror image of the flow inside: the position reflected in
    // the wall, the component across the wall negated, and the vorticity negated with each mirror.
    // Outside the canvas the flow continues as the mirror image of the flow inside, damped to rest
    // two cells out (the divergence test above samples the band too).
    void dampedOutsideTheWalls()
    {
        const StreamField f = StreamField::of(stirredField());
        const double width = f.nx * f.hx, height = f.ny * f.hy;
        const double bandX = StreamField::dampingCells * f.hx, bandY = StreamField::dampingCells * f.hy;
        for (const Vec2 p : samplePoints(width, height, 0.0)) {
            const Vec2 inside(1e-7, p.y), outside(-1e-7, p.y);
            const Vec2 v = f.velocity(inside);
            QVERIFY(glm::distance(f.velocity(outside), Vec2(-v.x, v.y)) < 1e-6);  // continuous across the wall
            QVERIFY(std::abs(f.velocity({0.0, p.y}).x) < 1e-12);                   // nothing crosses it
            const Vec2 halfway(-0.5 * bandX, p.y), mirror(0.5 * bandX, p.y);
            QVERIFY(glm::length(f.velocity(halfway)) < glm::length(f.velocity(mirror)) + 1e-12);  // damped
            for (const Vec2 rest : {Vec2(-bandX, p.y), Vec2(width + 1.5 * bandX, p.y), Vec2(p.x, -bandY),
                                    Vec2(p.x, height + 3.0 * bandY), Vec2(-bandX, -bandY), Vec2(1e300, -1e300)}) {
                QCOMPARE(f.velocity(rest), Vec2(0.0));
                QVERIFY(f.vorticity(rest) == 0.0);
            }
        }
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (const Vec2 bad : {Vec2(nan, 0.5), Vec2(0.5, nan), Vec2(1e300, -1e300)})
            QVERIFY(std::isfinite(f.velocity(bad).x) && std::isfinite(f.vorticity(bad)));  // stays on the lattice
    }
};

QTEST_APPLESS_MAIN(TestStreamFunction)
#include "tst_streamfunction.moc"
