#include "model/StateBlob.h"

#include "model/Scene.h"

#include <QtEndian>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <span>

namespace vf::model {
namespace {

using namespace Qt::StringLiterals;
using json::KeyPath;

static_assert(sizeof(sim::Vec2) == 2 * sizeof(double), "Vec2 arrays are written as packed doubles");

std::span<const double> flat(const std::vector<sim::Vec2>& points)
{
    return {reinterpret_cast<const double*>(points.data()), 2 * points.size()};
}

class BlobWriter {
public:
    explicit BlobWriter(QByteArray& out) : m_out(out) {}

    template <typename Int>
    void integer(Int value)
    {
        const Int little = qToLittleEndian(value);
        m_out.append(reinterpret_cast<const char*>(&little), sizeof little);
    }
    void number(double value) { integer(std::bit_cast<std::uint64_t>(value)); }
    // An array: its length in elements, then the elements.
    void numbers(std::span<const double> values)
    {
        integer(std::uint64_t(values.size()));
        raw(values);
    }
    void points(const std::vector<sim::Vec2>& points)
    {
        integer(std::uint64_t(points.size()));
        raw(flat(points));
    }

private:
    void raw(std::span<const double> values)
    {
        if constexpr (std::endian::native == std::endian::little) {
            m_out.append(reinterpret_cast<const char*>(values.data()), qsizetype(values.size_bytes()));
        } else {
            for (double value : values)
                number(value);
        }
    }

    QByteArray& m_out;
};

class BlobReader {
public:
    BlobReader(const QByteArray& bytes, KeyPath where) : m_bytes(bytes), m_where(std::move(where)) {}

    template <typename Int>
    Int integer(const char* what)
    {
        Int little;
        std::memcpy(&little, take(sizeof little, what), sizeof little);
        return qFromLittleEndian(little);
    }
    double number(const char* what) { return std::bit_cast<double>(integer<std::uint64_t>(what)); }
    // An array's length, checked against the bytes left before anyone allocates for it.
    std::size_t count(std::size_t elementBytes, const char* what)
    {
        const auto n = integer<std::uint64_t>(what);
        if (n > left() / elementBytes)
            fail(u"%1: %2 entries do not fit in the %3 bytes left"_s.arg(QLatin1String(what)).arg(n).arg(left()));
        return std::size_t(n);
    }
    std::vector<double> numbers(const char* what)
    {
        std::vector<double> values(count(sizeof(double), what));
        read(values.data(), values.size(), what);
        return values;
    }
    std::vector<sim::Vec2> points(const char* what)
    {
        const std::size_t n = count(2 * sizeof(double), what);
        std::vector<sim::Vec2> points(n);
        read(reinterpret_cast<double*>(points.data()), 2 * n, what);
        return points;
    }
    void finish() const
    {
        if (left() != 0)
            fail(u"%1 bytes left over after the state (a blob holds exactly one)"_s.arg(left()));
    }
    [[noreturn]] void fail(const QString& what) const { m_where.fail(what); }

private:
    std::size_t left() const { return std::size_t(m_bytes.size()) - m_position; }
    const char* take(std::size_t n, const char* what)
    {
        if (n > left())
            fail(u"the state ends in the middle of %1 (at byte %2 of %3)"_s.arg(QLatin1String(what)).arg(m_position).arg(m_bytes.size()));
        const char* data = m_bytes.constData() + m_position;
        m_position += n;
        return data;
    }
    void read(double* out, std::size_t n, const char* what)
    {
        const char* data = take(n * sizeof(double), what);
        if (n == 0)
            return;  // memcpy wants valid pointers even for no bytes
        if constexpr (std::endian::native == std::endian::little) {
            std::memcpy(out, data, n * sizeof(double));
        } else {
            for (std::size_t i = 0; i < n; ++i, data += sizeof(double)) {
                std::uint64_t little;
                std::memcpy(&little, data, sizeof little);
                out[i] = std::bit_cast<double>(qFromLittleEndian(little));
            }
        }
    }

