// The contour tracker of sim/ContourTracker.cpp on an OpenCL device: the host side of one step
// (advect, spacing, proximity grid, refinement by stream compaction with the collapse's sweep grid,
// area correction, the cuts of contour surgery, the widening of layers) and the transfers in and
// out. One file because every phase works on the same device buffers, held in Impl, and its
// launches must agree with them; the kernels are in contours*.cl, split by phase.
// The seam for a split is the read-back half (snapshots, outlines, staging, requests, from
// enqueueSnapshot on): it only reads the vertex buffers (through the motion scratch), and would
// move out with Impl's declaration in a private header shared by both files; contour surgery
// (cutPinches, applyCuts, separateLayers) could follow it, as it reads the positions back the same way.
#include "sim/opencl/DeviceContours.h"

#include "sim/ContourTracker.h"
#include "sim/CrossedChords.h"
#include "sim/Crossings.h"
#include "sim/Drop.h"
#include "sim/Pinches.h"
#include "sim/Separation.h"
#include "sim/SpacingField.h"

#include "sim/opencl/ContourCodes.h"
#include "sim/opencl/KernelSources.h"
#include "sim/opencl/Launch.h"
#include "sim/opencl/MapParameters.h"
#include "sim/opencl/Scan.h"


#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace vf::sim::opencl {

namespace {

constexpr int maxRounds = 16;  // as ContourTracker::refine
// The smallest capacity, and the smallest proximity grid (buckets): small scenes pay a fixed 1 MB
// rather than a grid so coarse that every bucket holds vertices from far apart.
constexpr std::size_t minCapacity = std::size_t(1) << 14;


// MOTION_ARGS of contours.cl: how vertices move in this step, and where split vertices go.
struct Motion {
    cl_int kind = motionFlow;  // RK4 through the flow, the drop's push or a comb
    Parameters a{}, b{}, c{};  // the map's parameters (contours.cl, MOTION_ARGS), in acc_t
    cl_int rewind = 1;         // TrackingSettings::timeRewinding
    cl_float chordTolerance = 0.0f;  // a map's, ExactMotion's (none for the flow)
    bool fp64 = false;               // acc_t is double
};

void setKernelArg(cl::Kernel& kernel, cl_uint& index, const Parameters& p, bool fp64)
{
    if (fp64)
        kernel.setArg(index++, cl_double4{{p[0], p[1], p[2], p[3]}});
    else
        kernel.setArg(index++, cl_float4{{cl_float(p[0]), cl_float(p[1]), cl_float(p[2]), cl_float(p[3])}});
}

void setKernelArg(cl::Kernel& kernel, cl_uint& index, const Motion& motion)
{
    kernel.setArg(index++, motion.kind);
    for (const Parameters& p : {motion.a, motion.b, motion.c})
        setKernelArg(kernel, index, p, motion.fp64);
    kernel.setArg(index++, motion.rewind);
    kernel.setArg(index++, motion.chordTolerance);
}

// A kernel argument of the accumulation type acc_t: double on fp64 devices, else float.
struct Accumulated {
    double value;
    bool fp64;
};

void setKernelArg(cl::Kernel& kernel, cl_uint& index, const Accumulated& a)
{
    if (a.fp64)
        kernel.setArg(index++, a.value);
    else
        kernel.setArg(index++, cl_float(a.value));
}

// The proximity grid (GRID_ARGS in contours_spacing.cl): cells as wide as the search radius on a
// torus of 2^columnBits × 2^rowBits buckets.
struct Grid {
    cl_float cellSize;
    cl_uint columnBits, rowBits;
    std::size_t buckets() const { return std::size_t(1) << (columnBits + rowBits); }
};

void setKernelArg(cl::Kernel& kernel, cl_uint& index, const Grid& grid)
{
    kernel.setArg(index++, grid.cellSize);
    kernel.setArg(index++, grid.columnBits);
    kernel.setArg(index++, grid.rowBits);
}

struct VertexSet {
    cl::Buffer motion;   // float4 (position, previous)
    cl::Buffer spacing;  // float d_i
    cl::Buffer contour;  // uint contour index
};

// Geometry copied from the device for read(): every field.
struct Snapshot {
    std::vector<cl_float4> motion;
    std::vector<float> spacing;
    std::vector<cl_uint> offset, count;
    std::vector<int> regions;
    std::vector<double> targets;
    cl::Event done;  // the last of the copies
};

// Positions copied from the device for a display (requestRead), and where each contour lies.
struct Outlines {
    std::vector<cl_float2> positions;
    std::vector<cl_uint> offset, count;
    std::vector<int> regions;  // each contour's
    int regionCount = 0;
    cl::Event done;              // the last of the copies
    std::uint64_t serial = 0;    // which request filled it; 0: none
    bool taken = true;
};

// Enqueues a copy of `values` into `buffer` from element `first` on (nothing when there are none).
template <class Values>
void put(cl::CommandQueue& queue, const cl::Buffer& buffer, std::size_t first, const Values& values)
{
    if (!values.empty())
        queue.enqueueWriteBuffer(buffer, CL_FALSE, first * sizeof(values[0]), values.size() * sizeof(values[0]),
                                 values.data());
}

// True once the command is done; a command that failed is a device failure.
bool isComplete(const cl::Event& event)
{
    const cl_int status = event.getInfo<CL_EVENT_COMMAND_EXECUTION_STATUS>();
    if (status < 0)
        throw cl::Error(status, "a readback failed");
    return status == CL_COMPLETE;
}

// VF_OPENCL_MAX_VERTICES, a test and diagnostic knob: the device holds at most this many vertices,
// as if its memory ended there, so the paths past the device's limit can be exercised without
// exhausting a real device. Unset: no cap.
std::optional<std::size_t> vertexCapFromEnvironment()
{
    const char* value = std::getenv("VF_OPENCL_MAX_VERTICES");
    if (!value)
        return std::nullopt;
    std::size_t cap = 0;
    const char* end = value + std::strlen(value);
    const auto [at, error] = std::from_chars(value, end, cap);
    if (error != std::errc() || at != end || cap == 0)
        throw DeviceError("VF_OPENCL_MAX_VERTICES='" + std::string(value) + "' is not a positive vertex count");
    return cap;
}

template <typename F>
auto guarded(F&& f) -> decltype(f())
{
    try {
        return f();
    } catch (const cl::Error& e) {
        throw DeviceError("OpenCL error in the contour tracker: " + std::string(e.what()) + " (" +
                          std::to_string(e.err()) + ")");
    }
}

} // namespace

struct DeviceContours::Impl {
    Impl(Device& device, const TrackingSettings& settings, Vec2 canvas, const std::string& flowSource,
         std::size_t sweepOverflow);
    // Copies into the staging buffers may still be running: they finish before the buffers go.
    ~Impl();

