// window_session: how the app keeps up as the ink grows, through the real main window. It plays
// SCENE (a generated marbling session: `vf_session write marbling --seed N FILE`) and, each time
// the simulation passes a mark of vertices, measures for S seconds the simulation's steps per
// second and the canvas's paints per second while it plays, then S seconds more while the view is
// panned with the middle button, 60 moves a second (looking around the sheet). Steps come from the
// frames the worker hands over, paints from the canvas's own paint events.
// A benchmark, run on demand; figures and the command in docs/BENCHMARKS.md ("The app").
//
//   window_session SCENE [--marks 100000,500000,1000000] [--seconds S] [--limit SECONDS]
//
// Stops after the last mark, or at the limit (default 1200 s) with the marks it reached.
#include "app/Canvas.h"
#include "app/MainWindow.h"
#include "sim/HeapPolicy.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QTimer>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

// Counts the paint events a widget gets.
class PaintCounter : public QObject {
public:
    explicit PaintCounter(QWidget& widget) { widget.installEventFilter(this); }
    qint64 paints = 0;

protected:
    bool eventFilter(QObject*, QEvent* event) override
    {
        if (event->type() == QEvent::Paint)
            ++paints;
        return false;
    }
};

// Where a measurement started: the wall clock, the steps of the newest frame, the paints so far.
struct Mark {
    qint64 ms = 0;
    std::int64_t steps = 0;
    qint64 paints = 0;
    std::size_t vertices = 0;
};

void sendMouse(QWidget& widget, QEvent::Type type, QPointF at, Qt::MouseButtons held)
{
    QMouseEvent event(type, at, widget.mapToGlobal(at), Qt::MiddleButton, held, Qt::NoModifier);
    QCoreApplication::sendEvent(&widget, &event);
}

} // namespace

int main(int argc, char** argv)
{
    vf::sim::keepLargeBlocksMapped();
    QApplication app(argc, argv);
    QStringList args = QApplication::arguments().mid(1);
    if (args.isEmpty()) {
        std::fprintf(stderr, "usage: window_session SCENE [--marks N,N,...] [--seconds S] [--limit SECONDS]\n");
        return 2;
    }
    const QString scene = args.takeFirst();
    std::vector<std::size_t> marks{100'000, 500'000, 1'000'000};
    double seconds = 5.0, limit = 1200.0;
    for (qsizetype i = 0; i + 1 < args.size(); i += 2) {
        if (args[i] == QLatin1String("--marks")) {
            marks.clear();
            for (const QString& m : args[i + 1].split(u','))
                marks.push_back(m.toULongLong());
        } else if (args[i] == QLatin1String("--seconds")) {
            seconds = args[i + 1].toDouble();
        } else if (args[i] == QLatin1String("--limit")) {
            limit = args[i + 1].toDouble();
        }
    }

    vf::app::MainWindow window;
    window.setReport([](const QString& title, const QString& text) {
        std::fprintf(stderr, "%s: %s\n", qPrintable(title), qPrintable(text));
    });
    window.resize(1280, 800);
    window.show();
    if (!window.openFile(scene))
        return 2;
    window.simulation().setPlaying(true);
    QWidget& canvas = window.canvas();
    PaintCounter counter(canvas);

    QElapsedTimer clock;
    clock.start();
    std::int64_t steps = 0;
    std::size_t vertices = 0;
    std::string backend;
    QObject::connect(&window.simulation(), &vf::app::SimulationController::frameArrived, [&] {
        const auto frame = window.simulation().frame();
        steps = frame->steps;
        vertices = frame->vertexCount;
        backend = frame->backend;
    });
    const auto now = [&] { return Mark{clock.elapsed(), steps, counter.paints, vertices}; };
    const auto rates = [&](const Mark& from, const Mark& to) {
        const double s = double(to.ms - from.ms) / 1000.0;
        return std::pair{double(to.steps - from.steps) / s, double(to.paints - from.paints) / s};
    };

    std::printf("mark       | vertices          | playing: steps/s  fps | panning: steps/s  fps\n");
    std::fflush(stdout);
    enum class Phase { Waiting, Playing, Panning } phase = Phase::Waiting;
    std::size_t next = 0;
    Mark start, panStart;
    int moves = 0;
    const QPointF middle(canvas.width() / 2.0, canvas.height() / 2.0);
    QTimer tick;
    tick.setInterval(16);
    QObject::connect(&tick, &QTimer::timeout, [&] {
        if (clock.elapsed() > qint64(limit * 1000) || next == marks.size()) {
            window.document().undoStack().setClean();
            app.quit();
            return;
        }
        switch (phase) {
        case Phase::Waiting:
            if (vertices >= marks[next]) {
                start = now();
                phase = Phase::Playing;
            }
            return;
        case Phase::Playing:
            if (clock.elapsed() - start.ms >= qint64(seconds * 1000)) {
                panStart = now();
                moves = 0;
                sendMouse(canvas, QEvent::MouseButtonPress, middle, Qt::MiddleButton);
                phase = Phase::Panning;
            }
            return;
        case Phase::Panning: {
            // Round and round a circle of 80 pixels, so the view comes back where it was.
            const double angle = 2.0 * M_PI * ++moves / 60.0;
            const QPointF at = middle + 80.0 * QPointF(std::cos(angle) - 1.0, std::sin(angle));
            sendMouse(canvas, QEvent::MouseMove, at, Qt::MiddleButton);
            if (clock.elapsed() - panStart.ms < qint64(seconds * 1000))
                return;
            sendMouse(canvas, QEvent::MouseButtonRelease, at, Qt::NoButton);
            const Mark end = now();
            const auto [playSteps, playFps] = rates(start, panStart);
            const auto [panSteps, panFps] = rates(panStart, end);
            std::printf("%-10zu | %7zu -> %7zu | %15.1f %5.1f | %15.1f %5.1f\n", marks[next], start.vertices,
                        end.vertices, playSteps, playFps, panSteps, panFps);
            std::fflush(stdout);
            ++next;
            phase = Phase::Waiting;
            return;
        }
        }
    });
    tick.start();
    app.exec();
    std::printf("%s, the canvas %d x %d; %zu of %zu marks reached in %.0f s\n", backend.c_str(), canvas.width(),
                canvas.height(), next, marks.size(), double(clock.elapsed()) / 1000.0);
    return next == marks.size() ? 0 : 1;
}
