// vf_snapshot_bench: what the app's undo history pays per entry. Simulation::snapshot() and
// restore() at about 100k and 1M vertices on every backend, in the scene of vf_bench (BenchScene.h)
// with the pen's next move given but not yet stepped. Each iteration takes a snapshot and restores
// it into the same simulation, as undo and redo do; both are timed in wall time (the OpenCL
// backend's are blocking transfers). docs/BENCHMARKS.md has the figures, the machine and the
// command. A benchmark, run on demand, never a test.
#include "BenchScene.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <string>

namespace {

using namespace vf;
using namespace vf::bench;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

void snapshotRestoreBenchmark(benchmark::State& state, const Backend& backend, std::int64_t target)
{
    const Layout layout = layoutFor(target);
    std::unique_ptr<sim::Simulation> simulation;
    try {
        simulation = backend.make(settingsFor(layout));
    } catch (const sim::opencl::DeviceError& e) {
        state.SkipWithError((std::string("OpenCL backend skipped: ") + e.what()).c_str());
        return;
    }
    int step = 0;
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

struct Size {
    std::int64_t vertices;
    int iterations;
};
constexpr Size kSizes[] = {{100'000, 20}, {1'000'000, 5}};

} // namespace

int main(int argc, char** argv)
{
    for (const Backend& b : backends())
        for (const Size& s : kSizes)
            benchmark::RegisterBenchmark(("SnapshotRestore/" + std::string(b.name) + "/" + std::to_string(s.vertices))
                                             .c_str(),
                                         snapshotRestoreBenchmark, b, s.vertices)
                ->Unit(benchmark::kMillisecond)
                ->Iterations(s.iterations)
                ->UseManualTime();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