    cl::Buffer buffer(std::size_t bytes) const { return cl::Buffer(device.context(), CL_MEM_READ_WRITE, bytes); }
    VertexSet vertexSet(std::size_t size) const;
    std::size_t deviceLimit() const;
    bool reserve(std::size_t needed);
    void reserveContours(std::size_t needed);
    std::size_t tiles() const { return roundUpToLocal(vertices + 1) / localSize; }
    Grid grid() const;
    Grid sweepGrid() const;
    std::size_t bucketsFor(std::size_t perBucket) const;
    Motion flowMotion() const { return Motion{motionFlow, {}, {}, {}, cl_int(settings.timeRewinding), 0.0f, fp64}; }
    Motion mapMotion(cl_int kind, const Parameters& a, const Parameters& b, const Parameters& c = {}) const
    {
        return Motion{kind, a, b, c, cl_int(settings.timeRewinding), cl_float(settings.chordTolerance), fp64};
    }

    // `exact`: the motion on the host, for an exact one (a drop, a tool's map).
    bool move(const FlowBinding& flow, const Motion& motion, bool startKnown = false,
              const ExactMotion* exact = nullptr);
    void splitCrossedChords(const ExactMotion& motion);
    std::size_t cutPinches();
    void computeSpacing(const FlowBinding& flow);
    void findNearestOtherParts(const Grid& grid);
    void buildGrid(const Grid& grid);
    void buildSweepGrid(const Grid& grid);
    bool refine(const FlowBinding& flow, const Motion& motion);
    struct Pass {
        bool withinBudget = true;
        bool changed = false;  // the scanned vertex count differs from the current one
        cl_uint flags = 0;     // FLAG_SHORT_EDGE(colour), FLAG_RECENTRED, FLAG_SPLIT_CAPPED
        cl_uint across = 0;    // a collapse decision's recentrings into another bucket of the sweep grid
        std::size_t total = 0; // the scanned vertex count
    };
    Pass countSplits(const FlowBinding& flow, const Motion& motion);
    Pass splitPass(const FlowBinding& flow, const Motion& motion);
    // The collapse's sweep grid while it holds the present positions: its geometry, and at least as
    // many entries as its overflow list holds (a recentring into another bucket of a vertex already
    // there takes no new one).
    struct SweepGrid {
        Grid grid;
        cl_uint overflowing = 0;
    };
    bool collapsePass(const FlowBinding& flow, const Motion& motion, cl_uint colours, std::optional<SweepGrid>& sweep);
    void lookAtEveryTile();
    void clearMarks(cl::Buffer& marks);
    void clearPassFlags();
    Pass readPass();
    void adopt(std::size_t total);
    void contourTerms(cl_int mode, Vec2 point, double dropArea, bool hold);
    // The squared distance within which other ink holds a vertex still in the area correction.
    cl_float holdWithin2() const
    {
        const auto within = cl_float(settings.areaHoldDistance());
        return within * within;
    }
    void correctAreas();
    void enqueueSnapshot(Snapshot& s);
    std::vector<Contour> toContours(const Snapshot& s) const;
    void enqueueOutlines(Outlines& s);
    void place(const std::vector<Contour>& contours, std::size_t firstVertex, std::size_t firstContour);
    void putContours(std::size_t firstContour, const std::vector<cl_uint>& offset, const std::vector<cl_uint>& count,
                     const std::vector<double>& areas);
    std::size_t applyCuts(const std::vector<ContourCut>& cuts);
    struct HostOutlines;
    HostOutlines readOutlines();
    void moveVertices(HostOutlines& host, const std::vector<VertexMove>& moves);

    Device& device;
    cl::CommandQueue& queue;
    const TrackingSettings settings;
    const Vec2 canvas;
    const bool fp64;
    const std::size_t accSize;
    const std::optional<std::size_t> vertexCap;  // VF_OPENCL_MAX_VERTICES
    Scan countScan, sumScan;
    cl::Kernel advect, strain, positionsOf, gatherVertices, arcTilesAndCount, gridScatter, sweepGridPass,
        nearestOtherPart, nearestBeyond, rawSpacing, smoothSpacing, splitCount, splitScatter, recountContours,
        collapseDecide, collapseScatter, recentreInPlace, contourTermTiles, contourTermSums, correctArea;

    // Vertices: two sets (compaction scatters from one into the other, then they swap) and scratch.
    std::size_t capacity = 0, vertices = 0;
    std::size_t paddedCapacity = 0;  // entries of each per-vertex array (see reserve())
    VertexSet front, back;
    // back.motion is scratch. After a strain check it holds, as float2, the flow's velocity at every
    // vertex, which the next advection reuses as RK4's first stage: valid until the scratch is
    // taken for anything else (motionScratch()) or the vertices are replaced (place()).
    bool strainSamplesKept = false;
    cl::Buffer& motionScratch()
    {
        strainSamplesKept = false;
        return back.motion;
    }
    cl::Buffer tileOffset;  // uint per vertex: offset within its tile, from the counting kernels
    cl::Buffer work;        // uint per vertex: grid bucket counts, then starts
    cl::Buffer actions;     // uint per vertex: what a collapse pass does with each vertex
    cl::Buffer sweepEntries;  // float2 per vertex: the collapse's sweep grid (buildSweepGrid())
    cl::Buffer sweepOverflow;  // overflowCapacity float2: the sweep grid's overflow list
    cl::Buffer tileTotals;  // one acc4 per tile: uint, acc_t or acc4 totals, as the pass needs
    cl::Buffer tileActive;  // uint per tile: refinement looks at its vertices (contours_refine.cl)
    // uint per tile: where the next pass looks, marked by a counting kernel (tileMarks, where
    // nothing moves) and by a scatter (tileMarksMoved, where its vertices land).
    cl::Buffer tileMarks, tileMarksMoved;

    // Contours: device arrays, and the host's regions and area targets.
    std::size_t contourCapacity = 0;
    std::vector<int> regions;
    std::vector<double> targets;
    cl::Buffer contourOffset, contourCount;  // uint
    cl::Buffer contourLength;                // float, the proximity term's arc lengths
    cl::Buffer contourTarget, contourLambda; // acc_t, the area correction

    cl::Buffer weights;  // eq. 6's Gaussian, constant
    cl::Buffer status;   // statusWords uint
    int smoothingRadius;
    const cl_uint overflowCapacity;
    EdgeGrid::Storage pinchGrid;  // the host's pinch search (cutPinches)

    std::array<Outlines, 2> staging;
    std::uint64_t requests = 0;
    PhaseClock* clock = nullptr;
};

