// The stable-fluids step of sim/FluidSolver.cpp on an OpenCL device, in float32, the velocity
// staying on the device between steps (the OpenCL backend's fluid on a GPU; on a CPU device it runs
// HostFluid instead, see Fluid.h, and the tests run this one there): the same MAC grid, free-slip
// closed walls, RK2-traced semi-Lagrangian or MacCormack advection, implicit viscosity, stylus and body force after viscosity, pressure
// projection. The kernels are in fluid.cl, the MAC sampling they share with the contour kernels in
// flow_fluid.cl. One file because the step's launches, the solver's buffers and its level table
// are one set of state that every launch sequence below reads.
//
// Linear solves: the preconditioned CG of sim/LinearSolve.cpp, stopping on the same max-norm
// residual. Its preconditioner is the same multigrid V-cycle (coarsening, red-black Gauss-Seidel,
// cycle), whose iteration count stays flat with the grid: the projection takes 2 to 5 iterations
// per step from 64^2 to 512^2 cells, warm-started from the last pressure. Where the matrix is so
// diagonally dominant that CG gains a factor of 6 per iteration anyway, the preconditioner is
// Jacobi, one launch instead of a V-cycle: the implicit viscosity at ordinary viscosities (nu dt /
// h^2 = 0.004 at 64^2 with the default nu and dt), 2 to 4 iterations. Each CG iteration is a list
// of launches bound once and queued without waiting. The scalars (alpha, beta, the convergence
// flag) stay on the device in a CgState, computed by single-work-group kernels from per-work-group
// partials in a fixed order (no atomics), so results are bit-identical run to run. Once the flag is
// set, every later kernel of the solve returns at once, so iterations queued past convergence
// change nothing. The host reads the state (32 bytes) after as many iterations as the last solve
// of that system took, then every kCheckEvery iterations: one read per solve in the steady state.
//
// PoCL, the CPU device this was tuned on, shaped the kernels: a launch costs a few microseconds, so
// the levels of at most kTailCells unknowns run in one work-group and one launch (mgTail); every
// barrier costs a pass over the work-group, so reductions use one; and its work-item loop
// vectoriser gives up on loops that hold float2/float4 values or divide per work-item, so the
// kernels are scalar and index 2D ranges (fluid.cl). The advection kernels still run scalar there:
// the OpenCL front end pairs their x and y arithmetic into 2-wide vectors before PoCL sees them.
//
// Pressure tolerance: as in FluidSolver.cpp the projection stops on the max norm of the CG
// residual, which equals -div u of the projected velocity up to roundoff; the target is
// max(FluidSettings::pressureTolerance, kPressureRoundoffFloor * S), with S the largest over cells
// of (|u_e| + |u_w|) / hx + (|v_s| + |v_n|) / hy, the sum of the magnitudes of the terms of the
// discrete divergence. float32 rounds div u at about 1e-7 S, so the absolute targets the double
// solver reaches (1e-8 / s by default) are out of reach. The stored pressure's own rounding adds
// to that, growing with the grid: measured max |div u| / S after stroke steps, 1.0e-6 at 64^2,
// 2.2e-6 at 256^2, 4.5e-6 at 512^2; tests/sim/tst_device_fluid.cpp holds it under 1e-5 S.
#include "sim/opencl/DeviceFluid.h"

