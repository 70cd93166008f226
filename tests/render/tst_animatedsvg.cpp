// Animated SVG: well-formed for xmllint; one group per frame, each visible for its own 1/N of the
// cycle by a discrete SMIL animation that repeats; and a reader that does not play SMIL
// (rsvg-convert) paints the first frame as our PNG render paints it (98% of pixels).
#include "AnimationScene.h"
#include "ExternalTools.h"
#include "FrameCompare.h"

#include <QFile>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

using namespace vf;

namespace {

constexpr int kFrames = 4;

render::ExportOptions frameOptions()
{
    render::ExportOptions options;
    options.pageWidth = 250;
    options.dpi = 72;
    return options;
}

struct FrameGroup {
    QString id;
    QString visibility;  // the group's own attribute: what a reader without SMIL shows
    QStringList animate; // values | keyTimes | dur | calcMode | repeatCount
    int paths = 0;
};

QList<FrameGroup> frameGroups(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QList<FrameGroup> groups;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        const QXmlStreamAttributes a = xml.attributes();
        if (xml.name() == QLatin1String("g") && a.value("id").startsWith(QLatin1String("frame-")))
            groups.append({a.value("id").toString(), a.value("visibility").toString(), {}, 0});
        else if (xml.name() == QLatin1String("animate") && !groups.isEmpty())
            for (const char* name : {"attributeName", "values", "keyTimes", "dur", "calcMode", "repeatCount"})
                groups.back().animate << a.value(QLatin1String(name)).toString();
        else if (xml.name() == QLatin1String("path") && !groups.isEmpty())
            ++groups.back().paths;
    }
    return xml.hasError() ? QList<FrameGroup>{} : groups;
}

} // namespace

class TestAnimatedSvg : public QObject {
    Q_OBJECT

private slots:
    void framesTakeTurnsAndTheFirstShowsWithoutSmil();
};

void TestAnimatedSvg::framesTakeTurnsAndTheFirstShowsWithoutSmil()
{
    REQUIRE_TOOL(xmllint, "xmllint");
    REQUIRE_TOOL(rsvg, "rsvg-convert");
    model::SceneRunner runner(test::animationScene());
    std::vector<model::Drawing> frames;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ink.svg"));
    QCOMPARE(render::exportAnimation(test::recordedAnimation(runner, kFrames, frames), path, frameOptions()), QString());

    const Run lint = run(xmllint, {QStringLiteral("--noout"), path});
    QVERIFY2(lint.exitCode == 0, lint.output.constData());
    const QList<FrameGroup> groups = frameGroups(path);
    QCOMPARE(groups.size(), kFrames);
    const QString cycle = QStringLiteral("0.133333333s");  // 4 frames at 30 fps
    const QList<QStringList> expected{
        {"visibility", "visible;hidden", "0;0.25", cycle, "discrete", "indefinite"},
        {"visibility", "hidden;visible;hidden", "0;0.25;0.5", cycle, "discrete", "indefinite"},
        {"visibility", "hidden;visible;hidden", "0;0.5;0.75", cycle, "discrete", "indefinite"},
        {"visibility", "hidden;visible", "0;0.75", cycle, "discrete", "indefinite"},
    };
    for (int i = 0; i < kFrames; ++i) {
        QCOMPARE(groups[i].id, QStringLiteral("frame-%1").arg(i));
        QCOMPARE(groups[i].visibility, i == 0 ? QString() : QStringLiteral("hidden"));
        QCOMPARE(groups[i].animate, expected[i]);
        QCOMPARE(std::size_t(groups[i].paths), frames[std::size_t(i)].regions.size());  // the drop lands at frame 2
    }

    const QString png = dir.filePath(QStringLiteral("rsvg.png"));
    const Run painted = run(rsvg, {QStringLiteral("-w"), QStringLiteral("250"), QStringLiteral("-h"), QStringLiteral("200"),
                                   QStringLiteral("-o"), png, path});
    QVERIFY2(painted.exitCode == 0, painted.output.constData());
    const QImage first = QImage(png);
    const double agree = test::agreement(test::ourRender(frames.front(), frameOptions()), first);
    qInfo("rsvg's picture and our first frame: %.2f%% of pixels agree", 100 * agree);
    QVERIFY(agree >= 0.98);
    QVERIFY(test::agreement(test::ourRender(frames.back(), frameOptions()), first) < 0.98);
}

QTEST_GUILESS_MAIN(TestAnimatedSvg)
#include "tst_animatedsvg.moc"