DeviceContours::Impl::Impl(Device& device_, const TrackingSettings& settings_, Vec2 canvas_,
                           const std::string& flowSource, std::size_t sweepOverflow_)
    : device(device_)
    , queue(device_.queue())
    , settings(settings_)
    , canvas(canvas_)
    , fp64(device_.hasFp64())
    , accSize(fp64 ? sizeof(double) : sizeof(float))
    , vertexCap(vertexCapFromEnvironment())
    , countScan(device_, "uint", sizeof(cl_uint), commonBuildOptions(fp64))
    , sumScan(device_, fp64 ? "double" : "float", accSize, commonBuildOptions(fp64))
    , smoothingRadius(std::max(0, settings_.smoothingRadius))
    , overflowCapacity(cl_uint(sweepOverflow_))
{
    const std::string acc = fp64 ? "double" : "float";
    const std::string options =
        commonBuildOptions(fp64) + " -DVF_ACC=" + acc + " -DVF_ACC2=" + acc + "2 -DVF_ACC4=" + acc + "4" +
        " -DVF_RECENTRE_CORRECTIONS=" + std::to_string(recentreCorrections) +
        " -DVF_TIP_WIDTH=" + std::to_string(tipWidth) + "f" +
        " -DVF_SPACING_FRACTION_BITS=" + std::to_string(spacingFractionBits) +
        " -DVF_SWEEP_OVERFLOW=" + std::to_string(overflowCapacity) + "u" + contourCodeDefinitions();
    const std::string source = joinedKernelSources({"flow.h.cl"}) + flowSource + "\n" +
                               joinedKernelSources({"workgroup.cl", "contours.cl", "contours_spacing.cl",
                                                    "contours_refine.cl", "contours_area.cl"});
    const cl::Program program = device.build(source, "contours.cl", options);
    for (auto [kernel, name] : {std::pair{&advect, "advect"},
                                {&strain, "strain"},
                                {&positionsOf, "positionsOf"},
                                {&gatherVertices, "gatherVertices"},
                                {&arcTilesAndCount, "arcTilesAndCount"},
                                {&gridScatter, "gridScatter"},
                                {&sweepGridPass, "sweepGridPass"},
                                {&nearestOtherPart, "nearestOtherPart"},
                                {&nearestBeyond, "nearestBeyond"},
                                {&rawSpacing, "rawSpacing"},
                                {&smoothSpacing, "smoothSpacing"},
                                {&splitCount, "splitCount"},
                                {&splitScatter, "splitScatter"},
                                {&recountContours, "recountContours"},
                                {&collapseDecide, "collapseDecide"},
                                {&collapseScatter, "collapseScatter"},
                                {&recentreInPlace, "recentreInPlace"},
                                {&contourTermTiles, "contourTermTiles"},
                                {&contourTermSums, "contourTermSums"},
                                {&correctArea, "correctArea"}})
        *kernel = cl::Kernel(program, name);

    const std::vector<double> exact = gaussianWeights(smoothingRadius);  // eq. 6, as SpacingField
    std::vector<float> w(exact.begin(), exact.end());
    weights = cl::Buffer(device.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, w.size() * sizeof(float), w.data());
    status = buffer(statusWords * sizeof(cl_uint));
    sweepOverflow = buffer(std::max<std::size_t>(overflowCapacity, 1) * sizeof(cl_float2));
}

VertexSet DeviceContours::Impl::vertexSet(std::size_t size) const
{
    return {buffer(size * sizeof(cl_float4)), buffer(size * sizeof(float)), buffer(size * sizeof(cl_uint))};
}

std::size_t DeviceContours::Impl::deviceLimit() const
{
    // The largest buffer is a motion array (16 bytes per vertex, plus a tile of padding).
    const std::uint64_t byAllocation = device.maxAllocation() / sizeof(cl_float4) - 2 * localSize;
    const std::uint64_t byMemory = device.globalMemory() / DeviceContours::bytesPerVertex();
    const std::size_t limit = std::size_t(std::min(byAllocation, byMemory));
    return vertexCap ? std::min(limit, *vertexCap) : limit;
}

// Grows the vertex capacity geometrically to hold `needed`, keeping the front set's contents.
// False when the device cannot hold that many.
bool DeviceContours::Impl::reserve(std::size_t needed)
{
    if (needed <= capacity)
        return true;
    const std::size_t limit = deviceLimit();
    if (needed > limit)
        return false;
    // Past max_vertices growth is pointless (refinement stops there), unless a contour added
    // directly needs it.
    const std::size_t ceiling = std::max(needed, std::min(limit, std::max(settings.maxVertices, minCapacity)));
    const std::size_t grown = std::min(ceiling, std::max({needed, 2 * capacity, minCapacity}));
    // Counting kernels also write entry n; the proximity search reads up to 3 entries past the end.
    paddedCapacity = roundUpToLocal(grown + 4);
    VertexSet f = vertexSet(paddedCapacity);
    if (vertices > 0) {
        queue.enqueueCopyBuffer(front.motion, f.motion, 0, 0, vertices * sizeof(cl_float4));
        queue.enqueueCopyBuffer(front.spacing, f.spacing, 0, 0, vertices * sizeof(float));
        queue.enqueueCopyBuffer(front.contour, f.contour, 0, 0, vertices * sizeof(cl_uint));
    }
    front = f;
    back = vertexSet(paddedCapacity);
    tileOffset = buffer(paddedCapacity * sizeof(cl_uint));
    work = buffer(paddedCapacity * sizeof(cl_uint));
    actions = buffer(paddedCapacity * sizeof(cl_uint));
    sweepEntries = buffer(paddedCapacity * sizeof(cl_float2));
    tileTotals = buffer((paddedCapacity / localSize + 1) * 4 * accSize);
    tileActive = buffer((paddedCapacity / localSize + 1) * sizeof(cl_uint));
    tileMarks = buffer((paddedCapacity / localSize + 1) * sizeof(cl_uint));
    tileMarksMoved = buffer((paddedCapacity / localSize + 1) * sizeof(cl_uint));
    capacity = grown;
    return true;
}

void DeviceContours::Impl::reserveContours(std::size_t needed)
{
    if (needed <= contourCapacity)
        return;
    const std::size_t grown = std::max<std::size_t>({needed, 2 * contourCapacity, 64});
    cl::Buffer offset = buffer(grown * sizeof(cl_uint)), count = buffer(grown * sizeof(cl_uint));
    cl::Buffer target = buffer(grown * accSize);
    if (!regions.empty()) {
        queue.enqueueCopyBuffer(contourOffset, offset, 0, 0, regions.size() * sizeof(cl_uint));
        queue.enqueueCopyBuffer(contourCount, count, 0, 0, regions.size() * sizeof(cl_uint));
        queue.enqueueCopyBuffer(contourTarget, target, 0, 0, regions.size() * accSize);
    }
    contourOffset = offset;
    contourCount = count;
    contourTarget = target;
    contourLength = buffer(grown * sizeof(float));
    contourLambda = buffer(grown * accSize);
    contourCapacity = grown;
}

// A power of two of buckets, about one per `perBucket` vertices, whose starts fit the work array
// (which also holds the scan's total).
std::size_t DeviceContours::Impl::bucketsFor(std::size_t perBucket) const
{
    return std::min(std::bit_ceil(std::max(vertices, minCapacity)) / perBucket, std::bit_floor(paddedCapacity - 1));
}

