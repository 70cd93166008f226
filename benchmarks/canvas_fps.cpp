// canvas_fps: display frames per second of the canvas widget (app/Canvas) on a marbled scene of
// about 200k and 1M vertices at 1280×800, (a) when every displayed frame is a new Frame, as while
// the simulation plays, and (b) when only repainting; and where a new frame's time goes: the level
// of detail (decimation), assembling the paths, filling them. A benchmark, run on demand; the
// figures, the machine and the command are in docs/BENCHMARKS.md ("The app").
//
//   canvas_fps [--seconds S] [--sizes N,N,...]
//
// Run it on any Qt platform: QT_QPA_PLATFORM=offscreen, or under X (xvfb-run -a), where each frame
// also goes to the X server.
//
// The scene: bull's-eye drops on a 5 × 4 lattice, 12 concentric rings each, laid in 12 rounds (one
// ring at every site per round, 4 colours in turn). As in the engine, every drop is a region of one
// contour (a later drop inside it makes it a ring) and regions are painted in the order they were
// dropped: 240 regions. Then everything is carried by an area-preserving map that
// keeps contours from crossing, like a marbler's stylus: three Gaussian twists (each rotates the
// plane about its centre by an angle that falls off with the distance) and a sinusoidal comb
// shear. Contours are refined as the engine does (eq. 2): an edge longer than the spacing gets the
// image of its parameter midpoint. The spacing is chosen so the scene has about N vertices. The
// new frames of (a) are the same scene with the map's phase advanced a little each frame.
#include "app/Canvas.h"
#include "app/ContourLod.h"
#include "app/RegionPaths.h"

#include <glm/geometric.hpp>

#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <numbers>
#include <vector>