#include "sim/opencl/KernelSources.h"
#include "sim/opencl/Launch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vf::sim::opencl {
namespace {

// The single-work-group kernels (VF_GROUP) run wider than the others (localSize, VF_LOCAL): on a
// GPU a whole V-cycle tail of 4096 cells then takes 16 cells per work-item and phase, not 64.
constexpr int kGroup = 256;
// As in sim/LinearSolve.cpp.
constexpr int kSmoothingSweeps = 2;
constexpr int kCoarsestSweeps = 20;
constexpr int kCoarsestSize = 16;
constexpr int kTailCells = 4096;
constexpr int kCheckEvery = 2;
// Viscosity solves stop at this max-norm residual relative to max |u*|: 1e-8 in the double solver,
// here a few float32 roundoffs; the projection that follows fixes the divergence anyway.
constexpr float kViscosityRelativeTolerance = 1e-6f;
// See the top of this file.
constexpr float kPressureRoundoffFloor = 1e-6f;

// The per-work-group partials of fluid.cl (PARTIAL_*), slot * groups + group.
enum Partial { kSumR = 1, kSumX = 3, kPartialSlots = 6 };

// Mirrors CgState in fluid.cl.
struct CgState {
    float tolerance, mean, rho, alpha, beta;
    cl_int done, iterations, unused;
};
static_assert(sizeof(CgState) == 32);

struct Launch {
    cl::Kernel kernel;
    cl::NDRange global, local;
};
using Launches = std::vector<Launch>;

template <class... Args>
cl::Kernel kernel(const cl::Program& program, const char* name, const Args&... args)
{
    cl::Kernel k(program, name);
    cl_uint index = 0;
    (k.setArg(index++, args), ...);
    return k;
}

// One work-item per element of a storage whose length is a multiple of localSize.
Launch overStorage(cl::Kernel k, std::size_t length)
{
    return {std::move(k), cl::NDRange(length), cl::NDRange(localSize)};
}

// One work-item per element of a cols x rows lattice: rows of work-groups along its rows.
Launch overLattice(cl::Kernel k, int cols, int rows)
{
    return {std::move(k), cl::NDRange(roundUpToLocal(cols), rows), cl::NDRange(localSize, 1)};
}

int groupsOver(int cols, int rows) { return int(roundUpToLocal(cols) / localSize) * rows; }

Launch singleGroup(cl::Kernel k)
{
    return {std::move(k), cl::NDRange(kGroup), cl::NDRange(kGroup)};
}

void enqueue(cl::CommandQueue& queue, const Launch& launch)
{
    queue.enqueueNDRangeKernel(launch.kernel, cl::NullRange, launch.global, launch.local);
}

void enqueue(cl::CommandQueue& queue, const Launches& launches)
{
    for (const Launch& launch : launches)
        enqueue(queue, launch);
}

void append(Launches& to, const Launches& from)
{
    to.insert(to.end(), from.begin(), from.end());
}

int iterationCap(int cols, int rows) { return 4 * (cols + rows) + 100; }  // as FluidSolver.cpp

std::string megabytes(std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// Zero-filled device buffers, refused with a DeviceError before the device would run out.
class Memory {
public:
    Memory(Device& device, std::string what)
        : m_device(device)
        , m_what(std::move(what))
    {
    }

    cl::Buffer zeros(std::size_t bytes)
    {
        m_total += bytes;
        if (bytes > m_device.maxAllocation() || m_total > m_device.globalMemory())
            throw DeviceError(m_what + " needs more than the " + megabytes(m_device.globalMemory())
                              + " of memory of the OpenCL device " + m_device.name());
        cl::Buffer buffer(m_device.context(), CL_MEM_READ_WRITE, bytes);
        m_device.queue().enqueueFillBuffer(buffer, cl_float(0), 0, bytes);
        return buffer;
    }

    template <class T>
    cl::Buffer upload(const std::vector<T>& values)
    {
        cl::Buffer buffer = zeros(values.size() * sizeof(T));
        m_device.queue().enqueueWriteBuffer(buffer, CL_TRUE, 0, values.size() * sizeof(T),
                                            values.data());
        return buffer;
    }

private:
    Device& m_device;
    std::string m_what;
    std::uint64_t m_total = 0;
};

DeviceError translate(const cl::Error& e, const Device& device)
{
    const std::string call = std::string(e.what()) + " (error " + std::to_string(e.err()) + ")";
    switch (e.err()) {
    case CL_MEM_OBJECT_ALLOCATION_FAILURE:
    case CL_OUT_OF_RESOURCES:
    case CL_OUT_OF_HOST_MEMORY:
    case CL_INVALID_BUFFER_SIZE:
        return DeviceError("the OpenCL device " + device.name()
                           + " ran out of memory for the fluid: " + call);
    default:
        return DeviceError("the OpenCL fluid solver failed on " + device.name() + ": " + call);
    }
}

template <class F>
decltype(auto) translatingErrors(const Device& device, F&& f)
{
    try {
        return f();
    } catch (const cl::Error& e) {
        throw translate(e, device);
    }
}

// ---- Linear solves ------------------------------------------------------------------------------

struct LevelShape {
    int mx, my, offset;
    int groupX = 1, groupY = 1;  // how cells group into the next level

    // With the ghost ring, rounded up to whole work-groups for the element-wise kernels.
    int stored() const { return int(roundUpToLocal(std::size_t(mx + 2) * (my + 2))); }
};

// The hierarchy of PcgSolver::setStencil and ::coarsen: 2 x 2 groups, or along one axis only while
// its couplings are more than twice the other's (semi-coarsening), down to kCoarsestSize unknowns.
// It depends only on the lattice and the ratio of ax to ay, so a viscosity solve keeps its levels
// when dt changes; only the coefficients are refilled.
std::vector<LevelShape> planLevels(const Stencil5& s)
{
    std::vector<LevelShape> levels{{s.mx, s.my, 0}};
    double strengthX = s.ax, strengthY = s.ay;
    while (levels.back().mx * levels.back().my > kCoarsestSize) {
        LevelShape& fine = levels.back();
        const bool alongX = fine.mx > 1 && (2.0 * strengthX >= strengthY || fine.my == 1);
        const bool alongY = fine.my > 1 && (2.0 * strengthY >= strengthX || fine.mx == 1);
        fine.groupX = alongX ? 2 : 1;
        fine.groupY = alongY ? 2 : 1;
        strengthX *= (alongX ? 0.5 : 1.0) * fine.groupY;
        strengthY *= (alongY ? 0.5 : 1.0) * fine.groupX;
        const LevelShape coarse{(fine.mx + fine.groupX - 1) / fine.groupX,
                                (fine.my + fine.groupY - 1) / fine.groupY,
                                fine.offset + fine.stored()};
        levels.push_back(coarse);
    }
    return levels;
}

// Preconditioned CG for one system (Stencil5) on the device. The right-hand side is written into
// b() by the caller's kernel, which also reduces the scale of the tolerance into partials()
// (PARTIAL_SCALE); the solution replaces the first guess in x().
class DevicePcg {
public:
    // `shape` fixes the lattice, the boundary conditions and the coarsening; setStencil() the
    // coefficients. The solve stops at max |r| <= max(absolute, relative * scale).
    DevicePcg(Device& device, Memory& memory, const cl::Program& program, const Stencil5& shape,
              float absolute, float relative);

    void setStencil(const Stencil5& stencil);
    void solve(int maxIterations);
    void clearSolution();
    // The solution as mx * my unknowns in row-major order, without the ghost ring (which stays
    // zero): the first guess of the next solve, for snapshots.
    std::vector<double> readSolution() const;
    void writeSolution(const std::vector<double>& unknowns);

    const cl::Buffer& x() const { return m_x; }
    const cl::Buffer& b() const { return m_b; }
    const cl::Buffer& partials() const { return m_partials; }

private:
    // Multigrid, or Jacobi (z = r / diagonal) where the matrix is so diagonally dominant that CG
    // converges in a few iterations anyway: the implicit viscosity at ordinary viscosities and time
    // steps, where the matrix is within a few percent of the identity and a V-cycle costs more
    // than it saves.
    enum Preconditioner { kMultigrid, kJacobi };

    Launch overCells(cl::Kernel k) const
    {
        return overLattice(std::move(k), m_levels[0].mx, m_levels[0].my);
    }
    Launch overVectors(cl::Kernel k) const
    {
        return overStorage(std::move(k), m_levels[0].stored());
    }
    Launches rebuildLaunches(const cl::Program& program) const;
    Launches vcycleLaunches(const cl::Program& program) const;
    Launches startLaunches(const cl::Program& program, const Launches& preconditioner,
                           float absolute, float relative) const;
    Launches iterationLaunches(const cl::Program& program, int parity,
                               const Launches& preconditioner) const;
    Launches directionLaunches(const cl::Program& program) const;

    cl::CommandQueue& m_queue;
    Stencil5 m_stencil;
    bool m_hasStencil = false;
    Preconditioner m_preconditioner = kMultigrid;
    std::vector<LevelShape> m_levels;
    // The partials per slot of the kernels over the finest level's cells, and of the element-wise
    // kernels over its storage.
    int m_cellGroups, m_vectorGroups;
    int m_plane;  // stored cells of all levels: the distance between the coefficient planes
    int m_lastIterations = 0;
    // Every level's coefficients (four planes), V-cycle unknowns (z on the finest) and right-hand
    // sides (r on the finest), at the levels' offsets.
    cl::Buffer m_coef, m_levelX, m_levelB;
    cl::Buffer m_x, m_b, m_d[2], m_q, m_partials, m_state, m_table;
    Launches m_rebuild, m_finish;
    Launches m_start[2], m_iteration[2][2];  // [preconditioner], [preconditioner][parity]
};

DevicePcg::DevicePcg(Device& device, Memory& memory, const cl::Program& program,
                     const Stencil5& shape, float absolute, float relative)
    : m_queue(device.queue())
    , m_stencil(shape)
    , m_levels(planLevels(shape))
    , m_cellGroups(groupsOver(shape.mx, shape.my))
    , m_vectorGroups(m_levels[0].stored() / int(localSize))
    , m_plane(m_levels.back().offset + m_levels.back().stored())
{
    const std::size_t fine = m_levels[0].stored() * sizeof(cl_float);
    m_coef = memory.zeros(4 * std::size_t(m_plane) * sizeof(cl_float));
    m_levelX = memory.zeros(m_plane * sizeof(cl_float));
    m_levelB = memory.zeros(m_plane * sizeof(cl_float));
    for (cl::Buffer* b : {&m_x, &m_b, &m_d[0], &m_d[1], &m_q})
        *b = memory.zeros(fine);
    m_partials = memory.zeros(std::size_t(kPartialSlots) * std::max(m_cellGroups, m_vectorGroups)
                              * sizeof(cl_float));
    m_state = memory.zeros(sizeof(CgState));
    std::vector<cl_int> table;  // mgTail's, LEVEL_INTS ints per level
    for (const LevelShape& l : m_levels)
        table.insert(table.end(), {l.mx, l.my, l.offset, l.groupX, l.groupY});
    m_table = memory.upload(table);

    m_rebuild = rebuildLaunches(program);
    const Launches preconditioners[2] = {
        vcycleLaunches(program),
        {overVectors(kernel(program, "cgJacobi", m_coef, m_plane, m_levelX, m_levelB, m_state))}};
    for (const Preconditioner p : {kMultigrid, kJacobi}) {
        m_start[p] = startLaunches(program, preconditioners[p], absolute, relative);
        for (int parity = 0; parity < 2; ++parity)
            m_iteration[p][parity] = iterationLaunches(program, parity, preconditioners[p]);
    }
    if (shape.singular()) {
        m_finish = {overVectors(kernel(program, "cgSum", m_x, m_partials)),
                    singleGroup(kernel(program, "cgMean", m_state, m_partials, int(kSumX),
                                       m_vectorGroups, shape.mx * shape.my)),
                    overCells(kernel(program, "cgRemoveMean", m_x, m_state, shape.mx, shape.my,
                                     m_partials))};
    }
}

Launches DevicePcg::rebuildLaunches(const cl::Program& program) const
{
    const auto inverse = [&](const LevelShape& l) {
        return overLattice(kernel(program, "levelInverse", m_coef, m_plane, l.mx, l.my, l.offset),
                           l.mx, l.my);
    };
    // The stencil's values are set by setStencil() before each rebuild.
    Launches launches{overCells(kernel(program, "levelFine", m_coef, m_plane, m_levels[0].mx,
                                       m_levels[0].my, 0.0f, 0.0f, 0.0f, 0, 0)),
                      inverse(m_levels[0])};
    for (std::size_t l = 1; l < m_levels.size(); ++l) {
        const LevelShape &fine = m_levels[l - 1], &coarse = m_levels[l];
        launches.push_back(overLattice(kernel(program, "levelCoarsen", m_coef, m_plane, fine.mx,
                                              fine.my, fine.offset, coarse.mx, coarse.my,
                                              coarse.offset, fine.groupX, fine.groupY),
                                       coarse.mx, coarse.my));
        launches.push_back(inverse(coarse));
    }
    return launches;
}

// PcgSolver::cycle: one launch per half-sweep, restriction and prolongation on the levels above
// the first of at most kTailCells unknowns, then the rest in mgTail.
Launches DevicePcg::vcycleLaunches(const cl::Program& program) const
{
    const int last = int(m_levels.size()) - 1;
    int tail = 0;
    while (m_levels[tail].mx * m_levels[tail].my > kTailCells)
        ++tail;
    const auto relax = [&](const LevelShape& l, int colour, int fromZero) {
        return overLattice(kernel(program, "mgRelax", m_coef, m_plane, m_levelX, m_levelB, m_state,
                                  l.mx, l.my, l.offset, colour, fromZero),
                           (l.mx + 1) / 2, l.my);
    };
    // Restriction and prolongation, over the cells of `over` (the coarse or the fine level).
    const auto between = [&](const char* name, const LevelShape& fine, const LevelShape& coarse,
                             const LevelShape& over, auto... buffers) {
        return overLattice(kernel(program, name, buffers..., m_state, fine.mx, fine.my, fine.offset,
                                  coarse.mx, coarse.my, coarse.offset, fine.groupX, fine.groupY),
                           over.mx, over.my);
    };
    Launches launches;
    for (int l = 0; l < tail; ++l) {
        for (int sweep = 0; sweep < kSmoothingSweeps; ++sweep) {
            launches.push_back(relax(m_levels[l], 0, sweep == 0));
            launches.push_back(relax(m_levels[l], 1, 0));
        }
        launches.push_back(between("mgRestrict", m_levels[l], m_levels[l + 1], m_levels[l + 1],
                                   m_coef, m_plane, m_levelX, m_levelB));
    }
    launches.push_back(singleGroup(kernel(program, "mgTail", m_coef, m_plane, m_levelX, m_levelB,
                                          m_state, m_table, tail, last)));
    for (int l = tail - 1; l >= 0; --l) {
        launches.push_back(between("mgProlong", m_levels[l], m_levels[l + 1], m_levels[l],
                                   m_levelX));
        for (int sweep = 0; sweep < kSmoothingSweeps; ++sweep) {
            launches.push_back(relax(m_levels[l], 1, 0));
            launches.push_back(relax(m_levels[l], 0, 0));
        }
    }
    return launches;
}

// r = b - A x (its mean removed for a singular system), the tolerance and the first check, then
// the first z = M r and r.z.
Launches DevicePcg::startLaunches(const cl::Program& program, const Launches& preconditioner,
                                  float absolute, float relative) const
{
    const int mx = m_levels[0].mx, my = m_levels[0].my;
    Launches launches{overCells(kernel(program, "cgResidual", m_coef, m_plane, m_x, m_b, m_levelB,
                                       m_d[0], mx, my, m_partials))};
    if (m_stencil.singular()) {
        launches.push_back(singleGroup(kernel(program, "cgMean", m_state, m_partials, int(kSumR),
                                              m_cellGroups, mx * my)));
        launches.push_back(
            overCells(kernel(program, "cgRemoveMean", m_levelB, m_state, mx, my, m_partials)));
    }
    launches.push_back(singleGroup(
        kernel(program, "cgStart", m_state, m_partials, m_cellGroups, absolute, relative)));
    append(launches, preconditioner);
    append(launches, directionLaunches(program));
    return launches;
}

// One iteration of PcgSolver::solve. cgApply reads the direction from m_d[parity] and writes the
// next one to the other copy.
Launches DevicePcg::iterationLaunches(const cl::Program& program, int parity,
                                      const Launches& preconditioner) const
{
    const int mx = m_levels[0].mx, my = m_levels[0].my;
    const cl::Buffer& d = m_d[1 - parity];
    Launches launches{
        overCells(kernel(program, "cgApply", m_coef, m_plane, m_levelX, m_d[parity], d, m_q,
                         m_state, mx, my, m_partials)),
        singleGroup(kernel(program, "cgAlpha", m_state, m_partials, m_cellGroups)),
        overVectors(kernel(program, "cgStep", m_x, m_levelB, d, m_q, m_state, m_partials)),
        singleGroup(kernel(program, "cgConverged", m_state, m_partials, m_vectorGroups))};
    append(launches, preconditioner);
    append(launches, directionLaunches(program));
    return launches;
}

// After z = M r: r.z, and from it beta.
Launches DevicePcg::directionLaunches(const cl::Program& program) const
{
    return {overVectors(kernel(program, "cgDot", m_levelB, m_levelX, m_state, m_partials)),
            singleGroup(kernel(program, "cgBeta", m_state, m_partials, m_vectorGroups))};
}

// Jacobi while the couplings of a row (2 ax + 2 ay) add up to at most half its identity part: the
// Jacobi-preconditioned matrix then has a condition number of at most about
// 1 + 4 (ax + ay) / center <= 2, so CG gains a factor of at least 6 per iteration.
void DevicePcg::setStencil(const Stencil5& stencil)
{
    if (m_hasStencil && stencil == m_stencil)
        return;
    m_stencil = stencil;
    m_hasStencil = true;
    m_preconditioner = 4.0 * (stencil.ax + stencil.ay) <= stencil.center ? kJacobi : kMultigrid;
    cl::Kernel& fine = m_rebuild.front().kernel;
    fine.setArg(4, float(stencil.center));
    fine.setArg(5, float(stencil.ax));
    fine.setArg(6, float(stencil.ay));
    fine.setArg(7, cl_int(stencil.dirichletX));
    fine.setArg(8, cl_int(stencil.dirichletY));
    enqueue(m_queue, m_rebuild);
}

void DevicePcg::solve(int maxIterations)
{
    enqueue(m_queue, m_start[m_preconditioner]);
    CgState state{};
    int queued = 0;
    int checkAt = std::max(m_lastIterations, 1);
    for (;;) {
        for (; queued < std::min(checkAt, maxIterations); ++queued)
            enqueue(m_queue, m_iteration[m_preconditioner][queued % 2]);
        m_queue.enqueueReadBuffer(m_state, CL_TRUE, 0, sizeof state, &state);
        if (state.done || queued >= maxIterations)
            break;
        checkAt = queued + kCheckEvery;
    }
    enqueue(m_queue, m_finish);
    m_lastIterations = state.iterations;
}

void DevicePcg::clearSolution()
{
    const std::size_t bytes = std::size_t(m_levels[0].stored()) * sizeof(cl_float);
    m_queue.enqueueFillBuffer(m_x, cl_float(0), 0, bytes);
}

std::vector<double> DevicePcg::readSolution() const
{
    const LevelShape& l = m_levels[0];
    std::vector<float> stored(l.stored());
    m_queue.enqueueReadBuffer(m_x, CL_TRUE, 0, stored.size() * sizeof(cl_float), stored.data());
    std::vector<double> unknowns;
    unknowns.reserve(std::size_t(l.mx) * l.my);
    for (int j = 0; j < l.my; ++j)
        for (int i = 0; i < l.mx; ++i)
            unknowns.push_back(stored[std::size_t(j + 1) * (l.mx + 2) + i + 1]);
    return unknowns;
}

void DevicePcg::writeSolution(const std::vector<double>& unknowns)
{
    const LevelShape& l = m_levels[0];
    std::vector<float> stored(l.stored(), 0.0f);
    for (int j = 0; j < l.my; ++j)
        for (int i = 0; i < l.mx; ++i)
            stored[std::size_t(j + 1) * (l.mx + 2) + i + 1] = float(unknowns[std::size_t(j) * l.mx + i]);
    m_queue.enqueueWriteBuffer(m_x, CL_TRUE, 0, stored.size() * sizeof(cl_float), stored.data());
}

// ---- The fluid ---------------------------------------------------------------------------------

struct Field {
    cl::Buffer u, v;
};

// The interior faces of one component as the unknowns of its viscosity solve (FaceGrid in
// FluidSolver.cpp): the lattice lines on the walls across the component's axis are left out.
struct FaceLattice {
    int cols, rows, firstCol, firstRow;
    bool normalX;

    int mx() const { return cols - 2 * firstCol; }
    int my() const { return rows - 2 * firstRow; }
};

FaceLattice faceLattice(int nx, int ny, int component)
{
    return component == 0 ? FaceLattice{nx + 1, ny, 1, 0, true}
                          : FaceLattice{nx, ny + 1, 0, 1, false};
}

struct StylusSegment {
    Vec2 from, to;
    double radius;
    Vec2 velocity;  // of the pen, canvas units / s
};

bool isFinite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

std::vector<double> readFloats(cl::CommandQueue& queue, const cl::Buffer& buffer, std::size_t count)
{
    std::vector<float> values(count);
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, count * sizeof(float), values.data());
    return {values.begin(), values.end()};
}

void writeFloats(cl::CommandQueue& queue, const cl::Buffer& buffer,
                 const std::vector<double>& values)
{
    const std::vector<float> narrow(values.begin(), values.end());
    queue.enqueueWriteBuffer(buffer, CL_TRUE, 0, narrow.size() * sizeof(float), narrow.data());
}

std::string buildOptions()
{
    return commonBuildOptions(false) + " -DVF_GROUP=" + std::to_string(kGroup)
         + " -DVF_SMOOTHING_SWEEPS=" + std::to_string(kSmoothingSweeps)
         + " -DVF_COARSEST_SWEEPS=" + std::to_string(kCoarsestSweeps);
}

} // namespace