// About one bucket per vertex (bucketsFor). Cells a quarter of the search radius: a bucket's own
// pairs (nearestOtherPart) grow with the square of what it holds, and dense ink, whose nearest
// other part is near, stays in its cell; the rest searches up to four rings (nearestBeyond).
Grid DeviceContours::Impl::grid() const
{
    const std::size_t buckets = bucketsFor(1);
    const auto bits = cl_uint(std::countr_zero(buckets));
    // Few vertices spread over the canvas in fine cells would alias many cells onto each bucket.
    const double cell = std::max(settings.proximityCell() / 2.0, std::sqrt(canvas.x * canvas.y / double(buckets)));
    return {cl_float(cell), (bits + 1) / 2, bits / 2};
}

// The sweep grid answers queries about triangles of two short edges, far smaller than its cells, so
// a bucket holds some sixteen positions on average (two cache lines of a contour's run through the
// cell): finer cells would cost more to build, several times a step, than they save in queries.
// Cells are square; their rows and columns wrap onto the buckets no more than the canvas needs.
Grid DeviceContours::Impl::sweepGrid() const
{
    const std::size_t buckets = bucketsFor(16);
    const auto bits = cl_uint(std::countr_zero(buckets));
    const double cell = std::sqrt(canvas.x * canvas.y / double(buckets));
    const auto bitsAcross = [&](double extent) {
        return cl_uint(std::bit_width(std::size_t(std::ceil(extent / cell)) - 1));
    };
    return {cl_float(cell), std::min((bits + 1) / 2, bitsAcross(canvas.x)), std::min(bits / 2, bitsAcross(canvas.y))};
}

bool DeviceContours::Impl::move(const FlowBinding& flow, const Motion& motion, bool startKnown,
                                const ExactMotion* exact)
{
    startKnown = startKnown && strainSamplesKept && motion.kind == motionFlow;
    // The samples are read one last time: the advection moves the vertices they belong to.
    const cl::Buffer& startVelocity = motionScratch();
    if (vertices == 0)
        return true;
    {
        const PhaseClock::Scope timing(clock, Phase::Advect);
        queue.enqueueFillBuffer(status, cl_uint(0), 0, statusWords * sizeof(cl_uint));
        launch(queue, advect, laneGroups(vertices), flow, motion, front.motion, cl_uint(vertices), startVelocity,
               cl_int(startKnown), status);
    }
    if (motion.kind == motionDrop) {  // as ContourTracker::drop
        splitCrossedChords(*exact);
        const PhaseClock::Scope timing(clock, Phase::Pinches);
        cutPinches();
    }
    computeSpacing(flow);
    const bool withinBudget = refine(flow, motion);
    if (exact)
        splitCrossedChords(*exact);
    if (settings.areaCorrection) {
        const PhaseClock::Scope timing(clock, Phase::Area);
        correctAreas();
    }
    return withinBudget;
}

// Eqs. 3–7 into front.spacing. Scratch, in order of use: back.spacing holds the tiles' arc sums,
// then the raw spacing; back.contour each grid entry's squared distance to another part;
// back.motion the grid entries; `work` the bucket counts, then starts; tileOffset the vertices'
// ranks within their buckets, then their slots in the grid.
void DeviceContours::Impl::computeSpacing(const FlowBinding& flow)
{
    const auto n = cl_uint(vertices);
    if (!settings.adaptive) {
        queue.enqueueFillBuffer(front.spacing, cl_float(settings.maxSpacing), 0, vertices * sizeof(float));
        return;
    }
    const Grid g = grid();
    const auto radius = cl_float(settings.proximityRadius());
    if (settings.proximity) {
        const PhaseClock::Scope timing(clock, Phase::Proximity);
        findNearestOtherParts(g);
    }
    const PhaseClock::Scope timing(clock, Phase::Spacing);
    launch(queue, rawSpacing, laneGroups(vertices), flow, front.motion, front.contour, contourOffset, contourCount, n,
           cl_float(settings.maxSpacing), cl_float(settings.curvatureLength()), cl_float(settings.vorticityScale),
           cl_float(settings.proximityLength()), radius, cl_int(settings.proximity), tileOffset, back.contour,
           back.spacing);
    launch(queue, smoothSpacing, laneGroups(vertices), back.spacing, front.contour, contourOffset, contourCount, n,
           weights, cl_int(smoothingRadius), cl_float(settings.minSpacing()), cl_float(settings.maxSpacing),
           front.spacing);
}

// Each vertex's nearest other part within the search radius (ProximityGrid::nearestOtherPart):
// the squared distance in back.contour, at the vertex's slot in tileOffset.
void DeviceContours::Impl::findNearestOtherParts(const Grid& g)
{
    const auto radius = cl_float(settings.proximityRadius());
    buildGrid(g);
    launch(queue, nearestOtherPart, laneGroups(g.buckets()), radius, work, motionScratch(), cl_uint(g.buckets()),
           contourLength, back.contour);
    launch(queue, nearestBeyond, laneGroups(g.buckets()), g, radius, work, motionScratch(), cl_uint(g.buckets()),
           contourLength, back.contour);
}

void DeviceContours::Impl::buildGrid(const Grid& g)
{
    const auto n = cl_uint(vertices);
    queue.enqueueFillBuffer(work, cl_uint(0), 0, (g.buckets() + 1) * sizeof(cl_uint));
    const std::size_t groups = laneGroups(vertices + 1), arcTiles = roundUpToLocal(groups) / localSize;
    launch(queue, arcTilesAndCount, groups, front.motion, front.contour, contourOffset, contourCount, n, g,
           back.spacing, tileTotals, cl_uint(arcTiles), work, tileOffset);
    sumScan.exclusive(tileTotals, arcTiles + 1);
    countScan.exclusive(work, g.buckets() + 1);
    launch(queue, gridScatter, laneGroups(vertices), front.motion, front.contour, contourOffset, contourCount, n,
           back.spacing, tileTotals, g, work, tileOffset, motionScratch(), contourLength);
    // Each entry's squared distance to another part starts at the search radius squared (nothing
    // found) for nearestOtherPart's atomic_min: one fill, where gridScatter would write it to
    // scattered slots.
    const auto radius = cl_float(settings.proximityRadius());
    queue.enqueueFillBuffer(back.contour, radius * radius, 0, vertices * sizeof(cl_float));
}

// Every vertex's position in its bucket of g, in sweepEntries; the buckets' starts in `work`.
void DeviceContours::Impl::buildSweepGrid(const Grid& g)
{
    const auto n = cl_uint(vertices);
    queue.enqueueFillBuffer(work, cl_uint(0), 0, (g.buckets() + 1) * sizeof(cl_uint));
    launch(queue, sweepGridPass, laneGroups(vertices), front.motion, n, g, cl_int(0), work, tileOffset,
           sweepEntries);
    countScan.exclusive(work, g.buckets() + 1);
    launch(queue, sweepGridPass, laneGroups(vertices), front.motion, n, g, cl_int(1), work, tileOffset,
           sweepEntries);
    queue.enqueueFillBuffer(status, cl_uint(0), statusOverflow * sizeof(cl_uint), sizeof(cl_uint));
    if (overflowCapacity > 0) {
        const cl_float2 forgotten{{-FLT_MAX, -FLT_MAX}};  // SWEEP_FORGOTTEN, in no triangle's box
        queue.enqueueFillBuffer(sweepOverflow, forgotten, 0, overflowCapacity * sizeof(cl_float2));
    }
}

