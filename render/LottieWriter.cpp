// Lottie (Bodymovin JSON): one shape layer per region, from the frame it first appears in, top
// layer first. Each contour of a region is one path item (`sh`) whose shape changes by hold
// keyframes (`h: 1`): vertex counts change from frame to frame and a player would otherwise morph
// between unequal paths. The region's fill (`fl`) follows its paths with the even-odd rule
// (`r: 2`), which fills all the paths before it in the layer together, holes included. A region
// with fewer contours than before empties its extra paths; a frame that repeats a path's shape
// adds no keyframe.
//
// The frames are not kept: each is fitted and written as text at once, into one buffer per path
// item, and the file is put together at the end. Memory is the file's size, not the frames'
// geometry (300 frames of 50k vertices would be 240 MB of doubles). Coordinates are page points,
// which Lottie takes as pixels, rounded to a power of ten at most a quarter of the fit's
// tolerance (render/SvgRounding.h), so rounding adds little to the fit's error; in- and
// out-tangents are rounded the same way, relative to their vertex as Lottie has them.
#include "render/AnimationWriters.h"

#include "render/BufferedWriter.h"
#include "render/Page.h"
#include "render/PathEmitter.h"
#include "render/SvgRounding.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

namespace vf::render {
namespace {

// Writes numbers rounded to `step` in their shortest form.
class Numbers {
public:
    explicit Numbers(double step) : m_step(step) {}

    void append(std::string& out, double value) const
    {
        char text[32];
        const double rounded = roundedToStep(value, m_step) + 0.0;  // + 0.0: no "-0"
        out.append(text, std::to_chars(text, text + sizeof text, rounded).ptr);
    }
    void appendPoint(std::string& out, sim::Vec2 p) const
    {
        out += '[';
        append(out, p.x);
        out += ',';
        append(out, p.y);
        out += ']';
    }

private:
    double m_step;
};

// Lottie's form of a closed path: vertices, and per vertex the in- and out-tangent relative to it.
struct LottiePath {
    std::vector<sim::Vec2> vertices, in, out;
};

// Collects a region's subpaths in page coordinates, one LottiePath each.
class LottieSink final : public PathSink {
public:
    explicit LottieSink(const Page& page) : m_page(page) {}

    void moveTo(sim::Vec2 point) override
    {
        m_paths.emplace_back();
        add(toPage(point));
    }
    void lineTo(sim::Vec2 point) override { add(toPage(point)); }
    void cubicTo(sim::Vec2 control1, sim::Vec2 control2, sim::Vec2 end) override
    {
        LottiePath& path = m_paths.back();
        path.out.back() = toPage(control1) - path.vertices.back();
        add(toPage(end));
        path.in.back() = toPage(control2) - path.vertices.back();
    }
    // A fitted contour's last segment ends on its start: that vertex is the first one, with the
    // last segment's in-tangent.
    void closePath() override
    {
        LottiePath& path = m_paths.back();
        if (path.vertices.size() > 1 && path.vertices.back() == path.vertices.front()) {
            path.in.front() = path.in.back();
            path.vertices.pop_back();
            path.in.pop_back();
            path.out.pop_back();
        }
    }

    const std::vector<LottiePath>& paths() const { return m_paths; }

private:
    sim::Vec2 toPage(sim::Vec2 p) const
    {
        return {m_page.left + p.x * m_page.pointsPerUnit, m_page.top + p.y * m_page.pointsPerUnit};
    }
    void add(sim::Vec2 vertex)
    {
        LottiePath& path = m_paths.back();
        path.vertices.push_back(vertex);
        path.in.emplace_back(0.0, 0.0);
        path.out.emplace_back(0.0, 0.0);
    }

    const Page& m_page;
    std::vector<LottiePath> m_paths;
};

const std::string kEmptyShape = R"({"c":true,"v":[],"i":[],"o":[]})";

std::string shapeText(const LottiePath& path, const Numbers& numbers)
{
    std::string text = R"({"c":true,"v":[)";
    const auto points = [&](const std::vector<sim::Vec2>& list) {
        for (std::size_t i = 0; i < list.size(); ++i) {
            if (i > 0)
                text += ',';
            numbers.appendPoint(text, list[i]);
        }
    };
    points(path.vertices);
    text += R"(],"i":[)";
    points(path.in);
    text += R"(],"o":[)";
    points(path.out);
    text += "]}";
    return text;
}

// One path item of a layer: its hold keyframes as text, and the shape of the last one.
struct PathItem {
    std::string keyframes;
    std::string last;
    int count = 0;

    void hold(int frame, const std::string& shape)
    {
        if (count > 0 && shape == last)
            return;
        if (count > 0)
            keyframes += ',';
        keyframes += R"({"t":)" + std::to_string(frame) + R"(,"s":[)" + shape + R"(],"h":1})";
        last = shape;
        ++count;
    }
};

struct Layer {
    QString name;
    QColor color;
    int firstFrame = 0;
    std::vector<PathItem> paths;