struct DeviceFluid::Impl {
    Impl(Device& device, const FluidSettings& settings);

    Field field();
    // One stream function lattice: the cell corners and a ghost corner past each wall (flow_fluid.cl).
    std::size_t streamCorners() const { return std::size_t(nx + 3) * (ny + 3); }
    void computeStreamFunction(bool fromRest);
    Stencil5 pressureStencil() const;
    Stencil5 viscousStencil(int component, double nuDt) const;
    void step(double dt);
    void diffuse(double dt);
    void applyStylus(const StylusSegment& segment, double dt);
    void applyForce(double dt);
    // The u faces as the first ny rows, the v faces as the ny + 1 rows after them (fluid.cl, Face).
    Launch overFaces(cl::Kernel k) const { return overLattice(std::move(k), nx + 1, 2 * ny + 1); }

    Device& device;
    cl::CommandQueue& queue;
    FluidSettings settings;
    int nx, ny;
    double hx, hy;
    std::size_t uCount, vCount;
    Memory memory;
    cl::Program program;
    Field current;
    Field start;       // the field at the step's start (the solver advects from it)
    cl::Buffer stream; // the stream functions at the step's start, halfway, and end (flow_fluid.cl)
    Field forward;  // MacCormack: the semi-Lagrangian result, traced back
    Field acceleration;  // the body force of the next step (addForce), if forceDamping is set
    DevicePcg pressure;
    std::vector<DevicePcg> viscosity;  // u, v; none for an inviscid fluid
    Launch advect;
    std::vector<Launch> correct;  // MacCormack's second pass, if any
    Launch stylus, force, divergence, gradient, streamFunction;
    std::vector<Launch> gather, scatter;
    std::vector<StylusSegment> pending;
    std::optional<double> forceDamping;
};

