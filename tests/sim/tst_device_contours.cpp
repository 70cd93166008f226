// The OpenCL contour tracker (sim/opencl/DeviceContours) against the double-precision reference
// (sim/ContourTracker): refinement by stream compaction keeps contours closed, ordered and within
// their spacing; geometry and vertex counts agree with the reference; runs are bit-identical.
// One file past 500 lines: every case compares with the reference through the helpers below.
#include "Backends.h"
#include "Flows.h"

#include "sim/AnalyticFlow.h"
#include "sim/Crossings.h"
#include "sim/ContourTracker.h"
#include "sim/ProximityGrid.h"
#include "sim/Simulation.h"
#include "sim/opencl/DeviceContours.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <numbers>
#include <optional>

using namespace vf;
using sim::Polygon;
using sim::Vec2;
using sim::opencl::DeviceContours;
using sim::opencl::FlowBinding;

namespace {

// The test flows, on the host as muparser expressions and on the device as one OpenCL C source,
// which picks the flow by the binding's `nx` (analytic flows ignore the grid arguments) so that
// every test shares one program build.
enum class FlowId { SingleVortex, Rotation, Contraction };

struct TestFlow {
    const char* u;
    const char* v;
};

// LeVeque's single vortex reversed at t = T/2 (T = 8); solid rotation about the canvas centre, one
// turn per 2 s; a uniform contraction toward the centre (not divergence-free: it deletes vertices).
TestFlow hostFlow(FlowId id)
{
    switch (id) {
    case FlowId::SingleVortex:
        return {"-sin(pi*x)^2*sin(2*pi*y)*cos(pi*t/8)", "sin(pi*y)^2*sin(2*pi*x)*cos(pi*t/8)"};
    case FlowId::Rotation:
        return {"-pi*(y-0.5)", "pi*(x-0.5)"};
    case FlowId::Contraction:
        break;
    }
    return {"-(x-0.5)", "-(y-0.5)"};
}

// sinpi/cospi rather than sin(pi * x): PoCL's scalar sin is several times slower.
const char* deviceFlowSource = R"CL(
inline __attribute__((always_inline)) float2 flowVelocity(FLOW_PARAMS, float2 p, float s)
{
    const float t = t0 + s * dt;
    if (nx == 0) {
        const float sx = sinpi(p.x), sy = sinpi(p.y), reversal = cospi(t / 8.0f);
        return (float2)(-sx * sx * sinpi(2.0f * p.y) * reversal, sy * sy * sinpi(2.0f * p.x) * reversal);
    }
    if (nx == 1)
        return (float2)(-M_PI_F * (p.y - 0.5f), M_PI_F * (p.x - 0.5f));
    return (float2)(0.5f - p.x, 0.5f - p.y);
}
inline __attribute__((always_inline)) float flowVorticity(FLOW_PARAMS, float2 p, float s)
{
    const float t = t0 + s * dt;
    if (nx == 0) {
        const float sx = sinpi(p.x), sy = sinpi(p.y), reversal = cospi(t / 8.0f);
        return 2.0f * M_PI_F * reversal * (sy * sy * cospi(2.0f * p.x) + sx * sx * cospi(2.0f * p.y));
    }
    return nx == 1 ? 2.0f * M_PI_F : 0.0f;
}
VF_DEFINE_LANES_BY_LANE
)CL";

sim::TrackingSettings tracking(double maxSpacing, bool adaptive)
{
    sim::TrackingSettings s;
    s.maxSpacing = maxSpacing;
    s.adaptive = adaptive;
    s.proximity = adaptive;
    return s;
}

// The device tracker and the reference, driven in step with the same substep rule as the
// backends (ReferenceSimulation::step).
class Pair {
public:
    Pair(sim::opencl::Device& device, FlowId flow, const sim::TrackingSettings& settings, bool withReference = true,
         std::size_t sweepOverflow = DeviceContours::sweepOverflowCapacity)
        : m_flowId(flow)
        , m_settings(settings)
        , m_host(hostFlow(flow).u, hostFlow(flow).v)
        , m_tracker(settings)
        , m_contours(device, settings, sim::Vec2(1.0), deviceFlowSource, sweepOverflow)
        , m_placeholder(device.context(), CL_MEM_READ_ONLY, sizeof(float))
        , m_withReference(withReference)
    {
    }

    // Replaces every contour on both (snapshot restore), spacing included.
    void write(const std::vector<sim::Contour>& contours)
    {
        m_contours.write(contours);
        if (m_withReference)
            m_tracker.setContours(contours);
    }

