// vf_bench: docs/BENCHMARKS.md, "The stirred scene". Vertex-steps per second of the full step
// (fluid solve, RK4 advection, adaptive spacing with the proximity term, refinement) at 100k and 1M vertices for
// every backend, beside a naive scalar RK4 loop over the same number of points in the same flow
// (and, for the OpenCL backend, its bare RK4 kernel), in one run of one binary. docs/BENCHMARKS.md
// has the figures, the machine and the commands.
//
// Families (run in this order, so the full step can report its ratios to the baselines):
//   NaiveRk4/N                 plain std::vector<dvec2>, classic RK4 through FluidFlow::velocity
//   BareRk4Kernel/N            the OpenCL backend's own RK4 advection kernel alone over N points in
//                              the device fluid: the ceiling the OpenCL step's throughput is held to
//   FullStep/<backend>/N       Simulation::step through the backend interface (reference, opencl)
//   Breakdown/reference/N      the reference step taken apart phase by phase (ms per step)
//   Drop/<backend>/N           Simulation::drop into the stirred sheet of N vertices (ms per drop),
//                              and the share of it the widening of layers takes
//
// The scene: the default 64×64 fluid, stirred by a pen that circles the canvas centre at a steady
// speed, first alone (so the flow is already moving) and then with a lattice of small ink circles
// whose total vertex count is about N. Adaptive spacing and proximity are on (the defaults).
#include "BenchMain.h"
#include "BenchScene.h"

#include "sim/ContourTracker.h"
#include "sim/FluidFlow.h"
#include "sim/ProximityGrid.h"
#include "sim/Simulation.h"
#include "sim/SpacingField.h"
#include "sim/opencl/ContourCodes.h"
#include "sim/opencl/DeviceContours.h"
#include "sim/opencl/DeviceFluid.h"
#include "sim/opencl/KernelSources.h"
#include "sim/opencl/Launch.h"
#include "sim/opencl/OpenClSimulation.h"

#include <benchmark/benchmark.h>
#include <malloc.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace vf::sim;
using namespace vf::bench;
using Clock = std::chrono::steady_clock;

// CPU time of this thread: what a phase costs, whatever else the (shared) machine runs meanwhile.
double threadSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// ---- Memory: peak resident set growth, from /proc/self (Linux) --------------------------------

long procStatusKiB(const char* key)
{
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::string prefix = std::string(key) + ":";
    while (std::getline(in, line))
        if (line.rfind(prefix, 0) == 0)
            return std::stol(line.substr(prefix.size()));
    return -1;
}

// Returns freed heap to the system and restarts the peak (VmHWM) at the current resident size, so
// the peak read later is this benchmark's own. Returns that resident size in bytes.
double resetPeakResident()
{
    malloc_trim(0);
    std::ofstream("/proc/self/clear_refs") << "5";
    return 1024.0 * double(procStatusKiB("VmRSS"));
}

double peakResident() { return 1024.0 * double(procStatusKiB("VmHWM")); }

// Bytes the program holds from malloc right now (small chunks plus mmapped blocks): the live
// footprint, free of what the allocator keeps resident for reuse.
double heapInUse()
{
    const struct mallinfo2 info = mallinfo2();
    return double(info.uordblks) + double(info.hblkhd);
}

// ---- NaiveRk4 -----------------------------------------------------------------------------------

// Wall-clock vertex-steps / s of every NaiveRk4 run (repetitions included) by target size, for the
// FullStep's ratio; the median is used.
std::map<std::int64_t, std::vector<double>> g_naiveRates;
// The same for BareRk4Kernel, for the OpenCL full step's ratio to it.
std::map<std::int64_t, std::vector<double>> g_bareRates;

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

