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

// A packed array (StateEncoding::Packed, PackedLinear) stores each value's 64 bits as the difference
// from a prediction of them: the value `stride` places before (Packed), or where the line through
// the two values `stride` and 2·`stride` places before goes on (PackedLinear: a contour's points
// and spacings and a grid's values are smooth, so their second differences are smaller than their
// first; in the bits, which is exact), or, with a reference array, the same place
// there moved as the value `stride` places before moved from its own (a previous position is its
// position displaced as the vertex before was: the flow is smooth along a contour). The first
// `stride` values without a reference, with nothing before them, are stored as they are. Neighbouring vertices and grid cells are close, so the
// differences are small numbers. The trailing zero bits that all of them share are shifted out (the
// OpenCL backend's float32 values widened to double end in 29 of them), zigzag makes small negative
// ones small too (0, -1, 1, -2... become 0, 1, 2, 3...), and the rest is stored as byte planes, lowest first,
// leaving out planes that are zero throughout: every value's lowest byte, then every value's next
// byte, and so on. Planes of close values are long runs that deflate shrinks well.
struct Prediction {
    std::size_t stride = 1;             // from the value this many places before, at least 1
    std::span<const double> reference;  // where given: from the same place here, moved likewise
    bool linear = false;                // without a reference: on the line through two values before
};

constexpr Prediction kPointPrediction{2, {}};  // x from the previous x, y from the previous y

std::uint64_t bitsOf(double value) { return std::bit_cast<std::uint64_t>(value); }

std::uint64_t zigzag(std::uint64_t difference) { return (difference << 1) ^ (0 - (difference >> 63)); }
std::uint64_t unzigzag(std::uint64_t z) { return (z >> 1) ^ (0 - (z & 1)); }

// The prediction for values[i] (i past the head): only values before i are read, so a reader can
// predict from what it has decoded so far.
std::uint64_t predicted(const double* values, std::size_t i, const Prediction& prediction)
{
    const std::size_t before = i - prediction.stride;  // wraps for the first values; not read then
    if (prediction.reference.empty() && prediction.linear && i >= 2 * prediction.stride)
        return 2 * bitsOf(values[before]) - bitsOf(values[before - prediction.stride]);
    if (prediction.reference.empty())
        return bitsOf(values[before]);
    // In the bits, wrapping: exact and the same on every machine, unlike arithmetic on doubles.
    const std::uint64_t moved = i >= prediction.stride ? bitsOf(values[before]) - bitsOf(prediction.reference[before]) : 0;
    return bitsOf(prediction.reference[i]) + moved;
}

Prediction withEncoding(Prediction prediction, StateEncoding encoding)
{
    prediction.linear = encoding == StateEncoding::PackedLinear;
    return prediction;
}

// How many values at the start are stored as they are.
std::size_t headOf(std::size_t n, const Prediction& prediction)
{
    return prediction.reference.empty() ? std::min(n, prediction.stride) : 0;
}

// Plane 0 is always stored, so that every value takes at least a byte: a reader can check a count
// against the bytes left before allocating, as for plain arrays.
uchar storedPlanes(std::uint64_t anyBits)
{
    uchar planes = 1;
    for (int b = 1; b < 8; ++b)
        if ((anyBits >> (8 * b)) & 0xff)
            planes |= uchar(1 << b);
    return planes;
}

// After the head, as BlobWriter::number writes them.
void appendPacked(QByteArray& out, std::span<const double> values, const Prediction& prediction)
{
    const std::size_t head = headOf(values.size(), prediction), n = values.size() - head;
    std::vector<std::uint64_t> residuals(n);
    std::uint64_t anyBits = 0;
    for (std::size_t i = 0; i < n; ++i) {
        residuals[i] = bitsOf(values[head + i]) - predicted(values.data(), head + i, prediction);
        anyBits |= residuals[i];
    }
    const int shift = anyBits == 0 ? 0 : std::countr_zero(anyBits);
    anyBits = 0;
    for (std::uint64_t& r : residuals) {
        r = zigzag(std::uint64_t(std::int64_t(r) >> shift));  // exact: the bits shifted out are zero
        anyBits |= r;
    }
    const uchar planes = storedPlanes(anyBits);
    out.append(char(shift));
    out.append(char(planes));
    qsizetype at = out.size();
    out.resize(at + qsizetype(n) * std::popcount(planes));
    auto* bytes = reinterpret_cast<uchar*>(out.data());
    for (int b = 0; b < 8; ++b) {
        if (!(planes & (1 << b)))
            continue;
        for (std::size_t i = 0; i < n; ++i)
            bytes[at++] = uchar(residuals[i] >> (8 * b));
    }
}

class BlobWriter {
public:
    BlobWriter(QByteArray& out, StateEncoding encoding) : m_out(out), m_encoding(encoding) {}