    void add(int region, const Polygon& p)
    {
        m_contours.addRegion(region, {p});
        if (m_withReference)
            m_tracker.addContour(region, p);
    }

    FlowBinding binding(double t0, double t1) const
    {
        FlowBinding b;
        b.field = m_placeholder;
        b.nx = int(m_flowId);
        b.t0 = t0;
        b.t1 = t1;
        return b;
    }

    // One step of dt on both; false when the device stopped at max_vertices. The device's first
    // substep takes the strain check's samples as RK4's first stage unless `sampleAgain`;
    // `afterStrainCheck` runs between the two.
    bool step(double dt, bool sampleAgain = false, const std::function<void()>& afterStrainCheck = {})
    {
        bool within = true;
        const int n = sim::substepCount(m_contours.strainInSpacings(binding(m_time, m_time), dt), m_settings);
        if (afterStrainCheck)
            afterStrainCheck();
        for (int k = 0; k < n && within; ++k) {
            within = m_contours.advect(binding(m_time, m_time + dt / n), k == 0 && !sampleAgain);
            m_time += dt / n;
        }
        if (m_withReference) {
            const double strain = m_tracker.strainInSpacings(m_host, m_referenceTime, dt);
            const int reference = sim::substepCount(strain, m_settings);
            for (int k = 0; k < reference; ++k) {
                m_tracker.advect(m_host, m_referenceTime, dt / reference);
                m_referenceTime += dt / reference;
            }
        }
        return within;
    }

    // An ink drop as ReferenceSimulation::drop does it, the dropped disc becoming `region`.
    void drop(Vec2 centre, double radius, int region)
    {
        const Polygon dropped = sim::circle(centre, radius, m_settings.maxSpacing);
        m_contours.growTargetAreasAround(centre, sim::signedArea(dropped));
        m_contours.drop(centre, radius, binding(m_time, m_time));
        if (m_withReference) {
            m_tracker.growTargetAreasAround(centre, sim::signedArea(dropped));
            m_tracker.drop({centre, radius}, m_host, m_referenceTime);
        }
        add(region, dropped);
    }

    DeviceContours& device() { return m_contours; }
    const sim::ContourTracker& reference() const { return m_tracker; }

    // The strain check of both for a step of dt from the current time.
    double deviceStrain(double dt) { return m_contours.strainInSpacings(binding(m_time, m_time), dt); }
    double referenceStrain(double dt) const { return m_tracker.strainInSpacings(m_host, m_referenceTime, dt); }

private:
    FlowId m_flowId;
    sim::TrackingSettings m_settings;
    sim::AnalyticFlow m_host;
    sim::ContourTracker m_tracker;
    DeviceContours m_contours;
    cl::Buffer m_placeholder;
    bool m_withReference;
    double m_time = 0.0, m_referenceTime = 0.0;
};

std::size_t totalVertices(const std::vector<sim::Contour>& contours)
{
    std::size_t n = 0;
    for (const sim::Contour& c : contours)
        n += c.positions.size();
    return n;
}

// Device against reference: the worst Hausdorff distance over corresponding contours, and the
// relative difference of the vertex counts.
struct Agreement {
    double hausdorff = 0.0;
    double countDifference = 0.0;
};

Agreement compare(Pair& pair)
{
    const std::vector<sim::Contour> device = pair.device().read();
    const std::vector<sim::Contour>& reference = pair.reference().contours();
    Agreement a;
    if (device.size() != reference.size())
        return {INFINITY, INFINITY};
    for (std::size_t c = 0; c < device.size(); ++c)
        a.hausdorff = std::max(a.hausdorff, sim::hausdorffDistance(device[c].positions, reference[c].positions));
    const double n = double(totalVertices(reference));
    a.countDifference = std::abs(double(totalVertices(device)) - n) / n;
    return a;
}

QString describe(const Agreement& a, const Pair& pair)
{
    return QStringLiteral("Hausdorff %1, vertex counts differ by %2% (reference %3)")
        .arg(a.hausdorff)
        .arg(100.0 * a.countDifference)
        .arg(pair.reference().vertexCount());
}