// As ContourTracker::refine: split and collapse passes alternate until neither changes anything,
// at most maxRounds times, then a last split pass keeps the upper bound that topology needs. A
// split pass leaves no edge longer than its spacing (short of the depth cap), so a round whose
// collapse pass changes nothing is the last: the next split pass would find nothing, and the
// collapse pass after it would see what this one saw. That saves a counting pass per step.
//
// The round's first split pass looks at every tile (everything moved); every later pass only at
// the tiles the pass before it marked (contours_refine.cl): the others would find nothing to do,
// so the result is the same as looking at all of them.
//
// The collapse's sweep grid is built for the positions the step has moved and split, and then kept
// through every collapse pass after it until a split pass changes something (after the first
// round, split passes of a step seldom do).
bool DeviceContours::Impl::refine(const FlowBinding& flow, const Motion& motion)
{
    bool withinBudget = true, settled = false;
    std::optional<SweepGrid> sweep;
    lookAtEveryTile();
    for (int round = 0; round < maxRounds && withinBudget && !settled; ++round) {
        const Pass split = [&] {
            const PhaseClock::Scope timing(clock, Phase::Split);
            return splitPass(flow, motion);
        }();
        withinBudget = split.withinBudget;
        if (split.changed)
            sweep.reset();
        // After a split the short edges flagged before it are stale: every colour gets a look.
        const cl_uint colours = split.changed ? flagsShortEdge : split.flags & flagsShortEdge;
        bool collapsed = false;
        if (colours != 0) {
            const PhaseClock::Scope timing(clock, Phase::Collapse);
            collapsed = collapsePass(flow, motion, colours, sweep);
        }
        settled = !collapsed && !(split.flags & flagSplitCapped);
    }
    if (!settled && withinBudget) {
        const PhaseClock::Scope timing(clock, Phase::Split);
        withinBudget = splitPass(flow, motion).withinBudget;
    }
    return withinBudget;
}

void DeviceContours::Impl::lookAtEveryTile()
{
    queue.enqueueFillBuffer(tileActive, cl_uint(1), 0, (tiles() + 1) * sizeof(cl_uint));
}

void DeviceContours::Impl::clearMarks(cl::Buffer& marks)
{
    queue.enqueueFillBuffer(marks, cl_uint(0), 0, (paddedCapacity / localSize + 1) * sizeof(cl_uint));
}

void DeviceContours::Impl::clearPassFlags()
{
    static_assert(statusAcross == statusPass + 1);
    queue.enqueueFillBuffer(status, cl_uint(0), statusPass * sizeof(cl_uint), 2 * sizeof(cl_uint));
}

// One scalar and the status come back: the only synchronisation of a pass.
DeviceContours::Impl::Pass DeviceContours::Impl::readPass()
{
    cl_uint total = 0;
    std::array<cl_uint, statusWords> words{};
    queue.enqueueReadBuffer(tileTotals, CL_FALSE, tiles() * sizeof(cl_uint), sizeof(cl_uint), &total);
    queue.enqueueReadBuffer(status, CL_TRUE, 0, sizeof(words), words.data());
    if (words[statusSticky] & flagNonFinite)
        throw std::runtime_error("the flow moved a contour vertex to a non-finite position");
    if (words[statusSticky] & flagSplitMismatch)
        throw std::logic_error("DeviceContours: the split count and scatter kernels disagree");
    return {true, total != vertices, words[statusPass], words[statusAcross], total};
}

// After a scatter into `back` that marked the tiles to look at next in tileMarksMoved: contours
// get their new ranges, the sets swap.
void DeviceContours::Impl::adopt(std::size_t total)
{
    launch(queue, recountContours, regions.size(), contourOffset, contourCount, cl_uint(regions.size()), tileActive,
           tileOffset, tileTotals);
    std::swap(front, back);
    std::swap(tileActive, tileMarksMoved);
    vertices = total;
}

DeviceContours::Impl::Pass DeviceContours::Impl::countSplits(const FlowBinding& flow, const Motion& motion)
{
    clearPassFlags();
    clearMarks(tileMarks);
    launch(queue, splitCount, laneGroups(vertices + 1), flow, motion, front.motion, front.spacing, front.contour,
           contourOffset, contourCount, cl_uint(vertices), tileActive, tileMarks, tileOffset, tileTotals,
           cl_uint(tiles()), status);
    countScan.exclusive(tileTotals, tiles() + 1);
    return readPass();
}

// Leaves in tileActive the tiles the next pass looks at.
DeviceContours::Impl::Pass DeviceContours::Impl::splitPass(const FlowBinding& flow, const Motion& motion)
{
    Pass pass = countSplits(flow, motion);
    if (!pass.changed) {
        std::swap(tileActive, tileMarks);
        return pass;
    }
    if (pass.total > capacity && pass.total <= settings.maxVertices && reserve(pass.total)) {
        lookAtEveryTile();  // the counts lived in the scratch that reserve() replaced
        pass = countSplits(flow, motion);
    }
    if (pass.total > capacity || pass.total > settings.maxVertices) {
        std::swap(tileActive, tileMarks);
        return {false, false, pass.flags, 0, vertices};
    }
    clearMarks(tileMarksMoved);
    launch(queue, splitScatter, laneGroups(vertices), flow, motion, front.motion, front.spacing, front.contour,
           contourOffset, contourCount, cl_uint(vertices), tileActive, tileOffset, tileTotals, motionScratch(),
           back.spacing, back.contour, tileMarksMoved, status);
    adopt(pass.total);
    return pass;
}

// The colour classes in `colours` (bit c for colour c) in turn, each a compaction of its deletions
// (or, with none, recentring in place). Each decision pass also says which later colours still
// touch short edges, and checks its removals against the sweep grid (sweepGrid()) of the positions
// it starts from (sweepsInk in contours_refine.cl). Deletions and recentrings move their entries
// in the grid (moveSweepEntry), so `sweep`, where it holds one, is built again only when its
// overflow list would fill. Leaves in tileActive the tiles the next pass looks at.
bool DeviceContours::Impl::collapsePass(const FlowBinding& flow, const Motion& motion, cl_uint colours,
                                        std::optional<SweepGrid>& sweep)
{
    bool changed = false;
    for (cl_uint colour = 0; colour < 3; ++colour) {
        if (!(colours & (flagShortEdge0 << colour)))
            continue;
        if (!sweep) {
            sweep = SweepGrid{sweepGrid()};
            buildSweepGrid(sweep->grid);
        }
        const Grid g = sweep->grid;
        const cl_uint overflowing = sweep->overflowing;
        clearPassFlags();
        clearMarks(tileMarks);
        launch(queue, collapseDecide, laneGroups(vertices + 1), flow, motion, g, work, sweepEntries, sweepOverflow,
               overflowing, front.motion, front.spacing, front.contour, contourOffset, contourCount,
               cl_uint(vertices), colour, tileActive, tileMarks, actions, tileOffset, tileTotals, cl_uint(tiles()),
               status);
        countScan.exclusive(tileTotals, tiles() + 1);
        const Pass pass = readPass();
        if (pass.changed) {
            clearMarks(tileMarksMoved);
            launch(queue, collapseScatter, laneGroups(vertices), flow, motion, front.motion, front.spacing,
                   front.contour, contourOffset, contourCount, cl_uint(vertices), tileActive, actions, tileOffset,
                   tileTotals, motionScratch(), back.spacing, back.contour, tileMarksMoved, g, work, sweepEntries,
                   sweepOverflow, overflowing, status);
            adopt(pass.total);
        } else {
            if (pass.flags & flagRecentred)
                launch(queue, recentreInPlace, laneGroups(vertices), flow, motion, front.motion, front.spacing,
                       front.contour, contourOffset, contourCount, cl_uint(vertices), tileActive, actions, g, work,
                       sweepEntries, sweepOverflow, overflowing, status);
            std::swap(tileActive, tileMarks);
        }
        if (pass.across > overflowCapacity - overflowing)
            sweep.reset();
        else
            sweep->overflowing += pass.across;
        changed = changed || pass.changed || (pass.flags & flagRecentred) != 0;
        colours = pass.flags & flagsShortEdge;
    }
    return changed;
}