namespace {

using namespace vf;
using sim::Vec2;

constexpr int kRings = 12;
constexpr int kLatticeX = 5, kLatticeY = 4;
constexpr double kOuterRadius = 0.085;
constexpr int kDistinctFrames = 6;  // new frames cycle through these, so no repaint finds a cache
const QSize kWidgetSize(1280, 800);

struct Twist {
    Vec2 centre;
    double angle;  // radians at the centre
    double sigma;  // canvas units
};

const std::array<Twist, 3> kTwists{{{{0.3, 0.35}, 5.0, 0.18}, {{0.7, 0.6}, -6.0, 0.2}, {{0.5, 0.5}, 2.5, 0.35}}};

Vec2 marble(Vec2 p, double phase)
{
    for (const Twist& t : kTwists) {
        const Vec2 d = p - t.centre;
        const double a = (t.angle + phase) * std::exp(-glm::dot(d, d) / (t.sigma * t.sigma));
        p = t.centre + Vec2(d.x * std::cos(a) - d.y * std::sin(a), d.x * std::sin(a) + d.y * std::cos(a));
    }
    p.x += 0.02 * std::sin(2 * std::numbers::pi * 4 * p.y + phase);  // the comb: shear along x...
    p.y += 0.015 * std::sin(2 * std::numbers::pi * 3 * p.x);           // ...then along y
    return p;
}

// One ring, refined so no edge of its image is longer than `spacing`.
sim::Polygon marbledRing(Vec2 centre, double radius, double spacing, double phase)
{
    const auto at = [&](double t) {
        return marble(centre + radius * Vec2(std::cos(t), std::sin(t)), phase);
    };
    const int start = std::max(8, int(2 * std::numbers::pi * radius / spacing));
    sim::Polygon ring;
    std::function<void(double, Vec2, double, Vec2, int)> refine = [&](double ta, Vec2 a, double tb, Vec2 b, int depth) {
        if (depth == 0 || glm::distance(a, b) <= spacing) {
            ring.push_back(a);
            return;
        }
        const double tm = 0.5 * (ta + tb);
        const Vec2 m = at(tm);
        refine(ta, a, tm, m, depth - 1);
        refine(tm, m, tb, b, depth - 1);
    };
    Vec2 previous = at(0.0);
    for (int i = 0; i < start; ++i) {
        const double ta = 2 * std::numbers::pi * i / start, tb = 2 * std::numbers::pi * (i + 1) / start;
        const Vec2 next = at(tb);
        refine(ta, previous, tb, next, 16);
        previous = next;
    }
    return ring;
}

std::shared_ptr<const model::Frame> marbledFrame(double spacing, double phase)
{
    auto frame = std::make_shared<model::Frame>();
    for (int k = 0; k < kRings; ++k)
        for (int j = 0; j < kLatticeY; ++j)
            for (int i = 0; i < kLatticeX; ++i) {
                const Vec2 centre((i + 0.5) / kLatticeX, (j + 0.5) / kLatticeY);
                frame->regions.push_back({marbledRing(centre, kOuterRadius * (kRings - k) / kRings, spacing, phase)});
            }
    for (const auto& region : frame->regions)
        for (const sim::Polygon& contour : region)
            frame->vertexCount += contour.size();
    return frame;
}

// The scene at about `vertices` vertices: the count goes as 1 / spacing, so two tries suffice.
double spacingFor(std::size_t vertices)
{
    double spacing = 0.002;
    for (int attempt = 0; attempt < 2; ++attempt)
        spacing *= double(marbledFrame(spacing, 0.0)->vertexCount) / double(vertices);
    return spacing;
}

model::RegionTable looks()
{
    const std::array<QColor, 4> palette{QColor("#1d3557"), QColor("#e63946"), QColor("#f1faee"), QColor("#457b9d")};
    model::RegionTable table;
    for (int k = 0; k < kRings; ++k)
        for (int site = 0; site < kLatticeX * kLatticeY; ++site) {
            const int index = int(table.size());
            table.push_back({QStringLiteral("drop %1").arg(index), palette[k % palette.size()], true, index});
        }
    return table;
}

// CPU time of this thread, ms: what the work costs whatever else the (shared) machine runs.
double threadMilliseconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

struct Rate {
    double fps;       // frames per wall-clock second
    double cpuMs;     // GUI-thread CPU time per frame
    int canvasFps;    // what the canvas's own counter said at the end
};

// Repaints the canvas (synchronously, through the platform's backing store and flush) for at
// least `seconds`, calling `before` ahead of each paint.
Rate paintRate(app::Canvas& canvas, double seconds, const std::function<void(int)>& before)
{
    QElapsedTimer clock;
    clock.start();
    const double cpuStart = threadMilliseconds();
    int frames = 0;
    while (clock.nsecsElapsed() < seconds * 1e9) {
        before(frames);
        canvas.repaint();
        ++frames;
    }
    const Rate rate{frames / (clock.nsecsElapsed() * 1e-9), (threadMilliseconds() - cpuStart) / frames, canvas.displayFps()};
    QCoreApplication::processEvents();
    return rate;
}

// GUI-thread CPU milliseconds per call of `work`, the mean over at least `seconds` of it.
double millisecondsPer(double seconds, const std::function<void()>& work)
{
    const double start = threadMilliseconds();
    int calls = 0;
    while (calls == 0 || threadMilliseconds() - start < seconds * 1e3) {
        work();
        ++calls;
    }
    return (threadMilliseconds() - start) / calls;
}

// Where a new frame's time goes, on the canvas's own view, painted into an image of its size.
void breakdown(const model::Frame& frame, const app::PixelMapping& toDevice, const model::RegionTable& table, double seconds)
{
    const QRectF visible(QPointF(-1, -1), QSizeF(kWidgetSize) + QSizeF(2, 2));
    QImage image(kWidgetSize, QImage::Format_ARGB32_Premultiplied);
    std::vector<std::vector<QPolygonF>> kept(frame.regions.size());
    std::size_t keptVertices = 0;
    const double decimate = millisecondsPer(seconds, [&] {
        keptVertices = 0;
        for (std::size_t r = 0; r < frame.regions.size(); ++r) {
            kept[r].resize(frame.regions[r].size());
            for (std::size_t c = 0; c < frame.regions[r].size(); ++c) {
                app::decimateContour(frame.regions[r][c], toDevice, app::kLodTolerance, visible, kept[r][c]);
                keptVertices += kept[r][c].size();
            }
        }
    });
    std::vector<QPainterPath> paths(frame.regions.size());
    const double assemble = millisecondsPer(seconds, [&] {
        for (std::size_t r = 0; r < kept.size(); ++r) {
            paths[r] = QPainterPath();
            paths[r].setFillRule(Qt::OddEvenFill);
            for (const QPolygonF& contour : kept[r]) {
                paths[r].addPolygon(contour);
                paths[r].closeSubpath();
            }
        }
    });
    const auto fill = [&](const std::function<void(QPainter&, std::size_t)>& draw) {
        return millisecondsPer(seconds, [&] {
            image.fill(Qt::white);
            QPainter painter(&image);
            painter.setRenderHint(QPainter::Antialiasing);
            painter.setPen(Qt::NoPen);
            for (const model::RegionLook& look : table) {
                painter.setBrush(look.color);
                draw(painter, std::size_t(look.simIndex));
            }
        });
    };
    const double fillPaths = fill([&](QPainter& p, std::size_t r) { p.drawPath(paths[r]); });
    // The alternative to a path: one polygon per region, each contour closed and joined to the next
    // by an edge walked once each way (zero area under even-odd).
    std::vector<QPolygonF> bridged(kept.size());
    for (std::size_t r = 0; r < kept.size(); ++r) {
        for (const QPolygonF& contour : kept[r])
            if (contour.size() >= 3)
                bridged[r] << contour << contour.first();
        for (auto c = kept[r].rbegin(); c != kept[r].rend(); ++c)
            if (c->size() >= 3)
                bridged[r] << c->first();
    }
    const double fillPolygons = fill([&](QPainter& p, std::size_t r) { p.drawPolygon(bridged[r], Qt::OddEvenFill); });
    // The same contours gathered into a few paths spread over the whole canvas (one per ring round:
    // 20 contours each): what a region of many far-apart contours costs. The rasteriser walks a
    // path's whole outline once per band of scanlines it renders.
    std::vector<QPainterPath> rounds(kRings);
    for (QPainterPath& round : rounds)
        round.setFillRule(Qt::OddEvenFill);
    for (std::size_t r = 0; r < paths.size(); ++r)
        rounds[r / (kLatticeX * kLatticeY)].addPath(paths[r]);
    const double fillRounds = millisecondsPer(seconds, [&] {
        image.fill(Qt::white);
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        for (const QPainterPath& round : rounds)
            painter.fillPath(round, Qt::darkBlue);
    });
    // Without the level of detail: every vertex of the frame.
    std::vector<QPainterPath> full(frame.regions.size());
    for (std::size_t r = 0; r < frame.regions.size(); ++r) {
        full[r].setFillRule(Qt::OddEvenFill);
        for (const sim::Polygon& contour : frame.regions[r]) {
            full[r].moveTo(toDevice.map(contour.front()));
            for (const Vec2& v : contour)
                full[r].lineTo(toDevice.map(v));
            full[r].closeSubpath();
        }
    }
    const double fillFull = fill([&](QPainter& p, std::size_t r) { p.drawPath(full[r]); });
    std::printf("  breakdown (ms CPU): %zu of %zu vertices kept; decimation %.1f, path assembly %.1f, "
                "fill %.1f (bridged drawPolygon %.1f; as 12 paths of 20 contours %.1f; every vertex, no LOD: %.1f)\n",
                keptVertices, frame.vertexCount, decimate, assemble, fillPaths, fillPolygons, fillRounds, fillFull);
}

void measure(std::size_t target, double seconds)
{
    const double spacing = spacingFor(target);
    std::vector<std::shared_ptr<const model::Frame>> frames;
    for (int i = 0; i < kDistinctFrames; ++i)
        frames.push_back(marbledFrame(spacing, 0.05 * i));
    const model::Frame& first = *frames.front();

    app::Canvas canvas;
    canvas.resize(kWidgetSize);
    canvas.setRegions(looks());
    canvas.setFrame(frames.front());
    canvas.show();
    QCoreApplication::processEvents();

    const auto view = [&](const char* name) {
        const Rate newFrames = paintRate(canvas, seconds, [&](int i) { canvas.setFrame(frames[i % frames.size()]); });
        canvas.setFrame(frames.front());
        const Rate repaints = paintRate(canvas, seconds, [](int) {});
        std::printf("  %-20s new frame every paint: %6.1f FPS (canvas counter %d), %6.1f ms CPU/frame | "
                    "repaint only: %6.1f FPS (counter %d), %6.2f ms CPU/frame\n",
                    name, newFrames.fps, newFrames.canvasFps, newFrames.cpuMs, repaints.fps, repaints.canvasFps,
                    repaints.cpuMs);
    };
    std::printf("scene: %zu vertices in %zu contours, spacing %.2g canvas units (%.2f px at fit)\n", first.vertexCount,
                first.regions.size(), spacing, spacing * canvas.zoom());
    view("fit (whole canvas)");
    const double dpr = canvas.devicePixelRatioF();
    const app::PixelMapping fitted{canvas.zoom() * dpr, canvas.mapFromCanvas({0, 0}).x() * dpr,
                                   canvas.mapFromCanvas({0, 0}).y() * dpr};
    for (int i = 0; i < 8; ++i)
        canvas.zoomIn();  // 16× about the centre
    view("zoomed 16x (centre)");
    breakdown(first, fitted, looks(), seconds / 3);
}

} // namespace

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    double seconds = 3.0;
    std::vector<std::size_t> sizes{200000, 1000000};
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i + 1 < args.size(); i += 2) {
        if (args[i] == QLatin1String("--seconds")) {
            seconds = args[i + 1].toDouble();
        } else if (args[i] == QLatin1String("--sizes")) {
            sizes.clear();
            for (const QString& size : args[i + 1].split(u','))
                sizes.push_back(size.toULong());
        } else {
            std::fprintf(stderr, "canvas_fps: unknown option %s (use --seconds S, --sizes N,N)\n", qPrintable(args[i]));
            return 2;
        }
    }
    std::printf("platform %s, widget %dx%d\n", qPrintable(QGuiApplication::platformName()), kWidgetSize.width(),
                kWidgetSize.height());
    for (std::size_t size : sizes)
        measure(size, seconds);
    return 0;
}