DeviceFluid::Impl::Impl(Device& device, const FluidSettings& s)
    : device(device)
    , queue(device.queue())
    , settings(s)
    , nx(s.nx)
    , ny(s.ny)
    , hx(s.width / s.nx)
    , hy(s.height / s.ny)
    , uCount(std::size_t(s.nx + 1) * s.ny)
    , vCount(std::size_t(s.nx) * (s.ny + 1))
    , memory(device, "the " + std::to_string(s.nx) + " x " + std::to_string(s.ny) + " fluid grid")
    , program(device.build(joinedKernelSources({"flow.h.cl", "flow_fluid.cl", "fluid.cl"}),
                           "the fluid solver (fluid.cl)", buildOptions()))
    , current(field())
    , start(field())
    , stream(memory.zeros(3 * streamCorners() * sizeof(cl_float)))
    , acceleration(field())
    , pressure(device, memory, program, pressureStencil(), float(s.pressureTolerance),
               kPressureRoundoffFloor)
{
    pressure.setStencil(pressureStencil());
    // The time step, the pen and the stylus strength are set when they are known.
    if (s.advection == Advection::MacCormack) {
        forward = field();
        advect = overFaces(kernel(program, "advect", start.u, start.v, forward.u, forward.v, nx, ny,
                                  0.0f, 0.0f));
        correct.push_back(overFaces(kernel(program, "macCormack", start.u, start.v, forward.u,
                                           forward.v, current.u, current.v, nx, ny, 0.0f, 0.0f)));
    } else {
        advect = overFaces(kernel(program, "advect", start.u, start.v, current.u, current.v, nx, ny,
                                  0.0f, 0.0f));
    }
    stylus = overFaces(kernel(program, "stylus", current.u, current.v, nx, ny, float(hx),
                              float(hy), 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f));
    force = overFaces(kernel(program, "bodyForce", current.u, current.v, acceleration.u, acceleration.v,
                             nx, ny, 0.0f, 0.0f));
    divergence = overLattice(kernel(program, "divergence", current.u, current.v, nx, ny, float(hx),
                                    float(hy), pressure.b(), pressure.partials()),
                             nx, ny);
    gradient = overFaces(kernel(program, "subtractGradient", current.u, current.v, pressure.x(), nx,
                                ny, float(hx), float(hy)));
    streamFunction = overLattice(
        kernel(program, "streamFunction", current.u, current.v, nx, ny, float(hx), float(hy), 0, stream), nx + 3, 1);
    if (s.viscosity == 0.0)
        return;
    viscosity.reserve(2);
    for (int c = 0; c < 2; ++c) {
        const FaceLattice f = faceLattice(nx, ny, c);
        const cl::Buffer& faces = c == 0 ? current.u : current.v;
        // Planned with nu dt = 1: only the ratio of the couplings shapes the levels (planLevels).
        const DevicePcg& solver = viscosity.emplace_back(
            device, memory, program, viscousStencil(c, 1.0), 0.0f, kViscosityRelativeTolerance);
        gather.push_back(overLattice(kernel(program, "gatherFaces", faces, f.cols, f.firstCol,
                                            f.firstRow, f.mx(), f.my(), solver.x(), solver.b(),
                                            solver.partials()),
                                     f.mx(), f.my()));
        scatter.push_back(overLattice(kernel(program, "scatterFaces", faces, f.cols, f.firstCol,
                                             f.firstRow, f.mx(), f.my(), solver.x()),
                                      f.mx(), f.my()));
    }
}

