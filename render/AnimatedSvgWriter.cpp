// Animated SVG: the still SVG's header and background, then one group per frame holding that
// frame's regions as even-odd paths. Every group is hidden but for its own interval of the cycle:
// a SMIL <animate> of `visibility`, discrete, repeating forever, so browsers play the frames in a
// loop. The first frame's group is visible without animation, so a reader that does not play SMIL
// (rsvg, Inkscape) shows the first frame. Coordinates are rounded to a power of ten at most a
// quarter of the fit's tolerance (render/SvgRounding.h); the frames stream to the file as they come.
#include "render/AnimationWriters.h"

#include "render/BufferedWriter.h"
#include "render/Page.h"
#include "render/SvgParts.h"
#include "render/SvgRounding.h"

#include <QString>

namespace vf::render {
namespace {

// values and keyTimes of frame `index`'s visibility over the cycle of `frames` frames.
void writeVisibility(BufferedWriter& xml, int index, int frames, double fps)
{
    const auto time = [&](int frame) { return QString::number(double(frame) / frames, 'g', 9); };
    QString values, keyTimes;
    if (index == 0) {
        values = QStringLiteral("visible;hidden");
        keyTimes = QStringLiteral("0;") + time(1);
    } else if (index == frames - 1) {
        values = QStringLiteral("hidden;visible");
        keyTimes = QStringLiteral("0;") + time(index);
    } else {
        values = QStringLiteral("hidden;visible;hidden");
        keyTimes = QStringLiteral("0;%1;%2").arg(time(index), time(index + 1));
    }
    xml << "<animate attributeName=\"visibility\" values=\"" << values << "\" keyTimes=\"" << keyTimes
        << "\" dur=\"" << QString::number(frames / fps, 'g', 9) << "s\" calcMode=\"discrete\" repeatCount=\"indefinite\"/>\n";
}

} // namespace

QString writeAnimatedSvg(const Animation& animation, const ExportOptions& options, const AnimationProgress& progress,
                         QIODevice& out)
{
    BufferedWriter xml(out);
    const QString error = forEachFrame(animation, options, progress, [&](int index, const model::Drawing& frame) {
        const PathStyle style = pathStyle(frame, options);
        if (index == 0) {
            writeSvgHeader(xml, frame, pageFor(frame, options));
            UniqueXmlIds ids;
            if (options.background)
                writeSvgBackground(xml, frame, ids);
        }
        xml << "<g id=\"frame-" << QString::number(index) << '"';
        if (index > 0)
            xml << " visibility=\"hidden\"";
        xml << ">\n";
        if (animation.frames > 1)
            writeVisibility(xml, index, animation.frames, animation.fps);
        for (const model::DrawnRegion& region : frame.regions) {
            if (!region.visible)
                continue;
            xml << "<path";
            writeSvgFill(xml, region.color);
            xml << " fill-rule=\"evenodd\" d=\"";
            SvgPathData data(xml, decimalStepBelow(style.tolerance / 4));
            emitRegion(region, style, data);
            xml << "\"/>\n";
        }
        xml << "</g>\n";
        return QString();
    });
    if (!error.isEmpty())
        return error;
    xml << "</svg>\n";
    return xml.finish();
}

} // namespace vf::render