// What stream compaction must keep: every contour closed with at least 3 vertices, counts adding
// up, no vertex duplicated, every edge within [d_e/2, d_e] (float rounding aside, and the lower
// bound less shortEdgeSlack and only away from other ink), and, for contours known to be
// star-shaped about `centre`, the
// vertices in angular order, once around.
QString invariantViolation(const std::vector<sim::Contour>& contours, std::size_t vertexCount,
                           std::optional<Vec2> centre = std::nullopt)
{
    if (totalVertices(contours) != vertexCount)
        return QStringLiteral("contours hold %1 vertices, the tracker counts %2")
            .arg(totalVertices(contours))
            .arg(vertexCount);
    // A short edge may stay where removing or moving its ends would sweep over other ink: where
    // another part lies within the edge's spacing.
    double widest = 0.0;
    for (const sim::Contour& c : contours)
        for (double d : c.spacing)
            widest = std::max(widest, d);
    sim::ProximityGrid near;
    near.build(contours, widest, widest);
    std::vector<std::pair<double, double>> all;
    for (std::size_t ci = 0; ci < contours.size(); ++ci) {
        const sim::Contour& c = contours[ci];
        const std::size_t n = c.positions.size();
        if (n < 3 || c.previous.size() != n || c.spacing.size() != n)
            return QStringLiteral("contour %1 has %2 vertices").arg(ci).arg(n);
        double turn = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            all.emplace_back(c.positions[i].x, c.positions[i].y);
            const double d = 0.5 * (c.spacing[i] + c.spacing[j]);
            const double length = glm::distance(c.positions[i], c.positions[j]);
            const double slack = test::shortEdgeSlack(QStringLiteral("opencl"), c.positions[i]);
            const bool beside = near.nearestOtherPart(ci, i) < d || near.nearestOtherPart(ci, j) < d;
            if (length > d * (1 + 1e-5) || (n > 3 && !beside && length + slack < 0.5 * d * (1 - 1e-5)))
                return QStringLiteral("contour %1 edge %2 has length %3 for spacing %4")
                    .arg(ci)
                    .arg(i)
                    .arg(length)
                    .arg(d);
            if (centre) {
                const Vec2 a = c.positions[i] - *centre, b = c.positions[j] - *centre;
                const double step = std::atan2(a.x * b.y - a.y * b.x, glm::dot(a, b));
                if (step <= 0.0)
                    return QStringLiteral("contour %1 goes back at vertex %2").arg(ci).arg(i);
                turn += step;
            }
        }
        if (centre && std::abs(turn - 2.0 * std::numbers::pi) > 1e-6)
            return QStringLiteral("contour %1 turns %2 around the centre").arg(ci).arg(turn);
    }
    std::sort(all.begin(), all.end());
    if (std::adjacent_find(all.begin(), all.end()) != all.end())
        return QStringLiteral("a vertex position appears twice");
    return {};
}

std::size_t crossings(const std::vector<sim::Contour>& contours)
{
    std::vector<const Polygon*> all;
    for (const sim::Contour& c : contours)
        all.push_back(&c.positions);
    return sim::countCrossings(all);
}

// n vertices on a circle, evenly over three quarters of it, so that one edge (a quarter circle's
// chord) is much longer than the others; listed so that the long edge runs from vertex
// `longAfter` to the next.
Polygon withOneLongEdge(Vec2 centre, double radius, int n, int longAfter)
{
    Polygon p(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        const int original = (k + n - 1 - longAfter) % n;  // original n − 1 → 0 is the long edge
        const double a = 1.5 * std::numbers::pi * original / (n - 1);
        p[std::size_t(k)] = centre + radius * Vec2(std::cos(a), std::sin(a));
    }
    return p;
}

double area(const std::vector<sim::Contour>& contours)
{
    double a = 0.0;
    for (const sim::Contour& c : contours)
        a += sim::signedArea(c.positions);
    return a;
}

} // namespace

class TestDeviceContours : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();

    void bytesPerVertexWithinBudget();
    void compactionKeepsRingsOrdered();
    void stretchAndReturnKeepsContoursValid();
    void sweepGridOverflowChangesNothing();

    void rotationMatchesReference_data();
    void rotationMatchesReference();
    void singleVortexMatchesReference();
    void dropMatchesReference();

    void singleVortexReturns_data();
    void singleVortexReturns();

    void strainMatchesReference_data();
    void strainMatchesReference();
    void strainTakesEachEndsSpacing();
    void smallContourMatchesReference();
    void proximityMatchesReference();
    void runsAreBitIdentical();
    void strainSamplesAreTheFirstStage();
    void maxVerticesStopsCleanly();
    void asynchronousReadIsDoubleBuffered();

private:
    std::optional<sim::opencl::Device> m_device;
};