Field DeviceFluid::Impl::field()
{
    return {memory.zeros(uCount * sizeof(cl_float)), memory.zeros(vCount * sizeof(cl_float))};
}

// -Laplacian on the cells, Neumann on every wall (FluidSolver::project): singular, the constants
// are its null space.
Stencil5 DeviceFluid::Impl::pressureStencil() const
{
    return {nx, ny, 0.0, 1.0 / (hx * hx), 1.0 / (hy * hy), false, false};
}

// (I - nu dt Laplacian) on one component's interior faces: Dirichlet across its normal axis (the
// walls), Neumann along the other (free slip), as FluidSolver::diffuse.
Stencil5 DeviceFluid::Impl::viscousStencil(int component, double nuDt) const
{
    const FaceLattice f = faceLattice(nx, ny, component);
    return {f.mx(), f.my(), 1.0, nuDt / (hx * hx), nuDt / (hy * hy), f.normalX, !f.normalX};
}

// The stream functions the contours move through (FluidFlow): the end's becomes the start's, the
// new field's is the end's, and the halfway one lies between; from rest, all three are the field's.
void DeviceFluid::Impl::computeStreamFunction(bool fromRest)
{
    if (!fromRest)
        queue.enqueueCopyBuffer(stream, stream, 2 * streamCorners() * sizeof(cl_float), 0,
                                streamCorners() * sizeof(cl_float));
    streamFunction.kernel.setArg(6, cl_int(fromRest));
    enqueue(queue, streamFunction);
}

