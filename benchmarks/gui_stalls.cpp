// gui_stalls: how long the GUI thread is ever held up while the app plays a big scene and the user
// drops ink, undoes and redoes — the issue's "no GUI-thread call blocks longer than a frame at
// 100k vertices". A zero-interval timer on the GUI thread notes the gap between its turns; every
// gap is time the event loop spent on something else (painting, taking frames, the document).
// Each gap is also measured in the GUI thread's own CPU time, which is the work it did (a busy
// machine also takes the CPU away from it, which shows in wall time only).
// A benchmark, run on demand; figures and the command in docs/BENCHMARKS.md ("The app").
//
//   gui_stalls SCENE [--vertices N] [--seconds S]
//
// It plays SCENE until the simulation has N vertices (default 100,000), then for S seconds
// (default 10) drops ink, undoes and redoes in turn every 400 ms, and prints the longest gaps.
#include "app/MainWindow.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <vector>

namespace {

qint64 threadCpuMicroseconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return qint64(t.tv_sec) * 1'000'000 + t.tv_nsec / 1000;
}

// The probe turns about every 10 µs, so storing every gap would grow a vector by megabytes, and
// its reallocation on this very thread would show up as a stall. Gaps under 0.1 ms are only
// counted; the others are kept in reserved space.
struct Gaps {
    std::size_t shortOnes = 0;
    std::vector<qint64> longOnes;  // µs

    Gaps() { longOnes.reserve(1 << 20); }
    void add(qint64 us)
    {
        if (us < 100 || longOnes.size() == longOnes.capacity())
            ++shortOnes;
        else
            longOnes.push_back(us);
    }
    void print(const char* what)
    {
        std::sort(longOnes.begin(), longOnes.end());
        const std::size_t n = shortOnes + longOnes.size();
        auto at = [&](double q) {
            const std::size_t i = std::size_t(q * double(n - 1));
            return i < shortOnes ? 0.0 : double(longOnes[i - shortOnes]) / 1000.0;
        };
        const auto overFrame = std::count_if(longOnes.begin(), longOnes.end(), [](qint64 us) { return us > 16'667; });
        std::printf("  %s: median %.1f ms, 99.9%% %.1f ms, longest %.1f ms; %td over 16.7 ms (0.0 means under 0.1)\n",
                    what, at(0.5), at(0.999), longOnes.empty() ? 0.0 : double(longOnes.back()) / 1000.0, overFrame);
    }
};

} // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    QStringList args = QApplication::arguments().mid(1);
    if (args.isEmpty()) {
        std::fprintf(stderr, "usage: gui_stalls SCENE [--vertices N] [--seconds S]\n");
        return 2;
    }
    const QString scene = args.takeFirst();
    std::size_t targetVertices = 100'000;
    double seconds = 10.0;
    for (qsizetype i = 0; i + 1 < args.size(); i += 2) {
        if (args[i] == QLatin1String("--vertices"))
            targetVertices = args[i + 1].toULongLong();
        else if (args[i] == QLatin1String("--seconds"))
            seconds = args[i + 1].toDouble();
    }

    vf::app::MainWindow window;
    window.setReport([](const QString& title, const QString& text) {
        std::fprintf(stderr, "%s: %s\n", qPrintable(title), qPrintable(text));
    });
    window.show();
    if (!window.openFile(scene))
        return 2;
    window.simulation().setPlaying(true);

    QElapsedTimer clock;
    clock.start();
    Gaps gaps, cpuGaps;  // between turns of the probe, while measuring
    qint64 last = clock.nsecsElapsed();
    qint64 lastCpu = threadCpuMicroseconds();
    bool measuring = false;
    qint64 measureStart = 0;
    int actions = 0, framesShown = 0;

    QTimer probe;
    probe.setInterval(0);
    QObject::connect(&probe, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        const qint64 cpu = threadCpuMicroseconds();
        if (measuring) {
            gaps.add((now - last) / 1000);
            cpuGaps.add(cpu - lastCpu);
        }
        last = now;
        lastCpu = cpu;
    });
    probe.start();
    QObject::connect(&window.simulation(), &vf::app::SimulationController::frameArrived, [&] {
        const auto frame = window.simulation().frame();
        if (measuring) {
            ++framesShown;
            return;
        }
        if (frame->vertexCount >= targetVertices || clock.elapsed() > 120'000) {
            std::printf("measuring at %zu vertices, %s\n", frame->vertexCount, frame->backend.c_str());
            measuring = true;
            measureStart = clock.elapsed();
        }
    });
    QTimer user;
    user.setInterval(400);
    QObject::connect(&user, &QTimer::timeout, [&] {
        if (!measuring)
            return;
        switch (actions++ % 3) {
        case 0:
            window.document().drop({0.2 + 0.05 * (actions % 12), 0.8}, 0.03, Qt::darkRed);
            break;
        case 1:
            window.document().undoStack().undo();
            break;
        default:
            window.document().undoStack().redo();
        }
        if (clock.elapsed() - measureStart > qint64(seconds * 1000)) {
            window.document().undoStack().setClean();
            app.quit();
        }
    });
    user.start();
    app.exec();

    std::printf("%d user actions, %d frames shown in %.1f s; gaps between turns of the GUI thread's event loop:\n",
                actions, framesShown, seconds);
    gaps.print("wall time");
    cpuGaps.print("GUI-thread CPU time");
    return 0;
}