// With `hold`, the vertices findNearestOtherParts found other ink near stay still (contours_area.cl).
void DeviceContours::Impl::contourTerms(cl_int mode, Vec2 point, double dropArea, bool hold)
{
    const cl_float2 p{{cl_float(point.x), cl_float(point.y)}};
    const auto shortEdge = cl_float(settings.minSpacing());
    const cl_float within2 = holdWithin2();
    launch(queue, contourTermTiles, vertices, mode, p, shortEdge, cl_int(hold), within2, tileOffset, back.contour,
           front.motion, front.contour, contourOffset, contourCount, cl_uint(vertices), tileTotals);
    launch(queue, contourTermSums, regions.size(), mode, p, shortEdge, cl_int(hold), within2, tileOffset, back.contour,
           cl_float(settings.areaCorrectionStep()), Accumulated{dropArea, fp64}, front.motion, contourOffset,
           contourCount, cl_uint(regions.size()), tileTotals, contourTarget, contourLambda);
}

// As ContourTracker::correctAreas: a vertex with another part within the hold distance stays, as do
// those at or beside a sharp turn (sim/AreaCorrection.h).
void DeviceContours::Impl::correctAreas()
{
    findNearestOtherParts(grid());
    contourTerms(termsArea, Vec2(0.0), 0.0, true);
    launch(queue, correctArea, vertices, cl_float(settings.minSpacing()), cl_int(1), holdWithin2(), tileOffset,
           back.contour, front.motion, front.contour, contourOffset, contourCount, cl_uint(vertices), contourLambda,
           motionScratch());
    std::swap(front.motion, back.motion);
}

void DeviceContours::Impl::enqueueSnapshot(Snapshot& s)
{
    const std::size_t contours = regions.size();
    s.motion.resize(vertices);
    s.spacing.resize(vertices);
    s.offset.resize(contours);
    s.count.resize(contours);
    s.regions = regions;
    s.targets = targets;
    if (contours == 0)
        return;
    if (vertices > 0) {
        queue.enqueueReadBuffer(front.motion, CL_FALSE, 0, vertices * sizeof(cl_float4), s.motion.data());
        queue.enqueueReadBuffer(front.spacing, CL_FALSE, 0, vertices * sizeof(float), s.spacing.data());
    }
    queue.enqueueReadBuffer(contourOffset, CL_FALSE, 0, contours * sizeof(cl_uint), s.offset.data());
    queue.enqueueReadBuffer(contourCount, CL_FALSE, 0, contours * sizeof(cl_uint), s.count.data(), nullptr, &s.done);
}

// The positions go through the scratch vertex set, packed to 8 bytes a vertex; the in-order queue
// runs the copy before any later command writes there.
void DeviceContours::Impl::enqueueOutlines(Outlines& s)
{
    const std::size_t contours = regions.size();
    s.positions.resize(vertices);
    s.offset.resize(contours);
    s.count.resize(contours);
    s.regions = regions;
    if (contours == 0)
        return;
    if (vertices > 0) {
        cl::Buffer& positions = motionScratch();
        launch(queue, positionsOf, vertices, front.motion, cl_uint(vertices), positions);
        queue.enqueueReadBuffer(positions, CL_FALSE, 0, vertices * sizeof(cl_float2), s.positions.data());
    }
    queue.enqueueReadBuffer(contourOffset, CL_FALSE, 0, contours * sizeof(cl_uint), s.offset.data());
    queue.enqueueReadBuffer(contourCount, CL_FALSE, 0, contours * sizeof(cl_uint), s.count.data(), nullptr, &s.done);
}

std::vector<Contour> DeviceContours::Impl::toContours(const Snapshot& s) const
{
    std::vector<Contour> contours(s.regions.size());
    for (std::size_t c = 0; c < contours.size(); ++c) {
        Contour& out = contours[c];
        out.region = s.regions[c];
        out.targetArea = s.targets[c];
        out.positions.reserve(s.count[c]);
        out.previous.reserve(s.count[c]);
        out.spacing.reserve(s.count[c]);
        for (std::size_t i = s.offset[c]; i < s.offset[c] + s.count[c]; ++i) {
            const cl_float4& m = s.motion[i];
            out.positions.emplace_back(m.s[0], m.s[1]);
            out.previous.emplace_back(m.s[2], m.s[3]);
            out.spacing.push_back(s.spacing[i]);
        }
    }
    return contours;
}

// Uploads `contours` as the store's contours from index `firstContour` on, their vertices from
// `firstVertex` on, in order, replacing whatever came after; all or nothing: when the device
// cannot hold them, nothing changes.
void DeviceContours::Impl::place(const std::vector<Contour>& contours, std::size_t firstVertex,
                                 std::size_t firstContour)
{
    std::size_t total = firstVertex;
    for (const Contour& c : contours)
        total += c.positions.size();
    if (!reserve(std::max<std::size_t>(1, total)))  // allocates the scratch too
        throw DeviceError("the OpenCL device cannot hold " + std::to_string(total) + " contour vertices");
    reserveContours(firstContour + contours.size());
    strainSamplesKept = false;
    std::vector<cl_float4> motion;
    std::vector<float> spacing;
    std::vector<cl_uint> contour, offset, count;
    std::vector<double> areas;  // the contours' area targets
    motion.reserve(total - firstVertex);
    spacing.reserve(total - firstVertex);
    contour.reserve(total - firstVertex);
    for (const Contour& c : contours) {
        offset.push_back(cl_uint(firstVertex + motion.size()));
        count.push_back(cl_uint(c.positions.size()));
        for (std::size_t i = 0; i < c.positions.size(); ++i) {
            const Vec2 p = c.positions[i], q = c.previous[i];
            motion.push_back({{cl_float(p.x), cl_float(p.y), cl_float(q.x), cl_float(q.y)}});
            spacing.push_back(float(c.spacing[i]));
            contour.push_back(cl_uint(firstContour + offset.size() - 1));
        }
        areas.push_back(c.targetArea);
    }
    put(queue, front.motion, firstVertex, motion);
    put(queue, front.spacing, firstVertex, spacing);
    put(queue, front.contour, firstVertex, contour);
    putContours(firstContour, offset, count, areas);
    queue.finish();  // the host vectors above go out of scope
    regions.resize(firstContour);
    for (const Contour& c : contours)
        regions.push_back(c.region);
    vertices = total;
}