// The order of FluidSolver::step: advection from a copy of the field at the step's start, viscosity,
// the pen, projection; then the stream functions of the step (for the contours).
void DeviceFluid::Impl::step(double dt)
{
    queue.enqueueCopyBuffer(current.u, start.u, 0, 0, uCount * sizeof(cl_float));
    queue.enqueueCopyBuffer(current.v, start.v, 0, 0, vCount * sizeof(cl_float));
    advect.kernel.setArg(6, float(dt / hx));
    advect.kernel.setArg(7, float(dt / hy));
    enqueue(queue, advect);
    for (Launch& launch : correct) {
        launch.kernel.setArg(8, float(dt / hx));
        launch.kernel.setArg(9, float(dt / hy));
        enqueue(queue, launch);
    }
    if (!viscosity.empty())
        diffuse(dt);
    for (const StylusSegment& segment : pending)
        applyStylus(segment, dt);
    pending.clear();
    if (forceDamping)
        applyForce(dt);
    enqueue(queue, divergence);
    pressure.solve(iterationCap(nx, ny));
    enqueue(queue, gradient);
    computeStreamFunction(false);
}

void DeviceFluid::Impl::diffuse(double dt)
{
    for (int c = 0; c < 2; ++c) {
        const FaceLattice f = faceLattice(nx, ny, c);
        viscosity[c].setStencil(viscousStencil(c, settings.viscosity * dt));
        enqueue(queue, gather[c]);
        viscosity[c].solve(iterationCap(f.cols, f.rows));
        enqueue(queue, scatter[c]);
    }
}