Vec2 naiveRk4(const FluidFlow& flow, Vec2 p, double t, double dt)
{
    const Vec2 k1 = flow.velocity(p, t);
    const Vec2 k2 = flow.velocity(p + 0.5 * dt * k1, t + 0.5 * dt);
    const Vec2 k3 = flow.velocity(p + 0.5 * dt * k2, t + 0.5 * dt);
    const Vec2 k4 = flow.velocity(p + dt * k3, t + dt);
    return p + (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// Exactly `target` points spread evenly over the scene's circles: what the baselines advance.
std::vector<Vec2> pointsOnCircles(const Layout& layout, std::int64_t target)
{
    const std::vector<Vec2> centres = circleCentres(layout);
    std::vector<Vec2> points;
    points.reserve(std::size_t(target));
    const std::int64_t circles = std::int64_t(centres.size());
    for (std::int64_t c = 0; c < circles; ++c) {
        const std::int64_t n = target / circles + (c < target % circles ? 1 : 0);
        for (std::int64_t k = 0; k < n; ++k) {
            const double angle = 2.0 * std::numbers::pi * double(k) / double(n);
            points.push_back(centres[c] + layout.radius * Vec2(std::cos(angle), std::sin(angle)));
        }
    }
    return points;
}

// Exactly N points on the same circles, advanced by classic RK4 through the same stirred flow
// (FluidFlow::velocity: bilinear MAC sampling, blended in time within the step, as the engine
// samples it). No refinement, no spacing, no proximity. The fluid solve is outside the timing.
void naiveRk4Benchmark(benchmark::State& state, std::int64_t target)
{
    const Layout layout = layoutFor(target);
    FluidFlow flow(settingsFor(layout).fluid);
    int step = 0;
    const auto stirAndAdvance = [&] {
        flow.solver().addStylus(penAt(step), penAt(step + 1), kPenRadius, kDt);
        flow.advance(kDt);
        ++step;
    };
    while (step < kStirSteps + kWarmupSteps)
        stirAndAdvance();

    std::vector<Vec2> points = pointsOnCircles(layout, target);

    double seconds = 0.0, cpuSeconds = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        stirAndAdvance();
        const double t = flow.time() - kDt;
        state.ResumeTiming();
        const auto start = Clock::now();
        const double cpuStart = threadSeconds();
        for (Vec2& p : points)
            p = naiveRk4(flow, p, t, kDt);
        benchmark::DoNotOptimize(points.data());
        benchmark::ClobberMemory();
        cpuSeconds += threadSeconds() - cpuStart;
        seconds += std::chrono::duration<double>(Clock::now() - start).count();
    }
    const double vertexSteps = double(target) * double(state.iterations());
    g_naiveRates[target].push_back(vertexSteps / seconds);
    state.counters["vertices"] = double(target);
    state.counters["vertex_steps_per_s"] = benchmark::Counter(vertexSteps, benchmark::Counter::kIsRate);
    state.counters["vertex_steps_per_cpu_s"] = vertexSteps / cpuSeconds;
    state.counters["B_per_vertex"] = double(sizeof(Vec2));  // the points array, all there is
}

// ---- BareRk4Kernel ------------------------------------------------------------------------------

// The `advect` kernel of contours.cl (classic RK4 through flow_fluid.cl's sampling, the kernel the
// full step advects with) alone, over exactly N float points on the same circles, in the same
// stirred DeviceFluid: no spacing, no refinement, no proximity, the fluid solve outside the timing.
// Timed from the launch to the queue's finish.
void bareRk4KernelBenchmark(benchmark::State& state, std::int64_t target)
{
    using namespace vf::sim::opencl;
    std::optional<Device> device;
    try {
        device = Device::open();
    } catch (const DeviceError& e) {
        state.SkipWithError((std::string("OpenCL backend skipped: ") + e.what()).c_str());
        return;
    }
    const Layout layout = layoutFor(target);
    const FluidSettings fluidSettings = settingsFor(layout).fluid;
    DeviceFluid fluid(*device, fluidSettings);
    int step = 0;
    double time = 0.0;
    const auto stirAndAdvance = [&] {
        fluid.addStylus(penAt(step), penAt(step + 1), kPenRadius, kDt);
        fluid.step(kDt);
        ++step;
        time += kDt;
    };
    while (step < kStirSteps + kWarmupSteps)
        stirAndAdvance();

    const bool fp64 = device->hasFp64();
    const std::string acc = fp64 ? "double" : "float";
    const cl::Program program =
        device->build(joinedKernelSources({"flow.h.cl", "flow_fluid.cl", "workgroup.cl", "contours.cl"}),
                      "contours.cl", commonBuildOptions(fp64) + " -DVF_ACC=" + acc + " -DVF_ACC2=" + acc +
                                         "2 -DVF_ACC4=" + acc + "4" + contourCodeDefinitions());
    cl::Kernel advect(program, "advect");
    std::vector<cl_float4> motion;
    for (const Vec2& p : pointsOnCircles(layout, target))
        motion.push_back({{cl_float(p.x), cl_float(p.y), cl_float(p.x), cl_float(p.y)}});
    cl::CommandQueue& queue = device->queue();
    const cl::Buffer points(device->context(), CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR,
                            motion.size() * sizeof(cl_float4), motion.data());
    const cl::Buffer status(device->context(), CL_MEM_READ_WRITE, statusWords * sizeof(cl_uint));
    queue.enqueueFillBuffer(status, cl_uint(0), 0, statusWords * sizeof(cl_uint));
    // MOTION_ARGS of contours.cl: RK4 through the flow (no map, no chord tolerance).
    const cl_int rewind = 1;
    const cl_float4 noMap{};
    const auto n = cl_uint(target);

    double seconds = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        stirAndAdvance();
        queue.finish();
        state.ResumeTiming();
        const auto start = Clock::now();
        launch(queue, advect, laneGroups(n), fluid.binding(time - kDt, time), motionFlow, noMap, noMap, noMap, rewind,
               cl_float(0), points, n, points, cl_int(0), status);
        queue.finish();
        seconds += std::chrono::duration<double>(Clock::now() - start).count();
    }
    const double vertexSteps = double(target) * double(state.iterations());
    g_bareRates[target].push_back(vertexSteps / seconds);
    state.counters["vertices"] = double(target);
    state.counters["vertex_steps_per_s"] = benchmark::Counter(vertexSteps, benchmark::Counter::kIsRate);
    if (const auto naive = g_naiveRates.find(target); naive != g_naiveRates.end())
        state.counters["bare_over_naive"] = (vertexSteps / seconds) / median(naive->second);
}