void TestDeviceContours::initTestCase()
{
    try {
        m_device.emplace(sim::opencl::Device::open());
    } catch (const sim::opencl::DeviceError& e) {
        QSKIP(qPrintable(QStringLiteral("no OpenCL device: %1").arg(e.what())));
    }
    qInfo() << "device" << m_device->name().c_str();
}

void TestDeviceContours::bytesPerVertexWithinBudget()
{
    // 61 bytes, and the collapse's sweep grid of 8, kept through a pass's colours (opencl-backend.md).
    QVERIFY(DeviceContours::bytesPerVertex() <= 72);
}

void TestDeviceContours::compactionKeepsRingsOrdered()
{
    // Heavy insertion, then heavy deletion, on contours whose order is known: rings around one
    // centre. A drop there pushes every point radially (angles kept) and stretches the inner ring
    // twentyfold; a contraction toward the centre then shrinks all of them twelvefold. At every
    // step each ring must go once around the centre in strictly increasing angle. Uniform
    // spacing, so that the vertex count follows the perimeter (the proximity term would refine
    // the rings ever more as they close up), and the drop depicted by the spacing alone (an exact
    // depiction keeps short edges where they hold the shape).
    const Vec2 centre(0.5, 0.5);
    sim::TrackingSettings uniform = tracking(1.0 / 256, false);
    uniform.chordTolerance = 0.0;
    Pair pair(*m_device, FlowId::Contraction, uniform, false);
    for (int k = 1; k <= 3; ++k)
        pair.add(k - 1, sim::circle(centre, 0.01 * k, 1.0 / 256));
    const std::size_t before = pair.device().vertexCount();
    pair.drop(centre, 0.2, 3);
    QString violation = invariantViolation(pair.device().read(), pair.device().vertexCount(), centre);
    QVERIFY2(violation.isEmpty(), qPrintable("after the drop: " + violation));
    const std::size_t afterDrop = pair.device().vertexCount();
    QVERIFY2(afterDrop > 4 * before, qPrintable(QStringLiteral("%1 → %2 vertices").arg(before).arg(afterDrop)));
    for (int step = 0; step < 50; ++step) {
        pair.step(0.05);
        violation = invariantViolation(pair.device().read(), pair.device().vertexCount(), centre);
        QVERIFY2(violation.isEmpty(), qPrintable(QStringLiteral("step %1: ").arg(step) + violation));
    }
    qInfo() << "vertices: rings" << before << "after the drop" << afterDrop << "after contracting"
            << pair.device().vertexCount();
    QVERIFY(pair.device().vertexCount() < afterDrop / 4);
}

void TestDeviceContours::stretchAndReturnKeepsContoursValid()
{
    // The time-reversed vortex stretches a circle into a long spiral and winds it back: thousands
    // of insertions, then as many deletions, with adaptive spacing and proximity.
    Pair pair(*m_device, FlowId::SingleVortex, tracking(1.0 / 128, true), false);
    pair.add(0, sim::circle({0.5, 0.75}, 0.15, 1.0 / 128));
    pair.add(1, sim::circle({0.5, 0.3}, 0.1, 1.0 / 128));
    std::size_t most = 0;
    for (int step = 0; step < 400; ++step) {
        pair.step(0.02);
        const auto contours = pair.device().read();
        most = std::max(most, pair.device().vertexCount());
        const QString violation = invariantViolation(contours, pair.device().vertexCount());
        QVERIFY2(violation.isEmpty(), qPrintable(QStringLiteral("step %1: ").arg(step) + violation));
        QCOMPARE(crossings(contours), std::size_t(0));
    }
    qInfo() << "vertices: most" << most << "at the end" << pair.device().vertexCount();
}