void DeviceFluid::Impl::applyStylus(const StylusSegment& segment, double dt)
{
    cl_uint index = 6;
    for (const double value : {segment.from.x, segment.from.y, segment.to.x, segment.to.y,
                               1.0 / (segment.radius * segment.radius), segment.velocity.x,
                               segment.velocity.y, stylusStrength(settings, dt)})
        stylus.kernel.setArg(index++, float(value));
    enqueue(queue, stylus);
}

void DeviceFluid::Impl::applyForce(double dt)
{
    force.kernel.setArg(6, float(std::exp(-*forceDamping * dt)));
    force.kernel.setArg(7, float(dt));
    enqueue(queue, force);
    forceDamping.reset();
}

DeviceFluid::DeviceFluid(Device& device, const FluidSettings& settings)
{
    // The reference solver's validation, so both refuse the same settings with the same message.
    static_cast<void>(FluidSolver(settings));
    m = translatingErrors(device, [&] { return std::make_unique<Impl>(device, settings); });
}

DeviceFluid::~DeviceFluid() = default;

const FluidSettings& DeviceFluid::settings() const { return m->settings; }

void DeviceFluid::addStylus(Vec2 from, Vec2 to, double radius, double duration)
{
    // As FluidSolver::addStylus: a pen that takes no time (or a NaN time) to move jumped.
    if (!(duration > 0.0) || !(radius > 0.0) || !std::isfinite(radius))
        return;
    const Vec2 velocity = (to - from) / duration;
    if (!isFinite(from) || !isFinite(to) || !isFinite(velocity))
        return;
    m->pending.push_back({from, to, radius, velocity});
}