// ---- FullStep -----------------------------------------------------------------------------------

// The backend's simulation of the scene, or null with the benchmark skipped where it has no device.
std::unique_ptr<Simulation> makeOrSkip(benchmark::State& state, const Backend& backend, const Layout& layout)
{
    try {
        return backend.make(settingsFor(layout));
    } catch (const opencl::DeviceError& e) {
        state.SkipWithError((std::string("OpenCL backend skipped: ") + e.what()).c_str());
        return nullptr;
    }
}

void fullStepBenchmark(benchmark::State& state, const Backend& backend, std::int64_t target)
{
    const Layout layout = layoutFor(target);
    const std::unique_ptr<Simulation> sim = makeOrSkip(state, backend, layout);
    if (!sim)
        return;
    int step = 0;
    const auto stirAndStep = [&] {
        sim->stylus(penAt(step), penAt(step + 1), kPenRadius, kDt);
        ++step;
        return sim->step(kDt);
    };
    while (step < kStirSteps)
        stirAndStep();

    const double baseline = resetPeakResident();  // the fluid is allocated; the ink is not
    const double heapBaseline = heapInUse();
    for (const Vec2& centre : circleCentres(layout))
        sim->addRegion({circle(centre, layout.radius, layout.maxSpacing)});
    for (int k = 0; k < kWarmupSteps; ++k)
        stirAndStep();

    double vertexSteps = 0.0, substeps = 0.0, seconds = 0.0, cpuSeconds = 0.0;
    const double first = double(sim->vertexCount());
    bool limited = false;
    for (auto _ : state) {
        const double n = double(sim->vertexCount());  // the vertices this step advances
        const auto start = Clock::now();
        const double cpuStart = threadSeconds();
        const StepReport report = stirAndStep();
        cpuSeconds += threadSeconds() - cpuStart;
        seconds += std::chrono::duration<double>(Clock::now() - start).count();
        vertexSteps += n;
        substeps += report.substeps;
        limited = limited || report.vertexLimitReached;
    }
    const double steps = double(state.iterations());
    const double mean = vertexSteps / steps;
    state.counters["vertices"] = mean;
    state.counters["growth"] = double(sim->vertexCount()) / first;  // last / first, over the timed steps
    state.counters["substeps"] = substeps / steps;
    state.counters["vertex_steps_per_s"] = benchmark::Counter(vertexSteps, benchmark::Counter::kIsRate);
    state.counters["vertex_steps_per_cpu_s"] = vertexSteps / cpuSeconds;
    state.counters["peak_rss_B_per_vertex"] = (peakResident() - baseline) / mean;
    state.counters["live_heap_B_per_vertex"] = (heapInUse() - heapBaseline) / double(sim->vertexCount());
    if (const auto naive = g_naiveRates.find(target); naive != g_naiveRates.end())
        state.counters["full_over_naive"] = (vertexSteps / seconds) / median(naive->second);
    // Only the OpenCL step runs the bare kernel's code; beside the reference the ratio means nothing.
    if (const auto bare = g_bareRates.find(target); bare != g_bareRates.end() && sim->backendName() == "opencl")
        state.counters["full_over_bare"] = (vertexSteps / seconds) / median(bare->second);
    if (sim->backendName() == "opencl")
        state.counters["device_B_per_vertex"] = double(opencl::DeviceContours::bytesPerVertex());
    if (limited)
        state.SkipWithError("refinement hit max_vertices: the scene is not the one described");
}

// ---- Breakdown ----------------------------------------------------------------------------------

