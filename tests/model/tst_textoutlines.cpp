// Text outlines: glyphs become simple, non-crossing, positively oriented contours in canvas units
// with short edges, counters as contours of their own, scaled by the em height.
#include "model/TextOutlines.h"
#include "sim/Crossings.h"

#include <QFontDatabase>
#include <QtTest>

#include <glm/geometric.hpp>

using namespace vf;
using namespace vf::model;
using namespace Qt::StringLiterals;
using sim::Vec2;

namespace {

struct Box {
    Vec2 min{std::numeric_limits<double>::max()}, max{-std::numeric_limits<double>::max()};
};

Box bounds(const std::vector<sim::Polygon>& contours)
{
    Box box;
    for (const sim::Polygon& contour : contours) {
        for (const Vec2& p : contour) {
            box.min = glm::min(box.min, p);
            box.max = glm::max(box.max, p);
        }
    }
    return box;
}

void verifyWellFormed(const std::vector<sim::Polygon>& contours, double spacing)
{
    std::vector<const sim::Polygon*> all;
    for (const sim::Polygon& contour : contours) {
        QVERIFY(contour.size() >= 3);
        QVERIFY(sim::signedArea(contour) > 0.0);
        QVERIFY(sim::isSimple(contour));
        for (std::size_t i = 0; i < contour.size(); ++i)
            QVERIFY(glm::distance(contour[i], contour[(i + 1) % contour.size()]) <= spacing * (1.0 + 1e-9));
        all.push_back(&contour);
    }
    QCOMPARE(sim::countCrossings(all), std::size_t(0));
}

QFont dejaVu()
{
    return QFont(u"DejaVu Sans"_s);
}

} // namespace

class TestTextOutlines : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY2(QFontDatabase::families().contains(u"DejaVu Sans"_s), "fonts-dejavu-core is not installed");
    }

    void letterOHasOuterAndCounter()
    {
        const double spacing = 0.002;
        const std::vector<sim::Polygon> contours = textContours(u"O"_s, dejaVu(), {0.2, 0.7}, 0.5, spacing);
        QCOMPARE(contours.size(), std::size_t(2));
        verifyWellFormed(contours, spacing);
        const bool firstOuter = sim::signedArea(contours[0]) > sim::signedArea(contours[1]);
        const sim::Polygon& outer = contours[firstOuter ? 0 : 1];
        const sim::Polygon& counter = contours[firstOuter ? 1 : 0];
        for (const Vec2& p : counter)
            QVERIFY(sim::windingNumber(outer, p) != 0);
        // Cap height of DejaVu Sans is about 0.73 em: the O stands on the baseline, y down.
        const Box box = bounds(contours);
        QVERIFY(box.max.y > 0.69 && box.max.y < 0.72);
        QVERIFY(box.min.y > 0.7 - 0.5 * 0.8 && box.min.y < 0.7 - 0.5 * 0.65);
        QVERIFY(box.min.x >= 0.2 && box.min.x < 0.2 + 0.1);
    }

    void wordHasItsLetters()
    {
        const double spacing = 0.002;
        const std::vector<sim::Polygon> contours = textContours(u"Hello"_s, dejaVu(), {0.1, 0.6}, 0.2, spacing);
        // H, e (+ counter), l, l, o (+ counter).
        QCOMPARE(contours.size(), std::size_t(7));
        verifyWellFormed(contours, spacing);
        const Box box = bounds(contours);
        QVERIFY(box.min.x >= 0.1 && box.min.x < 0.13);
        QVERIFY(box.max.x > 0.1 + 0.2 * 2.0 && box.max.x < 0.1 + 0.2 * 3.5);  // five letters, about 0.6 em each
        QVERIFY(box.min.y < 0.6 - 0.2 * 0.7 && box.min.y > 0.6 - 0.2 * 0.85);  // ascender of l
        QVERIFY(box.max.y > 0.6 && box.max.y < 0.6 + 0.2 * 0.05);              // o's overshoot only
    }

    void overlappingGlyphsMerge()
    {
        // Negative letter spacing makes the glyphs overlap; they must merge, not cross.
        QFont font = dejaVu();
        font.setLetterSpacing(QFont::AbsoluteSpacing, -800);
        const std::vector<sim::Polygon> contours = textContours(u"OOO"_s, font, {0.1, 0.6}, 0.2, 0.002);
        QVERIFY(!contours.empty());
        verifyWellFormed(contours, 0.002);
    }

    void emHeightScales()
    {
        const std::vector<sim::Polygon> small = textContours(u"Ag"_s, dejaVu(), {0.0, 0.0}, 0.1, 0.001);
        const std::vector<sim::Polygon> large = textContours(u"Ag"_s, dejaVu(), {0.0, 0.0}, 0.3, 0.001);
        QCOMPARE(small.size(), large.size());
        const Box a = bounds(small), b = bounds(large);
        QVERIFY(std::abs((b.max.x - b.min.x) / (a.max.x - a.min.x) - 3.0) < 0.01);
        QVERIFY(std::abs((b.max.y - b.min.y) / (a.max.y - a.min.y) - 3.0) < 0.01);
        double areaSmall = 0.0, areaLarge = 0.0;
        for (const sim::Polygon& c : small)
            areaSmall += sim::signedArea(c);
        for (const sim::Polygon& c : large)
            areaLarge += sim::signedArea(c);
        QVERIFY(std::abs(areaLarge / areaSmall - 9.0) < 0.05);
    }

    void blankTextHasNoContours()
    {
        QVERIFY(textContours(QString(), dejaVu(), {0.5, 0.5}, 0.2, 0.002).empty());
        QVERIFY(textContours(u" \t "_s, dejaVu(), {0.5, 0.5}, 0.2, 0.002).empty());
    }
};

QTEST_MAIN(TestTextOutlines)
#include "tst_textoutlines.moc"
