// project_sizes PROJECT: how big a project's states are in each layout the project format has had
// (docs/project-format.md: version 1 plain and stored, version 2 packed from the value before,
// version 3 packed on the line through the two before; 2 and 3 deflated at level 1), and how long
// readProjectFile takes on the file as it is (5 runs). The figures of docs/BENCHMARKS.md,
// "Project files".
#include "model/ProjectFile.h"
#include "model/StateBlob.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
#include <set>

using namespace vf;

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: project_sizes PROJECT.vfproj\n");
        return 2;
    }
    const QString path = QString::fromLocal8Bit(argv[1]);
    std::printf("readProjectFile:");
    model::ProjectReadResult read;
    for (int run = 0; run < 5; ++run) {
        QElapsedTimer timer;
        timer.start();
        read = model::readProjectFile(path);
        std::printf(" %lld", timer.elapsed());
    }
    std::printf(" ms\n");
    if (!read.ok()) {
        std::fprintf(stderr, "%s\n", qPrintable(read.error));
        return 1;
    }
    std::set<const sim::SimulationState*> seen;
    std::vector<const sim::SimulationState*> states;
    const auto add = [&](const std::shared_ptr<const sim::SimulationState>& s) {
        if (s && seen.insert(s.get()).second)
            states.push_back(s.get());
    };
    for (const model::HistoryEntry& entry : read.project.history) {
        add(entry.before);
        add(entry.after);
    }
    add(read.project.origin);
    // The current state, unless the file shares it with one of those.
    if (std::none_of(states.begin(), states.end(), [&](const sim::SimulationState* s) { return *s == read.project.state; }))
        states.push_back(&read.project.state);
    std::size_t vertices = 0;
    for (const sim::SimulationState* s : states)
        for (const sim::Contour& c : s->contours)
            vertices += c.positions.size();
    const model::StateEncoding layouts[] = {model::StateEncoding::Plain, model::StateEncoding::Packed,
                                            model::StateEncoding::PackedLinear};
    std::printf("%zu states, %zu vertices\n", states.size(), vertices);
    for (int version = 1; version <= 3; ++version) {
        qint64 bytes = 0;
        for (const sim::SimulationState* s : states)
            bytes += qCompress(model::encodeState(*s, layouts[version - 1]), version == 1 ? 0 : 1).size();
        std::printf("version %d: %lld bytes, %.2f per vertex\n", version, bytes, double(bytes) / double(vertices));
    }
}