void DeviceFluid::addForce(const BodyForce& force)
{
    validateForce(force, m->nx, m->ny);
    translatingErrors(m->device, [&] {
        writeFloats(m->queue, m->acceleration.u, force.acceleration.u);
        writeFloats(m->queue, m->acceleration.v, force.acceleration.v);
    });
    m->forceDamping = force.damping;
}

void DeviceFluid::step(double dt)
{
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw std::invalid_argument("DeviceFluid::step: dt must be positive and finite");
    translatingErrors(m->device, [&] { m->step(dt); });
}

FlowBinding DeviceFluid::binding(double t0, double t1) const
{
    FlowBinding b;
    b.field = m->stream;
    b.nx = m->nx;
    b.ny = m->ny;
    b.hx = float(m->hx);
    b.hy = float(m->hy);
    b.t0 = t0;
    b.t1 = t1;
    return b;
}

MacVelocity DeviceFluid::readVelocity() const
{
    return translatingErrors(m->device, [&] {
        return MacVelocity{m->nx, m->ny, m->hx, m->hy,
                           readFloats(m->queue, m->current.u, m->uCount),
                           readFloats(m->queue, m->current.v, m->vCount)};
    });
}

void DeviceFluid::writeVelocity(const MacVelocity& velocity)
{
    if (velocity.nx != m->nx || velocity.ny != m->ny || velocity.u.size() != m->uCount
        || velocity.v.size() != m->vCount)
        throw std::invalid_argument("DeviceFluid::writeVelocity: expected a "
                                    + std::to_string(m->nx) + " x " + std::to_string(m->ny)
                                    + " grid");
    translatingErrors(m->device, [&] {
        for (const Field* field : {&m->current, &m->start}) {
            writeFloats(m->queue, field->u, velocity.u);
            writeFloats(m->queue, field->v, velocity.v);
        }
        m->computeStreamFunction(true);
        // As FluidSolver::setVelocity: the warm-start pressure belongs to the old history; dropping
        // it makes every later step a function of this velocity alone.
        m->pressure.clearSolution();
    });
}

std::vector<double> DeviceFluid::readPressure() const
{
    return translatingErrors(m->device, [&] { return m->pressure.readSolution(); });
}

void DeviceFluid::writePressure(const std::vector<double>& pressure)
{
    if (pressure.size() != std::size_t(m->nx) * m->ny)
        throw std::invalid_argument("DeviceFluid::writePressure: expected " + std::to_string(m->nx) + " x "
                                    + std::to_string(m->ny) + " cells");
    translatingErrors(m->device, [&] { m->pressure.writeSolution(pressure); });
}

// Measured as FluidSolver::maxDivergence measures it, in double, on the float32 field read back.
double DeviceFluid::maxDivergence() const
{
    FluidSolver probe(m->settings);
    probe.setVelocity(readVelocity());
    return probe.maxDivergence();
}

} // namespace vf::sim::opencl
