// vf_snapshot_bench: what the app's undo history pays per entry, and the worker per frame, at
// about 100k and 1M vertices on every backend, in the scene of vf_bench (BenchScene.h) with the
// pen's next move given but not yet stepped.
//   SnapshotRestore: each iteration takes Simulation::snapshot() and restores it into the same
//     simulation, as undo and redo do; both are timed in wall time (the OpenCL backend's are
//     blocking transfers).
//   FrameGeometry: what a frame's geometry adds to a step, in wall time: a step alone, a step
//     after the blocking regions() (every field read back), and a step between requestRegions()
//     and takeRegions(), the worker's way while playing; also request and take back to back.
// docs/BENCHMARKS.md ("Snapshots and frames") has the figures, the machine and the command. A
// benchmark, run on demand, never a test.
#include "BenchMain.h"
#include "BenchScene.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <utility>

namespace {

using namespace vf;
using namespace vf::bench;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The benchmark scene, settled, with the pen's next move given; null (and the benchmark skipped)
// without an OpenCL device for that backend.
std::unique_ptr<sim::Simulation> settledScene(benchmark::State& state, const Backend& backend, std::int64_t target,
                                              int& step)
{
    const Layout layout = layoutFor(target);
    std::unique_ptr<sim::Simulation> simulation;
    try {
        simulation = backend.make(settingsFor(layout));
    } catch (const sim::opencl::DeviceError& e) {
        state.SkipWithError((std::string("OpenCL backend skipped: ") + e.what()).c_str());
        return nullptr;
    }
    const auto stir = [&] { simulation->stylus(penAt(step), penAt(step + 1), kPenRadius, kDt); ++step; };
    for (int k = 0; k < kStirSteps; ++k) {
        stir();
        simulation->step(kDt);
    }
    for (const sim::Vec2& centre : circleCentres(layout))
        simulation->addRegion({sim::circle(centre, layout.radius, layout.maxSpacing)});
    for (int k = 0; k < kWarmupSteps; ++k) {
        stir();
        simulation->step(kDt);
    }
    stir();  // pending: a snapshot carries it
    return simulation;
}

void snapshotRestoreBenchmark(benchmark::State& state, const Backend& backend, std::int64_t target)
{
    int step = 0;
    const std::unique_ptr<sim::Simulation> simulation = settledScene(state, backend, target, step);
    if (!simulation)
        return;
    double snapshotSeconds = 0.0, restoreSeconds = 0.0, bytes = 0.0;
    for (auto _ : state) {
        auto start = Clock::now();
        const sim::SimulationState snapshot = simulation->snapshot();
        const double taken = secondsSince(start);
        start = Clock::now();
        simulation->restore(snapshot);
        const double restored = secondsSince(start);
        snapshotSeconds += taken;
        restoreSeconds += restored;
        bytes = double(snapshot.bytes());
        state.SetIterationTime(taken + restored);
    }
    const double iterations = double(state.iterations());
    const double vertices = double(simulation->vertexCount());
    state.counters["vertices"] = vertices;
    state.counters["ms_snapshot"] = 1e3 * snapshotSeconds / iterations;
    state.counters["ms_restore"] = 1e3 * restoreSeconds / iterations;
    state.counters["MB_per_snapshot"] = bytes / 1e6;
    state.counters["B_per_vertex"] = bytes / vertices;
}

void frameGeometryBenchmark(benchmark::State& state, const Backend& backend, std::int64_t target)
{
    int step = 0;
    const std::unique_ptr<sim::Simulation> simulation = settledScene(state, backend, target, step);
    if (!simulation)
        return;
    const auto stepOn = [&] {
        simulation->step(kDt);
        simulation->stylus(penAt(step), penAt(step + 1), kPenRadius, kDt);
        ++step;
    };
    double backToBack = 0.0, stepAlone = 0.0, withBlocking = 0.0, withCopy = 0.0;
    for (auto _ : state) {
        auto start = Clock::now();
        simulation->requestRegions();
        benchmark::DoNotOptimize(simulation->takeRegions(true));
        const double copied = secondsSince(start);
        backToBack += copied;
        state.SetIterationTime(copied);

        start = Clock::now();
        stepOn();
        stepAlone += secondsSince(start);

        start = Clock::now();
        benchmark::DoNotOptimize(simulation->regions());
        stepOn();
        withBlocking += secondsSince(start);

        start = Clock::now();
        simulation->requestRegions();
        stepOn();
        benchmark::DoNotOptimize(simulation->takeRegions(true));
        withCopy += secondsSince(start);
    }
    const double iterations = double(state.iterations());
    state.counters["vertices"] = double(simulation->vertexCount());
    state.counters["ms_copy_back_to_back"] = 1e3 * backToBack / iterations;
    state.counters["ms_step"] = 1e3 * stepAlone / iterations;
    state.counters["ms_step_and_blocking_regions"] = 1e3 * withBlocking / iterations;
    state.counters["ms_step_and_copy"] = 1e3 * withCopy / iterations;
}

struct Size {
    std::int64_t vertices;
    int iterations;
};
constexpr Size kSizes[] = {{100'000, 20}, {1'000'000, 8}};

} // namespace

int main(int argc, char** argv)
{
    using Function = void (*)(benchmark::State&, const Backend&, std::int64_t);
    for (const auto& [family, function] : {std::pair<const char*, Function>{"SnapshotRestore/", snapshotRestoreBenchmark},
                                           std::pair<const char*, Function>{"FrameGeometry/", frameGeometryBenchmark}})
        for (const Backend& b : backends())
            for (const Size& s : kSizes)
                benchmark::RegisterBenchmark((family + std::string(b.name) + "/" + std::to_string(s.vertices)).c_str(),
                                             function, b, s.vertices)
                    ->Unit(benchmark::kMillisecond)
                    ->Iterations(s.iterations)
                    ->UseManualTime();
    return vf::bench::runRegisteredBenchmarks(argc, argv);
}