// The reference step (ReferenceSimulation::step with one substep) taken apart, each phase in thread
// CPU time. The real step runs first (strain, fluid, ContourTracker::advect); then RK4 alone, the
// spacing (eqs. 3-7) alone, and the proximity grid's build and queries alone are repeated on a
// copy of the state that step started from. Refinement (split, collapse, ring bookkeeping) is
// what advect takes beyond RK4 and spacing. Every phase is reported as its best (minimum) over the
// timed steps, which filters out other processes on a shared machine; the benchmark's own time
// (manual) is the mean real step.
void breakdownBenchmark(benchmark::State& state, std::int64_t target)
{
    const Layout layout = layoutFor(target);
    const SimulationSettings settings = settingsFor(layout);
    FluidFlow flow(settings.fluid);
    ContourTracker tracker(settings.tracking);
    ProximityGrid grid;
    int step = 0;
    const auto stir = [&] {
        flow.solver().addStylus(penAt(step), penAt(step + 1), kPenRadius, kDt);
        ++step;
    };
    for (int k = 0; k < kStirSteps; ++k) {
        stir();
        flow.advance(kDt);
    }
    int region = 0;
    for (const Vec2& centre : circleCentres(layout))
        tracker.addContour(region++, circle(centre, layout.radius, layout.maxSpacing));
    for (int k = 0; k < kWarmupSteps; ++k) {
        stir();
        const double t = flow.time();
        flow.advance(kDt);
        tracker.advect(flow, t, kDt);
    }

    enum Phase { Strain, Fluid, Advect, Rk4, Spacing, GridBuild, Proximity, PhaseCount };
    std::array<double, PhaseCount> best;
    best.fill(INFINITY);
    double vertices = 0.0, substepsWanted = 0.0;
    const auto timed = [&best](Phase phase, auto&& work) {
        const double start = threadSeconds();
        work();
        const double seconds = threadSeconds() - start;
        best[phase] = std::min(best[phase], seconds);
        return seconds;
    };
    for (auto _ : state) {
        vertices += double(tracker.vertexCount());
        const double t = flow.time();
        std::vector<Contour> copy = tracker.contours();

        double strain = 0.0;
        double stepSeconds = timed(Strain, [&] { strain = tracker.strainInSpacings(flow, t, kDt); });
        substepsWanted += std::max(1.0, std::ceil(strain / settings.tracking.substepStrain));
        stir();
        stepSeconds += timed(Fluid, [&] { flow.advance(kDt); });
        stepSeconds += timed(Advect, [&] { tracker.advect(flow, t, kDt); });
        state.SetIterationTime(stepSeconds);

        timed(Rk4, [&] {
            for (Contour& c : copy) {
                c.previous = c.positions;
                for (std::size_t i = 0; i < c.positions.size(); ++i)
                    c.positions[i] = rungeKutta4(flow, c.previous[i], t, kDt);
            }
        });
        timed(Spacing, [&] { computeSpacing(copy, flow, t + kDt, settings.tracking, grid); });
        timed(GridBuild, [&] { grid.build(copy, settings.tracking.proximityRadius(), settings.tracking.proximityCell()); });
        timed(Proximity, [&] {
            double nearest = 0.0;
            for (std::size_t ci = 0; ci < copy.size(); ++ci)
                for (std::size_t i = 0; i < copy[ci].positions.size(); ++i)
                    nearest += std::min(1.0, grid.nearestOtherPart(ci, i));
            benchmark::DoNotOptimize(nearest);
        });
    }
    double contourBytes = 0.0;
    for (const Contour& c : tracker.contours())
        contourBytes += double(sizeof(Contour)) + double(c.positions.capacity() * sizeof(Vec2))
                      + double(c.previous.capacity() * sizeof(Vec2)) + double(c.spacing.capacity() * sizeof(double));
    const double steps = double(state.iterations());
    const auto ms = [](double seconds) { return 1e3 * seconds; };
    state.counters["vertices"] = vertices / steps;
    state.counters["substeps_wanted"] = substepsWanted / steps;
    state.counters["vertex_steps_per_s"] = benchmark::Counter(vertices, benchmark::Counter::kIsRate);
    state.counters["ms_strain"] = ms(best[Strain]);
    state.counters["ms_fluid"] = ms(best[Fluid]);
    state.counters["ms_advect"] = ms(best[Advect]);  // RK4 + spacing + refinement, the real one
    state.counters["ms_rk4"] = ms(best[Rk4]);
    state.counters["ms_spacing"] = ms(best[Spacing]);
    state.counters["ms_grid_build"] = ms(best[GridBuild]);
    state.counters["ms_proximity"] = ms(best[Proximity]);
    state.counters["ms_spacing_rest"] = ms(best[Spacing] - best[GridBuild] - best[Proximity]);  // κ, ω, exp, eq. 6
    state.counters["ms_refine"] = ms(best[Advect] - best[Rk4] - best[Spacing]);
    state.counters["contour_B_per_vertex"] = contourBytes / double(tracker.vertexCount());
}