    // The region's shapes at `frame`: path items beyond them are emptied, new ones start empty
    // at the layer's first frame so that they show nothing before.
    void add(int frame, const std::vector<std::string>& shapes)
    {
        for (std::size_t i = 0; i < std::max(shapes.size(), paths.size()); ++i) {
            if (i == paths.size()) {
                paths.emplace_back();
                if (frame > firstFrame)
                    paths.back().hold(firstFrame, kEmptyShape);
            }
            paths[i].hold(frame, i < shapes.size() ? shapes[i] : kEmptyShape);
        }
    }
};

std::string jsonString(const QString& text)
{
    const QByteArray array = QJsonDocument(QJsonArray{text}).toJson(QJsonDocument::Compact);
    return array.mid(1, array.size() - 2).toStdString();  // without the brackets
}

// A shape layer with static transform; `shapes` is the JSON of its items.
void writeLayer(BufferedWriter& json, int index, const std::string& name, int firstFrame, int frames,
                const std::string& shapes)
{
    json << R"({"ddd":0,"ind":)" << std::to_string(index) << R"(,"ty":4,"nm":)" << name
         << R"(,"sr":1,"ks":{"o":{"a":0,"k":100},"r":{"a":0,"k":0},"p":{"a":0,"k":[0,0,0]},)"
            R"("a":{"a":0,"k":[0,0,0]},"s":{"a":0,"k":[100,100,100]}},"ao":0,"shapes":[)"
         << shapes << R"(],"ip":)" << std::to_string(firstFrame) << R"(,"op":)" << std::to_string(frames)
         << R"(,"st":0,"bm":0})";
}

// The region's paint: `color` (channels 0 to 1, to 4 decimals) and its opacity, even-odd.
std::string fill(const QColor& color)
{
    const Numbers numbers(1e-4);
    std::string text = R"({"ty":"fl","c":{"a":0,"k":[)";
    for (const double channel : {color.redF(), color.greenF(), color.blueF()}) {
        numbers.append(text, channel);
        text += ',';
    }
    text += R"(1]},"o":{"a":0,"k":)";
    numbers.append(text, color.alphaF() * 100);
    text += R"(},"r":2})";
    return text;
}

} // namespace

QString writeLottie(const Animation& animation, const ExportOptions& options, const AnimationProgress& progress,
                    QIODevice& out)
{
    std::vector<Layer> layers;  // by region index, bottom to top
    model::Drawing first;
    const QString error = forEachFrame(animation, options, progress, [&](int index, const model::Drawing& frame) {
        if (index == 0)
            first = model::Drawing{frame.width, frame.height, frame.background, {}};
        const Page page = pageFor(frame, options);
        const PathStyle style = pathStyle(frame, options);
        const Numbers numbers(decimalStepBelow(style.tolerance * page.pointsPerUnit / 4));
        for (std::size_t r = 0; r < std::max(layers.size(), frame.regions.size()); ++r) {
            if (r == layers.size())
                layers.push_back({frame.regions[r].name, frame.regions[r].color, index, {}});
            std::vector<std::string> shapes;  // a region gone or hidden has none
            if (r < frame.regions.size() && frame.regions[r].visible) {
                LottieSink sink(page);
                emitRegion(frame.regions[r], style, sink);
                for (const LottiePath& path : sink.paths())
                    shapes.push_back(shapeText(path, numbers));
            }
            layers[r].add(index, shapes);
        }
        return QString();
    });
    if (!error.isEmpty())
        return error;

    const Page page = pageFor(first, options);
    BufferedWriter json(out);
    json << R"({"v":"5.7.0","fr":)" << animation.fps << R"(,"ip":0,"op":)" << std::to_string(animation.frames)
         << R"(,"w":)" << std::to_string(std::lround(page.width)) << R"(,"h":)"
         << std::to_string(std::lround(page.height)) << R"(,"nm":"vectorfluid","ddd":0,"assets":[],"layers":[)";
    int layerIndex = 1;
    for (auto layer = layers.rbegin(); layer != layers.rend(); ++layer) {
        std::string shapes;
        for (std::size_t i = 0; i < layer->paths.size(); ++i) {
            const PathItem& path = layer->paths[i];
            shapes += R"({"ty":"sh","nm":"contour )" + std::to_string(i + 1) + R"(","ks":)";
            shapes += path.count == 1 ? R"({"a":0,"k":)" + path.last + "}" : R"({"a":1,"k":[)" + path.keyframes + "]}";
            shapes += "},";
        }
        shapes += fill(layer->color);
        if (layerIndex > 1)
            json << ',';
        writeLayer(json, layerIndex++, jsonString(layer->name), layer->firstFrame, animation.frames, shapes);
    }
    if (options.background) {
        const Numbers numbers(decimalStepBelow(pathStyle(first, options).tolerance * page.pointsPerUnit / 4));
        const double width = first.width * page.pointsPerUnit, height = first.height * page.pointsPerUnit;
        std::string rectangle = R"({"ty":"rc","d":1,"p":{"a":0,"k":)";
        numbers.appendPoint(rectangle, {page.left + width / 2, page.top + height / 2});
        rectangle += R"(},"s":{"a":0,"k":)";
        numbers.appendPoint(rectangle, {width, height});
        rectangle += R"(},"r":{"a":0,"k":0}},)" + fill(first.background);
        if (layerIndex > 1)
            json << ',';
        writeLayer(json, layerIndex, R"("Background")", 0, animation.frames, rectangle);
    }
    json << "]}\n";
    return json.finish();
}

} // namespace vf::render