void TestDeviceContours::sweepGridOverflowChangesNothing()
{
    // Rings and a drop contracted twelvefold at adaptive spacing: deletions and recentrings, some
    // into another bucket of the collapse's sweep grid. With the grid's overflow list at its length
    // and at one entry (read by the checks while it holds one, the grid built again when a pass
    // would overfill it), the same vertices, bit for bit, at every 10th step.
    std::vector<std::unique_ptr<Pair>> pairs;
    for (std::size_t overflow : {DeviceContours::sweepOverflowCapacity, std::size_t(1)}) {
        pairs.push_back(std::make_unique<Pair>(*m_device, FlowId::Contraction, tracking(1.0 / 1024, true), false,
                                               overflow));
        for (int k = 1; k <= 3; ++k)
            pairs.back()->add(k - 1, sim::circle({0.5 + 0.02 * k, 0.5}, 0.1 * k, 1.0 / 1024));
        pairs.back()->drop({0.45, 0.5}, 0.05, 3);
    }
    std::size_t most = 0;
    for (int step = 1; step <= 50; ++step) {
        for (auto& pair : pairs)
            pair->step(0.05);
        most = std::max(most, pairs[0]->device().vertexCount());
        if (step % 10 != 0)
            continue;
        const std::vector<sim::Contour> expected = pairs[0]->device().read();
        for (std::size_t k = 1; k < pairs.size(); ++k) {
            const std::vector<sim::Contour> got = pairs[k]->device().read();
            QCOMPARE(got.size(), expected.size());
            for (std::size_t c = 0; c < got.size(); ++c)
                QVERIFY2(got[c].positions == expected[c].positions,
                         qPrintable(QStringLiteral("step %1, list %2, contour %3: %4 vertices against %5")
                                        .arg(step)
                                        .arg(k)
                                        .arg(c)
                                        .arg(got[c].positions.size())
                                        .arg(expected[c].positions.size())));
        }
    }
    QVERIFY2(pairs[0]->device().vertexCount() < most / 2,
             qPrintable(QStringLiteral("%1 of at most %2 vertices left: few collapses")
                            .arg(pairs[0]->device().vertexCount())
                            .arg(most)));
}

void TestDeviceContours::rotationMatchesReference_data()
{
    QTest::addColumn<bool>("adaptive");
    QTest::newRow("uniform") << false;
    QTest::newRow("adaptive") << true;
}

void TestDeviceContours::rotationMatchesReference()
{
    QFETCH(bool, adaptive);
    Pair pair(*m_device, FlowId::Rotation, tracking(1.0 / 256, adaptive));
    const Polygon start = test::slottedDisk(1.0 / 256);
    pair.add(0, start);
    for (int step = 0; step < 200; ++step)
        pair.step(0.01);
    const Agreement a = compare(pair);
    const double returned = sim::hausdorffDistance(pair.device().read()[0].positions, start);
    qInfo() << qPrintable(describe(a, pair)) << "| return after one turn" << returned;
    QVERIFY2(a.hausdorff <= 1e-3 && a.countDifference <= 0.02, qPrintable(describe(a, pair)));
    QVERIFY2(returned < 0.002, qPrintable(QStringLiteral("return %1").arg(returned)));
}

void TestDeviceContours::singleVortexMatchesReference()
{
    Pair pair(*m_device, FlowId::SingleVortex, tracking(1.0 / 128, true));
    pair.add(0, sim::circle({0.5, 0.75}, 0.15, 1.0 / 128));
    for (int step = 1; step <= 400; ++step) {
        pair.step(0.02);
        if (step == 100 || step == 400) {
            const Agreement a = compare(pair);
            qInfo() << "t =" << step * 0.02 << qPrintable(describe(a, pair));
            QVERIFY2(a.hausdorff <= 1e-3 && a.countDifference <= 0.02, qPrintable(describe(a, pair)));
        }
    }
}

void TestDeviceContours::dropMatchesReference()
{
    // Drops on existing ink (the flow enters only through the vorticity term of the spacing): one
    // drop inside a circle, which becomes a ring, one between two others. Refinement bisects
    // edges stretched up to tenfold, as the reference does. The drops are depicted within 4e-7,
    // above what float positions resolve here (two roundings at 0.9: 2.1e-7), so that both
    // backends depict them alike.
    sim::TrackingSettings settings = tracking(1.0 / 256, true);
    settings.chordTolerance = 4e-7;
    Pair pair(*m_device, FlowId::SingleVortex, settings);
    pair.add(0, sim::circle({0.5, 0.5}, 0.15, 1.0 / 256));
    pair.add(1, sim::circle({0.75, 0.7}, 0.05, 1.0 / 256));
    pair.add(2, sim::circle({0.3, 0.75}, 0.08, 1.0 / 256));
    pair.drop({0.5, 0.55}, 0.1, 3);
    pair.drop({0.6, 0.75}, 0.07, 4);
    const Agreement a = compare(pair);
    qInfo() << qPrintable(describe(a, pair));
    QVERIFY2(a.hausdorff <= 1e-3 && a.countDifference <= 0.02, qPrintable(describe(a, pair)));
    const auto device = pair.device().read();
    const auto& reference = pair.reference().contours();
    for (std::size_t c = 0; c < device.size(); ++c)
        QVERIFY2(std::abs(device[c].targetArea - reference[c].targetArea) <= 1e-12,
                 qPrintable(QStringLiteral("contour %1 target %2 vs %3")
                                .arg(c)
                                .arg(device[c].targetArea)
                                .arg(reference[c].targetArea)));
    QCOMPARE(crossings(device), std::size_t(0));
}