// The contours' ranges and area targets from index `firstContour` on (the host's copy of the
// targets too); the copies are enqueued, and the caller waits before the vectors go.
void DeviceContours::Impl::putContours(std::size_t firstContour, const std::vector<cl_uint>& offset,
                                       const std::vector<cl_uint>& count, const std::vector<double>& areas)
{
    put(queue, contourOffset, firstContour, offset);
    put(queue, contourCount, firstContour, count);
    targets.resize(firstContour);
    targets.insert(targets.end(), areas.begin(), areas.end());
    if (fp64) {
        put(queue, contourTarget, firstContour, areas);
    } else {
        const std::vector<float> areaFloats(areas.begin(), areas.end());
        put(queue, contourTarget, firstContour, areaFloats);
        queue.finish();
    }
}

// Contour surgery on the device (DeviceContours::cutPinches): every vertex kept is gathered, in its
// new place, into the scratch vertex set, which becomes the front; the contours' ranges, regions and
// targets are replaced.
std::size_t DeviceContours::Impl::applyCuts(const std::vector<ContourCut>& cuts)
{
    const std::size_t contours = regions.size();
    std::vector<cl_uint> offset(contours), count(contours);
    queue.enqueueReadBuffer(contourOffset, CL_FALSE, 0, contours * sizeof(cl_uint), offset.data());
    queue.enqueueReadBuffer(contourCount, CL_TRUE, 0, contours * sizeof(cl_uint), count.data());
    std::vector<cl_uint> from, newContour, newOffset, newCount;  // per new vertex, per new contour
    std::vector<int> newRegions;
    std::vector<double> newTargets;
    from.reserve(vertices);
    newContour.reserve(vertices);
    std::size_t made = 0;
    const auto addContour = [&](int region, double target, const auto& vertexOf, std::size_t size) {
        newOffset.push_back(cl_uint(from.size()));
        newCount.push_back(cl_uint(size));
        for (std::size_t i = 0; i < size; ++i) {
            from.push_back(cl_uint(vertexOf(i)));
            newContour.push_back(cl_uint(newRegions.size()));
        }
        newRegions.push_back(region);
        newTargets.push_back(target);
    };
    auto cut = cuts.begin();
    for (std::size_t k = 0; k < contours; ++k) {
        if (cut == cuts.end() || cut->contour != k) {
            addContour(regions[k], targets[k], [&](std::size_t i) { return offset[k] + i; }, count[k]);
            continue;
        }
        const std::vector<double> shares = sharedTargets(targets[k], cut->kept);
        for (std::size_t l = 0; l < cut->kept.size(); ++l) {
            const std::vector<std::uint32_t>& loop = cut->kept[l].vertices;
            addContour(regions[k], shares[l], [&](std::size_t i) { return offset[k] + loop[i]; }, loop.size());
        }
        made += cut->cuts;
        ++cut;
    }
    reserveContours(newRegions.size());
    const auto n = cl_uint(from.size());
    put(queue, back.contour, 0, from);
    put(queue, tileOffset, 0, newContour);
    launch(queue, gatherVertices, n, front.motion, front.spacing, n, tileOffset, back.motion, back.spacing,
           back.contour);
    std::swap(front, back);
    putContours(0, newOffset, newCount, newTargets);
    queue.finish();  // the host vectors above go out of scope
    regions = std::move(newRegions);
    vertices = n;
    strainSamplesKept = false;
    return made;
}

DeviceContours::Impl::~Impl()
{
    try {
        queue.finish();
    } catch (const cl::Error&) {  // a failed device has nothing running any more
    }
}

DeviceContours::DeviceContours(Device& device, const TrackingSettings& settings, Vec2 canvas,
                               const std::string& flowSource, std::size_t sweepOverflow)
    : m(guarded([&] { return std::make_unique<Impl>(device, settings, canvas, flowSource, sweepOverflow); }))
{
}

DeviceContours::~DeviceContours() = default;

void DeviceContours::addRegion(int region, const std::vector<Polygon>& polygons)
{
    guarded([&] {
        std::vector<Contour> contours;
        for (const Polygon& polygon : polygons) {
            Contour& c = contours.emplace_back();
            c.region = region;
            c.positions = c.previous = resample(polygon, m->settings.maxSpacing);
            c.spacing.assign(c.positions.size(), m->settings.maxSpacing);
            c.targetArea = signedArea(c.positions);
        }
        m->place(contours, m->vertices, m->regions.size());
    });
}

void DeviceContours::growTargetAreasAround(Vec2 p, double area)
{
    guarded([&] {
        if (m->regions.empty())
            return;
        m->contourTerms(termsWinding, p, area, false);
        const std::size_t contours = m->regions.size();
        if (m->fp64) {
            m->queue.enqueueReadBuffer(m->contourTarget, CL_TRUE, 0, contours * sizeof(double), m->targets.data());
        } else {
            std::vector<float> t(contours);
            m->queue.enqueueReadBuffer(m->contourTarget, CL_TRUE, 0, contours * sizeof(float), t.data());
            std::copy(t.begin(), t.end(), m->targets.begin());
        }
    });
}

double DeviceContours::strainInSpacings(const FlowBinding& flow, double dt)
{
    return guarded([&] {
        if (m->vertices == 0)
            return 0.0;
        cl::CommandQueue& q = m->queue;
        q.enqueueFillBuffer(m->status, cl_uint(0), statusStrain * sizeof(cl_uint), sizeof(cl_uint));
        launch(q, m->strain, laneGroups(m->vertices), flow, cl_float(dt), m->front.motion, m->front.spacing,
               m->front.contour, m->contourOffset, m->contourCount, cl_uint(m->vertices), m->motionScratch(), m->status);
        m->strainSamplesKept = true;
        float worst = 0.0f;
        q.enqueueReadBuffer(m->status, CL_TRUE, statusStrain * sizeof(cl_uint), sizeof(float), &worst);
        return double(worst);
    });
}

bool DeviceContours::advect(const FlowBinding& flow, bool startSampled)
{
    return guarded([&] { return m->move(flow, m->flowMotion(), startSampled); });
}

bool DeviceContours::drop(Vec2 center, double radius, const FlowBinding& flow)
{
    return guarded([&] {
        const ExactMotion onHost = exactMotion(DropPush{center, radius}, m->settings.chordTolerance);
        return m->move(flow, m->mapMotion(motionDrop, {{center.x, center.y, radius, 0.0}}, {}), false, &onHost);
    });
}