// ---- Drop ---------------------------------------------------------------------------------------

// Drops of radius 0.05 into the stirred sheet, one per iteration at places spread over the canvas
// (a Weyl sequence), each drop pushing every vertex. "widening_ms" is what Simulation::separateLayers
// took of each drop (the phase clock's "pinches": drops cut nothing). A drop widens the layers near
// it, and every fourteenth all of them (Simulation::drop): after an untimed first drop, the 13
// timed ones hold one of those, so the means are what a long run of drops costs.
void dropBenchmark(benchmark::State& state, const Backend& backend, std::int64_t target)
{
    const Layout layout = layoutFor(target);
    const std::unique_ptr<Simulation> sim = makeOrSkip(state, backend, layout);
    if (!sim)
        return;
    int step = 0;
    for (; step < kStirSteps; ++step)
        sim->stylus(penAt(step), penAt(step + 1), kPenRadius, kDt), sim->step(kDt);
    for (const Vec2& centre : circleCentres(layout))
        sim->addRegion({circle(centre, layout.radius, layout.maxSpacing)});
    for (int k = 0; k < kWarmupSteps; ++k, ++step)
        sim->stylus(penAt(step), penAt(step + 1), kPenRadius, kDt), sim->step(kDt);
    int k = 0;
    const auto dropAt = [&] {
        ++k;
        sim->drop({0.2 + 0.6 * std::fmod(0.618034 * k, 1.0), 0.2 + 0.6 * std::fmod(0.414214 * k, 1.0)}, 0.05);
    };
    dropAt();
    sim->enablePhaseTiming();
    const double widening = sim->phaseSeconds()[std::size_t(Phase::Pinches)];
    double seconds = 0.0, vertices = 0.0;
    for (auto _ : state) {
        vertices += double(sim->vertexCount());
        const auto start = Clock::now();
        dropAt();
        seconds += std::chrono::duration<double>(Clock::now() - start).count();
    }
    const double drops = double(state.iterations());
    state.counters["vertices"] = vertices / drops;
    state.counters["widening_ms"] = 1e3 * (sim->phaseSeconds()[std::size_t(Phase::Pinches)] - widening) / drops;
    state.counters["drop_ms"] = 1e3 * seconds / drops;
}

// ---- Registration -------------------------------------------------------------------------------

struct Size {
    std::int64_t vertices;
    int naiveIterations, fullIterations, breakdownIterations;
};
constexpr Size kSizes[] = {{100'000, 200, 30, 10}, {1'000'000, 40, 10, 6}};

void registerAll()
{
    for (const Size& s : kSizes)
        benchmark::RegisterBenchmark(("NaiveRk4/" + std::to_string(s.vertices)).c_str(), naiveRk4Benchmark, s.vertices)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(s.naiveIterations)
            ->UseRealTime();
    for (const Size& s : kSizes)
        benchmark::RegisterBenchmark(("BareRk4Kernel/" + std::to_string(s.vertices)).c_str(), bareRk4KernelBenchmark,
                                     s.vertices)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(s.naiveIterations)
            ->UseRealTime();
    for (const Backend& b : backends())
        for (const Size& s : kSizes)
            benchmark::RegisterBenchmark(("FullStep/" + std::string(b.name) + "/" + std::to_string(s.vertices)).c_str(),
                                         fullStepBenchmark, b, s.vertices)
                ->Unit(benchmark::kMillisecond)
                ->Iterations(s.fullIterations)
                ->UseRealTime();
    for (const Size& s : kSizes)
        benchmark::RegisterBenchmark(("Breakdown/reference/" + std::to_string(s.vertices)).c_str(), breakdownBenchmark,
                                     s.vertices)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(s.breakdownIterations)
            ->UseManualTime();
    for (const Backend& b : backends())
        for (const Size& s : kSizes)
            benchmark::RegisterBenchmark(("Drop/" + std::string(b.name) + "/" + std::to_string(s.vertices)).c_str(),
                                         dropBenchmark, b, s.vertices)
                ->Unit(benchmark::kMillisecond)
                ->Iterations(13)
                ->UseRealTime();
}

} // namespace

int main(int argc, char** argv)
{
    registerAll();
    return vf::bench::runRegisteredBenchmarks(argc, argv);
}