    const QByteArray& m_bytes;
    KeyPath m_where;
    std::size_t m_position = 0;
};

// ---- checks -----------------------------------------------------------------------------------

bool allFinite(std::span<const double> values)
{
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

void checkFinite(std::span<const double> values, const QString& what, const KeyPath& where)
{
    if (!allFinite(values))
        where.fail(u"%1 holds a value that is not finite (NaN or infinity)"_s.arg(what));
}

void checkLength(std::size_t size, std::size_t expected, const QString& what, const KeyPath& where)
{
    if (size != expected)
        where.fail(u"%1 has %2 values, expected %3"_s.arg(what).arg(size).arg(expected));
}

void checkContour(const sim::Contour& c, int regionCount, const QString& name, const KeyPath& where)
{
    if (c.region < 0 || c.region >= regionCount)
        where.fail(u"%1 belongs to region %2, outside the state's %3 regions"_s.arg(name).arg(c.region).arg(regionCount));
    const std::size_t n = c.positions.size();
    if (n < 3)
        where.fail(u"%1 has %2 vertices, a closed contour needs at least 3"_s.arg(name).arg(n));
    if (c.previous.size() != n || c.spacing.size() != n)
        where.fail(u"%1 has %2 positions but %3 previous positions and %4 spacings (they must agree)"_s
                       .arg(name).arg(n).arg(c.previous.size()).arg(c.spacing.size()));
    checkFinite(flat(c.positions), name + u" positions"_s, where);
    checkFinite(flat(c.previous), name + u" previous positions"_s, where);
    checkFinite(c.spacing, name + u" spacing"_s, where);
    checkFinite({&c.targetArea, 1}, name + u" target area"_s, where);
}

void checkFluid(const sim::FluidState& fluid, const KeyPath& where)
{
    const sim::MacVelocity& v = fluid.velocity;
    if (v.nx < limits::minGrid || v.nx > limits::maxGrid || v.ny < limits::minGrid || v.ny > limits::maxGrid)
        where.fail(u"the fluid grid %1 x %2 is outside [%3, %4]"_s.arg(v.nx).arg(v.ny).arg(limits::minGrid).arg(limits::maxGrid));
    if (!(std::isfinite(v.hx) && v.hx > 0.0 && std::isfinite(v.hy) && v.hy > 0.0))
        where.fail(u"the fluid cell size %1 x %2 is not positive and finite"_s.arg(v.hx).arg(v.hy));
    const auto nx = std::size_t(v.nx), ny = std::size_t(v.ny);
    checkLength(v.u.size(), (nx + 1) * ny, u"the velocity u"_s, where);
    checkLength(v.v.size(), nx * (ny + 1), u"the velocity v"_s, where);
    checkLength(fluid.pressure.size(), nx * ny, u"the pressure"_s, where);
    checkFinite(v.u, u"the velocity u"_s, where);
    checkFinite(v.v, u"the velocity v"_s, where);
    checkFinite(fluid.pressure, u"the pressure"_s, where);
}

} // namespace

void checkState(const sim::SimulationState& state, const KeyPath& where)
{
    checkFinite({&state.time, 1}, u"the time"_s, where);
    if (state.regionCount < 0 || std::size_t(state.regionCount) > limits::maxRegions)
        where.fail(u"the region count %1 is outside [0, %2]"_s.arg(state.regionCount).arg(limits::maxRegions));
    for (std::size_t i = 0; i < state.contours.size(); ++i)
        checkContour(state.contours[i], state.regionCount, u"contour %1"_s.arg(i), where);
    if (state.fluid)
        checkFluid(*state.fluid, where);
    for (std::size_t i = 0; i < state.pendingStylus.size(); ++i) {
        const sim::StylusSegment& s = state.pendingStylus[i];
        const double values[] = {s.from.x, s.from.y, s.to.x, s.to.y, s.radius, s.duration};
        checkFinite(values, u"pending stylus segment %1"_s.arg(i), where);
    }
}

// The layout is docs/project-format.md's "State blobs" table, field by field.
QByteArray encodeState(const sim::SimulationState& state)
{
    QByteArray out;
    out.reserve(qsizetype(state.bytes()));
    BlobWriter blob(out);
    blob.number(state.time);
    blob.integer(std::int32_t(state.regionCount));
    blob.integer(std::uint64_t(state.contours.size()));
    for (const sim::Contour& c : state.contours) {
        blob.integer(std::int32_t(c.region));
        blob.number(c.targetArea);
        blob.points(c.positions);
        blob.points(c.previous);
        blob.numbers(c.spacing);
    }
    blob.integer(std::uint8_t(state.fluid ? 1 : 0));
    if (state.fluid) {
        const sim::MacVelocity& v = state.fluid->velocity;
        blob.integer(std::int32_t(v.nx));
        blob.integer(std::int32_t(v.ny));
        blob.number(v.hx);
        blob.number(v.hy);
        blob.numbers(v.u);
        blob.numbers(v.v);
        blob.numbers(state.fluid->pressure);
    }
    blob.integer(std::uint64_t(state.pendingStylus.size()));
    for (const sim::StylusSegment& s : state.pendingStylus) {
        for (double value : {s.from.x, s.from.y, s.to.x, s.to.y, s.radius, s.duration})
            blob.number(value);
    }
    return out;
}

sim::SimulationState decodeState(const QByteArray& bytes, const KeyPath& where)
{
    // The smallest encoded contour: region, target area and three empty arrays.
    constexpr std::size_t kMinContourBytes = 4 + 8 + 3 * 8;
    constexpr std::size_t kStylusBytes = 6 * 8;

    BlobReader blob(bytes, where);
    sim::SimulationState state;
    state.time = blob.number("the time");
    state.regionCount = blob.integer<std::int32_t>("the region count");
    state.contours.resize(blob.count(kMinContourBytes, "the contours"));
    for (sim::Contour& c : state.contours) {
        c.region = blob.integer<std::int32_t>("a contour's region");
        c.targetArea = blob.number("a contour's target area");
        c.positions = blob.points("a contour's positions");
        c.previous = blob.points("a contour's previous positions");
        c.spacing = blob.numbers("a contour's spacing");
    }
    const auto hasFluid = blob.integer<std::uint8_t>("the fluid flag");
    if (hasFluid > 1)
        blob.fail(u"the fluid flag is %1, must be 0 or 1"_s.arg(hasFluid));
    if (hasFluid) {
        sim::FluidState& fluid = state.fluid.emplace();
        sim::MacVelocity& v = fluid.velocity;
        v.nx = blob.integer<std::int32_t>("the grid width");
        v.ny = blob.integer<std::int32_t>("the grid height");
        v.hx = blob.number("the cell width");
        v.hy = blob.number("the cell height");
        v.u = blob.numbers("the velocity u");
        v.v = blob.numbers("the velocity v");
        fluid.pressure = blob.numbers("the pressure");
    }
    state.pendingStylus.resize(blob.count(kStylusBytes, "the pending stylus"));
    for (sim::StylusSegment& s : state.pendingStylus) {
        s.from.x = blob.number("a stylus segment");
        s.from.y = blob.number("a stylus segment");
        s.to.x = blob.number("a stylus segment");
        s.to.y = blob.number("a stylus segment");
        s.radius = blob.number("a stylus segment");
        s.duration = blob.number("a stylus segment");
    }
    blob.finish();
    checkState(state, where);
    return state;
}

} // namespace vf::model