bool DeviceContours::applyMap(const ExactMap& map, const FlowBinding& flow)
{
    return guarded([&] {
        const std::optional<MapParameters> p = mapParameters(map);
        if (!p || m->vertices == 0)
            return true;
        const ExactMotion onHost = exactMotion(map, m->settings.chordTolerance);
        return m->move(flow, m->mapMotion(p->kind, p->a, p->b, p->c), false, &onHost);
    });
}

void DeviceContours::write(const std::vector<Contour>& contours)
{
    guarded([&] {
        m->place(contours, 0, 0);
        for (Outlines& staged : m->staging)
            staged.taken = true;
    });
}

// The positions, read back for a search on the host (8 bytes a vertex), and each contour's among them.
struct DeviceContours::Impl::HostOutlines {
    std::vector<Vec2> positions;
    std::vector<Outline> outlines;
};

// The widening's moves, made where the positions lie (and on the host's copy, which the area
// changes are measured on), and the contours' targets following their areas (sim::moveVertices).
// A vertex's previous position goes with it: the next motion starts from there.
void DeviceContours::Impl::moveVertices(HostOutlines& host, const std::vector<VertexMove>& moves)
{
    std::vector<cl_float4> moved;
    moved.reserve(moves.size());
    for (const VertexMove& move : moves) {
        const Outline& c = host.outlines[move.contour];
        const std::size_t first = std::size_t(c.data() - host.positions.data());
        targets[move.contour] += moveVertex({host.positions.data() + first, c.size()}, move.vertex, move.to);
        const auto x = cl_float(move.to.x), y = cl_float(move.to.y);
        moved.push_back({{x, y, x, y}});
        queue.enqueueWriteBuffer(front.motion, CL_FALSE, (first + move.vertex) * sizeof(cl_float4), sizeof(cl_float4),
                                 &moved.back());
    }
    if (fp64) {
        put(queue, contourTarget, 0, targets);
    } else {
        const std::vector<float> targetFloats(targets.begin(), targets.end());
        put(queue, contourTarget, 0, targetFloats);
    }
    queue.finish();  // before `moved` and the float targets go
}

DeviceContours::Impl::HostOutlines DeviceContours::Impl::readOutlines()
{
    HostOutlines host;
    Outlines s;
    enqueueOutlines(s);
    if (s.done())
        s.done.wait();
    host.positions.resize(s.positions.size());
    std::transform(s.positions.begin(), s.positions.end(), host.positions.begin(),
                   [](const cl_float2& p) { return Vec2(p.s[0], p.s[1]); });
    for (std::size_t c = 0; c < s.offset.size(); ++c)
        host.outlines.emplace_back(host.positions.data() + s.offset[c], s.count[c]);
    return host;
}

// sim/CrossedChords.h, on the host: the positions are read back (8 bytes a vertex), which shows
// that most motions crossed nothing; else the whole store is read, for the pre-images, and written
// again where a chord was split.
void DeviceContours::Impl::splitCrossedChords(const ExactMotion& motion)
{
    const PhaseClock::Scope timing(clock, Phase::Split);
    if (findOutlineCrossings(readOutlines().outlines, 1).empty())
        return;
    Snapshot s;
    enqueueSnapshot(s);
    if (s.done())
        s.done.wait();
    std::vector<Contour> contours = toContours(s);
    if (sim::splitCrossedChords(contours, motion, true) > 0)
        place(contours, 0, 0);
}

// The search is on the host; the cuts are made on the device.
std::size_t DeviceContours::Impl::cutPinches()
{
    const std::vector<ContourCut> cuts = findCuts(readOutlines().outlines, pinchGrid);
    return cuts.empty() ? 0 : applyCuts(cuts);
}

std::size_t DeviceContours::cutPinches()
{
    return guarded([&] { return m->cutPinches(); });
}

std::size_t DeviceContours::separateLayers(std::optional<Window> within)
{
    return guarded([&] {
        Impl::HostOutlines host = m->readOutlines();
        const std::vector<VertexMove> moves = findSeparations(host.outlines, true, within);
        if (!moves.empty())
            m->moveVertices(host, moves);
        return moves.size();
    });
}

std::size_t DeviceContours::deviceVertexLimit() const
{
    return m->deviceLimit();
}

std::size_t DeviceContours::vertexCount() const
{
    return m->vertices;
}

std::vector<Contour> DeviceContours::read() const
{
    return guarded([&] {
        Snapshot s;
        m->enqueueSnapshot(s);
        if (s.done())
            s.done.wait();
        return m->toContours(s);
    });
}

std::uint64_t DeviceContours::requestRead(int regionCount)
{
    return guarded([&] {
        Outlines& s = m->staging[m->requests % 2];
        if (s.done())
            s.done.wait();  // still being filled from two requests ago
        s.taken = true;     // until the new copy is enqueued whole
        s.done = cl::Event();
        m->enqueueOutlines(s);
        s.regionCount = regionCount;
        s.serial = ++m->requests;
        s.taken = false;
        m->queue.flush();
        return s.serial;
    });
}

std::optional<RegionsCopy> DeviceContours::takeRead(bool wait)
{
    return guarded([&]() -> std::optional<RegionsCopy> {
        Outlines* newest = &m->staging[0];
        Outlines* older = &m->staging[1];
        if (older->serial > newest->serial)
            std::swap(newest, older);
        if (wait && !newest->taken && newest->done())
            newest->done.wait();
        for (Outlines* s : {newest, older}) {
            if (s->taken || (s->done() && !isComplete(s->done)))
                continue;
            newest->taken = older->taken = true;  // an older copy is superseded by a newer one
            RegionsCopy copy{s->serial, std::vector<std::vector<Polygon>>(std::size_t(s->regionCount))};
            for (std::size_t c = 0; c < s->regions.size(); ++c) {
                Polygon& out = copy.regions.at(std::size_t(s->regions[c])).emplace_back();
                out.reserve(s->count[c]);
                for (std::size_t i = s->offset[c]; i < s->offset[c] + s->count[c]; ++i)
                    out.emplace_back(s->positions[i].s[0], s->positions[i].s[1]);
            }
            return copy;
        }
        return std::nullopt;
    });
}

void DeviceContours::setPhaseClock(PhaseClock* clock)
{
    m->clock = clock;
}

std::size_t DeviceContours::bytesPerVertex()
{
    // Two vertex sets of float4 motion + float spacing + uint contour (24 bytes each), the tile
    // offsets, the work array and the collapse actions (4 bytes each), the sweep grid's float2
    // entries: 68. Per tile of 64 vertices one acc4 of 32 bytes and a uint flag (0.56 per vertex),
    // and the scans' block totals (under 0.05): rounded up, 69.
    constexpr std::size_t perSet = sizeof(cl_float4) + sizeof(float) + sizeof(cl_uint);
    return 2 * perSet + 3 * sizeof(cl_uint) + sizeof(cl_float2) + 1;
}

} // namespace vf::sim::opencl