void TestDeviceContours::singleVortexReturns_data()
{
    QTest::addColumn<bool>("areaCorrection");
    QTest::addColumn<double>("areaTolerance");
    QTest::newRow("plain") << false << 1e-3;
    QTest::newRow("area-correction") << true << 1e-5;
}

void TestDeviceContours::singleVortexReturns()
{
    // The accuracy bar (docs/method.md, "Accuracy"): circle r = 0.15 at (0.5, 0.75), period 8, uniform spacing 1/256, in float32.
    QFETCH(bool, areaCorrection);
    QFETCH(double, areaTolerance);
    auto settings = tracking(1.0 / 256, false);
    settings.areaCorrection = areaCorrection;
    Pair pair(*m_device, FlowId::SingleVortex, settings, false);
    const Polygon start = sim::circle({0.5, 0.75}, 0.15, 1.0 / 256);
    pair.add(0, start);
    const double startArea = sim::signedArea(start);
    double worstArea = 0.0;
    for (int step = 0; step < 800; ++step) {
        pair.step(0.01);
        worstArea = std::max(worstArea, std::abs(area(pair.device().read()) / startArea - 1.0));
    }
    const double shape = sim::hausdorffDistance(pair.device().read()[0].positions, start);
    qInfo() << "worst relative area error" << worstArea << "shape return" << shape << "vertices"
            << pair.device().vertexCount();
    QVERIFY2(worstArea < areaTolerance, qPrintable(QStringLiteral("area error %1").arg(worstArea)));
    QVERIFY2(shape < 0.002, qPrintable(QStringLiteral("shape return %1").arg(shape)));
}

// The strain check against the reference's where its largest term is one edge: inside a work-item's
// eight lanes, between two work-items, between two work-groups of 512 vertices, or a contour's
// closing edge. In the contraction flow an edge's velocity difference is the edge itself, so the
// strain is the longest edge's length · dt / d_max; small contours of 8 vertices stand before it.
void TestDeviceContours::strainMatchesReference_data()
{
    QTest::addColumn<int>("fillers");   // 8-vertex contours before the one with the long edge
    QTest::addColumn<int>("vertices");  // of the contour with the long edge
    QTest::addColumn<int>("longAfter"); // its vertex where the long edge starts
    QTest::newRow("within lanes (vertices 8, 9)") << 1 << 10 << 0;
    QTest::newRow("between work-items (15, 16)") << 1 << 10 << 7;
    QTest::newRow("between work-groups (511, 512)") << 63 << 20 << 7;
    QTest::newRow("closing edge (20, 8)") << 1 << 13 << 12;
}

void TestDeviceContours::strainMatchesReference()
{
    QFETCH(int, fillers);
    QFETCH(int, vertices);
    QFETCH(int, longAfter);
    const double dt = 0.01;
    Pair pair(*m_device, FlowId::Contraction, tracking(1.0, false));
    for (int k = 0; k < fillers; ++k)
        pair.add(k, sim::circle({0.1 + 0.0008 * k, 0.1}, 0.0002, 1.0));  // 8 vertices each
    pair.add(fillers, withOneLongEdge({0.5, 0.5}, 0.2, vertices, longAfter));
    const double longEdge = 0.2 * std::sqrt(2.0);
    const double device = pair.deviceStrain(dt), reference = pair.referenceStrain(dt);
    QVERIFY2(std::abs(reference - longEdge * dt) <= 1e-12, qPrintable(QString::number(reference)));
    QVERIFY2(std::abs(device - reference) <= 1e-5 * reference,
             qPrintable(QStringLiteral("device %1, reference %2").arg(device).arg(reference)));
}