    template <typename Int>
    void integer(Int value)
    {
        const Int little = qToLittleEndian(value);
        m_out.append(reinterpret_cast<const char*>(&little), sizeof little);
    }
    void number(double value) { integer(bitsOf(value)); }
    // An array: its length in elements, then the elements.
    void numbers(std::span<const double> values, const Prediction& prediction = {})
    {
        integer(std::uint64_t(values.size()));
        raw(values, prediction);
    }
    void points(const std::vector<sim::Vec2>& points, const Prediction& prediction = kPointPrediction)
    {
        integer(std::uint64_t(points.size()));
        raw(flat(points), prediction);
    }

private:
    void raw(std::span<const double> values, const Prediction& prediction)
    {
        if (m_encoding != StateEncoding::Plain) {
            for (double value : values.first(headOf(values.size(), prediction)))
                number(value);
            appendPacked(m_out, values, withEncoding(prediction, m_encoding));
        } else if constexpr (std::endian::native == std::endian::little) {
            m_out.append(reinterpret_cast<const char*>(values.data()), qsizetype(values.size_bytes()));
        } else {
            for (double value : values)
                number(value);
        }
    }

    QByteArray& m_out;
    StateEncoding m_encoding;
};

class BlobReader {
public:
    BlobReader(const QByteArray& bytes, StateEncoding encoding, KeyPath where)
        : m_bytes(bytes), m_encoding(encoding), m_where(std::move(where))
    {
    }

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
    std::vector<double> numbers(const char* what, const Prediction& prediction = {})
    {
        std::vector<double> values(count(valueBytes(), what));
        read(values.data(), values.size(), what, prediction);
        return values;
    }
    std::vector<sim::Vec2> points(const char* what, const Prediction& prediction = kPointPrediction)
    {
        const std::size_t n = count(2 * valueBytes(), what);
        std::vector<sim::Vec2> points(n);
        read(reinterpret_cast<double*>(points.data()), 2 * n, what, prediction);
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
    // The fewest bytes a value of an array takes.
    std::size_t valueBytes() const { return m_encoding == StateEncoding::Plain ? sizeof(double) : 1; }
    void read(double* out, std::size_t n, const char* what, const Prediction& prediction)
    {
        if (m_encoding != StateEncoding::Plain) {
            readPacked(out, n, what, withEncoding(prediction, m_encoding));
            return;
        }
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
    void readPacked(double* out, std::size_t count, const char* what, const Prediction& prediction)
    {
        const std::size_t head = headOf(count, prediction), n = count - head;
        for (std::size_t i = 0; i < head; ++i)
            out[i] = number(what);
        const auto shift = integer<std::uint8_t>(what);
        const auto planes = integer<std::uint8_t>(what);
        if (shift > 63 || !(planes & 1))
            fail(u"%1: a packed array's shift %2 or planes %3 are impossible"_s.arg(QLatin1String(what)).arg(shift).arg(planes));
        if (!prediction.reference.empty() && prediction.reference.size() != count)
            fail(u"%1: %2 values, but %3 to predict them from"_s.arg(QLatin1String(what)).arg(count).arg(prediction.reference.size()));
        const auto* bytes = reinterpret_cast<const uchar*>(take(n * std::size_t(std::popcount(planes)), what));
        std::vector<std::uint64_t> residuals(n, 0);
        for (int b = 0; b < 8; ++b) {
            if (!(planes & (1 << b)))
                continue;
            for (std::size_t i = 0; i < n; ++i)
                residuals[i] |= std::uint64_t(*bytes++) << (8 * b);
        }
        for (std::size_t i = 0; i < n; ++i)
            out[head + i] = std::bit_cast<double>((unzigzag(residuals[i]) << shift) + predicted(out, head + i, prediction));
    }

    const QByteArray& m_bytes;
    StateEncoding m_encoding;
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
QByteArray encodeState(const sim::SimulationState& state, StateEncoding encoding)
{
    QByteArray out;
    out.reserve(qsizetype(state.bytes()));
    BlobWriter blob(out, encoding);
    blob.number(state.time);
    blob.integer(std::int32_t(state.regionCount));
    blob.integer(std::uint64_t(state.contours.size()));
    for (const sim::Contour& c : state.contours) {
        blob.integer(std::int32_t(c.region));
        blob.number(c.targetArea);
        blob.points(c.positions);
        blob.points(c.previous, {2, flat(c.positions)});
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

sim::SimulationState decodeState(const QByteArray& bytes, StateEncoding encoding, const KeyPath& where)
{
    // The smallest encoded contour: region, target area and three empty arrays.
    constexpr std::size_t kMinContourBytes = 4 + 8 + 3 * 8;
    constexpr std::size_t kStylusBytes = 6 * 8;

    BlobReader blob(bytes, encoding, where);
    sim::SimulationState state;
    state.time = blob.number("the time");
    state.regionCount = blob.integer<std::int32_t>("the region count");
    state.contours.resize(blob.count(kMinContourBytes, "the contours"));
    for (sim::Contour& c : state.contours) {
        c.region = blob.integer<std::int32_t>("a contour's region");
        c.targetArea = blob.number("a contour's target area");
        c.positions = blob.points("a contour's positions");
        c.previous = blob.points("a contour's previous positions", {2, flat(c.positions)});
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
