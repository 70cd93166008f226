// vf_session: the session benchmarks (docs/BENCHMARKS.md, "Sessions"). Plays a generated session (sessions/)
// or a scene file through one backend and reports, as one line of JSON, the wall time of its steps,
// vertex-steps per second, the peak vertex count, the process's peak resident memory and the
// share of each phase; or runs the naive scalar RK4 loop over the vertex counts another run saved.
// scripts/bench runs it once per session and backend, each in a process of its own so that peak
// memory is the run's own.
//
//   vf_session write NAME [--seed N] FILE.vfscene
//   vf_session run NAME|SCENE [--seed N] [--steps N] --backend reference|opencl [--counts FILE]
//                             [--check-topology K] [--area-correction]
//   vf_session naive NAME|SCENE [--seed N] --counts FILE
#include "model/SceneFile.h"
#include "model/SceneRunner.h"
#include "sessions/Sessions.h"
#include "sim/Crossings.h"
#include "sim/FluidFlow.h"
#include "sim/HeapPolicy.h"
#include "sim/ReferenceSimulation.h"
#include "sim/opencl/OpenClSimulation.h"

#include <QGuiApplication>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>

namespace {

using namespace vf;
using Clock = std::chrono::steady_clock;

[[noreturn]] void fail(const std::string& line)
{
    std::cerr << "vf_session: " << line << '\n';
    std::exit(2);
}

struct Arguments {
    std::string command, session, file, backend, counts;
    std::uint32_t seed = 1;
    std::int64_t steps = -1, checkTopology = 0;
    bool areaCorrection = false;
};

Arguments parse(int argc, char** argv)
{
    Arguments a;
    if (argc < 3)
        fail("usage: vf_session write|run|naive NAME|SCENE [options] (see benchmarks/vf_session.cpp)");
    a.command = argv[1];
    a.session = argv[2];
    for (int i = 3; i < argc; ++i) {
        const std::string key = argv[i];
        const auto value = [&] {
            if (i + 1 >= argc)
                fail(key + " needs a value");
            return std::string(argv[++i]);
        };
        if (key == "--seed")
            a.seed = std::uint32_t(std::stoul(value()));
        else if (key == "--steps")
            a.steps = std::stoll(value());
        else if (key == "--backend")
            a.backend = value();
        else if (key == "--counts")
            a.counts = value();
        else if (key == "--check-topology")
            a.checkTopology = std::stoll(value());
        else if (key == "--area-correction")
            a.areaCorrection = true;
        else if (a.command == "write" && a.file.empty())
            a.file = key;
        else
            fail("unknown argument " + key);
    }
    return a;
}

model::Scene sceneOf(const Arguments& a)
{
    std::optional<model::Scene> scene = sessions::byName(a.session, a.seed);
    if (!scene) {
        const model::SceneReadResult read = model::readSceneFile(QString::fromStdString(a.session));
        if (!read.ok())
            fail(read.error.toStdString());
        scene = read.scene;
    }
    if (a.steps >= 0)
        scene->time.steps = a.steps;
    scene->tracking.areaCorrection = scene->tracking.areaCorrection || a.areaCorrection;
    return *scene;
}

long peakResidentBytes()
{
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmHWM:", 0) == 0)
            return 1024 * std::stol(line.substr(6));
    return -1;
}

// The first step at which contours cross that did not cross when they appeared, or -1.
std::int64_t checkTopology(const sim::Simulation& simulation, std::map<std::size_t, bool>& known, std::int64_t step,
                           std::int64_t firstCrossing)
{
    if (firstCrossing >= 0)
        return firstCrossing;
    const std::vector<sim::Contour> contours = simulation.contours();
    std::vector<const sim::Polygon*> polygons;
    for (const sim::Contour& c : contours)
        polygons.push_back(&c.positions);
    for (const sim::EdgeCrossing& x : sim::findCrossings(polygons)) {
        const bool appeared = !known.count(x.polygonB);
        if (!(x.polygonA != x.polygonB && appeared))
            return step;
    }
    for (std::size_t c = 0; c < contours.size(); ++c)
        known[c] = true;
    return -1;
}

// The largest relative difference, over regions, between a region's area (its contours' signed
// areas summed) and what it should be (their area targets: the area each had when it appeared,
// grown by the drops that landed inside it).
double worstAreaError(const sim::Simulation& simulation)
{
    std::map<int, std::pair<double, double>> regions;  // area, target
    for (const sim::Contour& c : simulation.contours()) {
        regions[c.region].first += sim::signedArea(c.positions);
        regions[c.region].second += c.targetArea;
    }
    double worst = 0.0;
    for (const auto& [region, area] : regions)
        worst = std::max(worst, std::abs(area.first - area.second) / std::abs(area.second));
    return worst;
}

int run(const Arguments& a)
{
    const model::Scene scene = sceneOf(a);
    model::SceneRunner runner(scene, [&](const sim::SimulationSettings& s) {
        return sim::opencl::makeSimulation(s, a.backend, std::nullopt);
    });
    auto& simulation = const_cast<sim::Simulation&>(runner.simulation());
    simulation.enablePhaseTiming();
    std::ofstream counts;
    if (!a.counts.empty())
        counts.open(a.counts);
    double seconds = 0.0;
    std::int64_t vertexSteps = 0, substeps = 0, firstCrossing = -1, pinchesCut = 0;
    std::size_t peak = simulation.vertexCount();
    std::map<std::size_t, bool> known;
    bool limit = false;
    std::int64_t step = 0;
    for (; step < scene.time.steps && !limit; ++step) {
        const auto start = Clock::now();
        const sim::StepReport report = runner.step(scene.time.dt);
        seconds += std::chrono::duration<double>(Clock::now() - start).count();
        limit = report.vertexLimitReached;
        substeps += report.substeps;
        pinchesCut += std::int64_t(report.pinchesCut);
        vertexSteps += std::int64_t(simulation.vertexCount());
        peak = std::max(peak, simulation.vertexCount());
        if (counts.is_open())
            counts << simulation.vertexCount() << '\n';
        if (a.checkTopology > 0 && (step + 1) % a.checkTopology == 0)
            firstCrossing = checkTopology(simulation, known, step + 1, firstCrossing);
    }
    // The session's own peak, before the area check below copies the contours out.
    const long peakRss = peakResidentBytes();
    double phaseTotal = 0.0;
    for (double s : simulation.phaseSeconds())
        phaseTotal += s;
    std::ostringstream phases;
    for (std::size_t p = 0; p < sim::phaseCount; ++p)
        phases << (p ? ", " : "") << '"' << sim::phaseNames[p] << "\": " << simulation.phaseSeconds()[p];
    std::printf("{\"session\": \"%s\", \"seed\": %u, \"backend\": \"%s\", \"device\": \"%s\", \"area_correction\": %s, "
                "\"steps\": %lld, \"substeps\": %lld, \"pinches_cut\": %lld, "
                "\"seconds\": %.4f, \"vertex_steps\": %lld, \"vertex_steps_per_second\": %.1f, \"peak_vertices\": %zu, "
                "\"end_vertices\": %zu, \"peak_rss_bytes\": %ld, \"limit_reached\": %s, \"phase_seconds\": {%s}, "
                "\"phases_total\": %.4f, \"first_crossing_step\": %lld, \"worst_area_error\": %.3g}\n",
                a.session.c_str(), a.seed, simulation.backendName().c_str(), simulation.description().c_str(),
                simulation.settings().tracking.areaCorrection ? "true" : "false", (long long)step, (long long)substeps, (long long)pinchesCut,
                seconds, (long long)vertexSteps, double(vertexSteps) / seconds, peak, simulation.vertexCount(),
                peakRss, limit ? "true" : "false", phases.str().c_str(), phaseTotal,
                (long long)firstCrossing, worstAreaError(simulation));
    return 0;
}

// The naive loop: the scene's fluid alone (its strokes, no ink), and at each step classic RK4 in
// double through it over as many points as the other run had vertices after that step, with no
// refinement: what the ratio of a backend to "naive" compares against.
int naive(const Arguments& a)
{
    model::Scene scene = sceneOf(a);
    scene.regions.clear();
    std::erase_if(scene.strokes, [](const model::Stroke& s) { return std::holds_alternative<model::DropStroke>(s); });
    std::vector<std::size_t> counts;
    std::ifstream in(a.counts);
    for (std::size_t n = 0; in >> n;)
        counts.push_back(n);
    if (counts.empty())
        fail(a.counts + ": no vertex counts");
    std::size_t most = *std::max_element(counts.begin(), counts.end());
    std::vector<sim::Vec2> points(most);
    std::mt19937 engine(a.seed);
    std::uniform_real_distribution<double> x(0.0, scene.canvas.width), y(0.0, scene.canvas.height);
    for (sim::Vec2& p : points)
        p = {x(engine), y(engine)};
    const sim::ReferenceSimulation* fluid = nullptr;
    model::SceneRunner runner(scene, [&](const sim::SimulationSettings& s) {
        auto simulation = std::make_unique<sim::ReferenceSimulation>(s);
        fluid = simulation.get();
        return simulation;
    });
    double seconds = 0.0;
    std::int64_t vertexSteps = 0;
    const double dt = scene.time.dt;
    for (std::size_t step = 0; step < counts.size(); ++step) {
        runner.step(dt);
        const sim::Flow& flow = fluid->flow();
        const double t = flow.time() - dt;
        const auto start = Clock::now();
        for (std::size_t i = 0; i < counts[step]; ++i)
            points[i] = sim::rungeKutta4(flow, points[i], t, dt);
        seconds += std::chrono::duration<double>(Clock::now() - start).count();
        vertexSteps += std::int64_t(counts[step]);
    }
    std::printf("{\"session\": \"%s\", \"seed\": %u, \"backend\": \"naive\", \"steps\": %zu, \"seconds\": %.4f, "
                "\"vertex_steps\": %lld, \"vertex_steps_per_second\": %.1f}\n",
                a.session.c_str(), a.seed, counts.size(), seconds, (long long)vertexSteps, double(vertexSteps) / seconds);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    vf::sim::keepLargeBlocksMapped();
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");  // the shape-design letters need fonts, not a display
    QGuiApplication app(argc, argv);
    const Arguments a = parse(argc, argv);
    if (a.command == "write") {
        const std::optional<model::Scene> scene = sessions::byName(a.session, a.seed);
        if (!scene)
            fail("no session called " + a.session);
        const QString error = model::writeSceneFile(*scene, QString::fromStdString(a.file));
        if (!error.isEmpty())
            fail(error.toStdString());
        return 0;
    }
    if (a.command == "run")
        return run(a);
    if (a.command == "naive")
        return naive(a);
    fail("unknown command " + a.command);
}