// The strain check divides by each edge's spacing, the mean (d_i + d_j)/2 of its ends. On a regular
// 40-gon whose spacing alternates between two values every edge has the same mean, and the device
// agrees with the reference; an edge spacing taken from one end only would double the strain.
// The first four work-items' lanes take the vector path, the last the per-vertex one.
void TestDeviceContours::strainTakesEachEndsSpacing()
{
    const double dt = 0.01, radius = 0.2;
    const int n = 40;
    Pair pair(*m_device, FlowId::Contraction, tracking(1.0, false));
    sim::Contour contour;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * std::numbers::pi * k / n;
        contour.positions.push_back(Vec2(0.5, 0.5) + radius * Vec2(std::cos(a), std::sin(a)));
        contour.spacing.push_back(k % 2 == 0 ? 0.01 : 0.03);
    }
    contour.previous = contour.positions;
    contour.targetArea = sim::signedArea(contour.positions);
    pair.write({contour});
    const double edge = glm::distance(contour.positions[0], contour.positions[1]);
    const double device = pair.deviceStrain(dt), reference = pair.referenceStrain(dt);
    QVERIFY2(std::abs(reference - edge * dt / 0.02) <= 1e-12, qPrintable(QString::number(reference)));
    QVERIFY2(std::abs(device - reference) <= 1e-5 * reference,
             qPrintable(QStringLiteral("device %1, reference %2").arg(device).arg(reference)));
}

// A contour of five vertices fills part of one work-item's lanes; it turns with the rotation as
// the reference's does, and keeps its vertices (its edges lie between half and all of d_max).
void TestDeviceContours::smallContourMatchesReference()
{
    const double maxSpacing = 0.15;
    Pair pair(*m_device, FlowId::Rotation, tracking(maxSpacing, false));
    Polygon pentagon;
    for (int k = 0; k < 5; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 5;
        pentagon.push_back(Vec2(0.5, 0.5) + 0.1 * Vec2(std::cos(a), std::sin(a)));  // edges 0.118
    }
    pair.add(0, pentagon);
    for (int step = 0; step < 20; ++step)
        pair.step(0.01);
    QCOMPARE(pair.device().vertexCount(), std::size_t(5));
    const Agreement a = compare(pair);
    QVERIFY2(a.hausdorff <= 1e-5 && a.countDifference == 0.0, qPrintable(describe(a, pair)));
}

// The proximity term through the neighbour grid. Pairs of rings a third of the search radius
// apart (0.005; 0.0025 for one) come closest side by side and one above the other, inside the
// grid's torus and across its seams, where it joins its last column to its first (x = 0) and its
// last row to its first (y = 0): side by side across x = 0, one above the other across y = 0, and
// one above the other at the origin, across both. After one short step each vertex's spacing
// agrees with the reference's, and the term is active on every ring: where it comes closest to
// its neighbour its spacing falls below 0.7 d_max, where curvature alone would keep 0.85 d_max.
void TestDeviceContours::proximityMatchesReference()
{
    const double maxSpacing = 1.0 / 128, radius = 0.0975;
    Pair pair(*m_device, FlowId::Contraction, tracking(maxSpacing, true));
    const Vec2 centres[] = {{-0.1, 0.3}, {0.1, 0.3}, {0.3, -0.1}, {0.3, 0.1}, {0.0, -0.1},
                            {0.0, 0.1},  {0.4, 0.6}, {0.6, 0.6}, {0.6, 0.4}, {0.6, 0.2025}};
    for (int k = 0; k < int(std::size(centres)); ++k)
        pair.add(k, sim::circle(centres[k], radius, maxSpacing));
    pair.step(1e-6);
    const std::vector<sim::Contour> device = pair.device().read();
    const std::vector<sim::Contour>& reference = pair.reference().contours();
    QCOMPARE(device.size(), reference.size());
    double worst = 0.0;
    for (std::size_t c = 0; c < device.size(); ++c) {
        QCOMPARE(device[c].spacing.size(), reference[c].spacing.size());
        double smallest = maxSpacing;
        for (std::size_t i = 0; i < device[c].spacing.size(); ++i) {
            smallest = std::min(smallest, reference[c].spacing[i]);
            worst = std::max(worst, std::abs(device[c].spacing[i] - reference[c].spacing[i]) / reference[c].spacing[i]);
        }
        QVERIFY2(smallest < 0.7 * maxSpacing,
                 qPrintable(QStringLiteral("ring %1: smallest spacing %2 d_max").arg(c).arg(smallest / maxSpacing)));
    }
    qInfo() << "vertices" << pair.device().vertexCount() << "worst relative spacing difference" << worst;
    QVERIFY2(worst < 1e-4, qPrintable(QString::number(worst)));
}

void TestDeviceContours::runsAreBitIdentical()
{
    auto run = [&] {
        Pair pair(*m_device, FlowId::SingleVortex, tracking(1.0 / 128, true), false);
        pair.add(0, sim::circle({0.5, 0.75}, 0.15, 1.0 / 128));
        pair.add(1, sim::circle({0.5, 0.5}, 0.05, 1.0 / 128));
        for (int step = 0; step < 100; ++step)
            pair.step(0.02);
        pair.drop({0.4, 0.6}, 0.05, 2);
        return pair.device().read();
    };
    const auto first = run(), second = run();
    QCOMPARE(first.size(), second.size());
    for (std::size_t c = 0; c < first.size(); ++c) {
        QVERIFY(first[c].positions == second[c].positions);
        QVERIFY(first[c].previous == second[c].previous);
        QVERIFY(first[c].spacing == second[c].spacing);
    }
}

// RK4's first stage taken from the strain check is the stage itself: runs that take it and runs
// that sample again agree bit for bit, also when a contour is added between the strain check and
// the advection (the samples then lack its vertices, and the device must not use them).
void TestDeviceContours::strainSamplesAreTheFirstStage()
{
    auto run = [&](bool sampleAgain) {
        Pair pair(*m_device, FlowId::SingleVortex, tracking(1.0 / 128, true), false);
        pair.add(0, sim::circle({0.5, 0.75}, 0.15, 1.0 / 128));
        for (int step = 0; step < 40; ++step)
            pair.step(0.02, sampleAgain);
        pair.step(0.02, sampleAgain, [&] { pair.add(1, sim::circle({0.5, 0.5}, 0.05, 1.0 / 128)); });
        pair.drop({0.4, 0.6}, 0.05, 2);
        for (int step = 0; step < 10; ++step)
            pair.step(0.02, sampleAgain);
        return pair.device().read();
    };
    const auto taken = run(false), sampled = run(true);
    QCOMPARE(taken.size(), std::size_t(3));
    QCOMPARE(taken.size(), sampled.size());
    for (std::size_t c = 0; c < taken.size(); ++c) {
        QVERIFY(taken[c].positions == sampled[c].positions);
        QVERIFY(taken[c].previous == sampled[c].previous);
    }
}

void TestDeviceContours::maxVerticesStopsCleanly()
{
    auto settings = tracking(1.0 / 256, false);
    settings.maxVertices = 1000;
    Pair pair(*m_device, FlowId::SingleVortex, settings, false);
    pair.add(0, sim::circle({0.5, 0.75}, 0.15, 1.0 / 256));
    bool stopped = false;
    for (int step = 0; step < 200 && !stopped; ++step)
        stopped = !pair.step(0.02);
    QVERIFY2(stopped, "the vortex should need more than 1000 vertices");
    QVERIFY(pair.device().vertexCount() <= 1000);
    const auto contours = pair.device().read();
    QCOMPARE(totalVertices(contours), pair.device().vertexCount());
    QCOMPARE(crossings(contours), std::size_t(0));
}

void TestDeviceContours::asynchronousReadIsDoubleBuffered()
{
    Pair pair(*m_device, FlowId::SingleVortex, tracking(1.0 / 128, true), false);
    pair.add(0, sim::circle({0.5, 0.75}, 0.15, 1.0 / 128));
    pair.add(2, sim::circle({0.5, 0.4}, 0.1, 1.0 / 128));
    DeviceContours& device = pair.device();
    QVERIFY(!device.takeRead());
    pair.step(0.02);
    const auto first = device.read();
    QCOMPARE(device.requestRead(3), std::uint64_t(1));
    pair.step(0.02);
    const auto second = device.read();
    QCOMPARE(device.requestRead(3), std::uint64_t(2));
    pair.step(0.02);  // enqueued behind both copies
    const auto taken = device.takeRead(true);
    QVERIFY(taken);
    QCOMPARE(taken->request, std::uint64_t(2));  // the newest request
    QCOMPARE(taken->regions.size(), std::size_t(3));
    QVERIFY(taken->regions[1].empty());
    QCOMPARE(taken->regions[0].size(), std::size_t(1));
    QVERIFY(taken->regions[0][0] == second[0].positions);
    QVERIFY(taken->regions[2][0] == second[1].positions);
    QVERIFY(!device.takeRead(true));  // each at most once, the older one superseded
    QVERIFY(first[0].positions != second[0].positions);
    // A restore drops the copies requested before it.
    device.requestRead(3);
    device.write(second);
    QVERIFY(!device.takeRead(true));
}

QTEST_APPLESS_MAIN(TestDeviceContours)
#include "tst_device_contours.moc"
