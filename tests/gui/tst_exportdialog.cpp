// The export dialog driven through its widgets: the files it writes open in readers, the options
// reach them, failures are reported without writing, and the choices are remembered. Also
// Copy as SVG.
#include "FindChild.h"
#include "../TestFiles.h"
#include "../render/SvgReadBack.h"
#include "app/ClipboardExport.h"
#include "app/ExportDialog.h"
#include "app/Folders.h"

#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QGuiApplication>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QMimeData>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <memory>
#include <numbers>

using namespace vf;

namespace {

using vf::test::child;

// A 2 x 1 canvas: a square and a circle shown, a triangle hidden.
model::Drawing testDrawing()
{
    model::Drawing drawing;
    drawing.width = 2.0;
    drawing.height = 1.0;
    drawing.background = QColor(250, 240, 200);
    sim::Polygon circle;  // fine enough for curves within the default Bézier tolerance
    constexpr int kCircleVertices = 512;
    for (int i = 0; i < kCircleVertices; ++i) {
        const double a = 2 * std::numbers::pi * i / kCircleVertices;
        circle.push_back({1.5 + 0.3 * std::cos(a), 0.5 - 0.3 * std::sin(a)});
    }
    drawing.regions = {
        {QStringLiteral("square"), QColor(200, 30, 30), true, {{{0.2, 0.2}, {0.2, 0.8}, {0.8, 0.8}, {0.8, 0.2}}}},
        {QStringLiteral("circle"), QColor(30, 30, 200), true, {circle}},
        {QStringLiteral("hidden"), QColor(30, 200, 30), false, {{{1.0, 0.1}, {1.2, 0.1}, {1.1, 0.3}}}},
    };
    return drawing;
}

constexpr int kVisibleRegions = 2;

void typeInto(QLineEdit* edit, const QString& text)
{
    QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(edit, text);
}

// No Enter: in a dialog that would press Export.
void typeInto(QAbstractSpinBox* box, const QString& text)
{
    box->selectAll();  // the number, without a suffix such as " dpi"
    QTest::keyClicks(box, text);
}

// Arrow keys, as a user choosing from a closed combo box.
void pick(QComboBox* combo, const QString& text)
{
    const int target = combo->findText(text);
    QVERIFY2(target >= 0, qPrintable(text));
    while (combo->currentIndex() != target)
        QTest::keyClick(combo, combo->currentIndex() < target ? Qt::Key_Down : Qt::Key_Up);
}

// The <path> elements outside hidden layers.
int visiblePathCount(const test::ParsedSvg& svg)
{
    int count = 0;
    for (const test::ParsedLayer& layer : svg.layers) {
        if (!layer.style.contains(QLatin1String("display:none")))
            count += int(layer.paths.size());
    }
    return count;
}

double points(const QString& length)
{
    return QStringView(length).chopped(2).toDouble();  // "123.4pt"
}

} // namespace

class TestExportDialog : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void svgHasOnePathPerVisibleRegion_data();
    void svgHasOnePathPerVisibleRegion();
    void pdfOpensInQpdf();
    void pngHasTheSizeTheResolutionImplies_data();
    void pngHasTheSizeTheResolutionImplies();
    void backgroundOffLeavesPngTransparent();
    void pageHeightFollowsTheCanvas();
    void pageHeightIsFreeWithTheCanvasCentred();
    void defaultPathIsInAnExistingFolderAndShownWhole();
    void returnInThePathExports();
    void unwritablePathReportsAndWritesNothing();
    void pngBeyondMemoryIsRefused();
    void formatAndSuffixStayInStep();
    void choicesAreRemembered();
    void copyAsSvgPutsSvgOnTheClipboard();

private:
    std::unique_ptr<app::ExportDialog> openDialog();
    void exportTo(app::ExportDialog& dialog, const QString& fileName);
    QString path(const QString& name) const { return m_dir.filePath(name); }

    QTemporaryDir m_dir;
};

void TestExportDialog::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);  // keeps the user's remembered options out of it
    QVERIFY(m_dir.isValid());
    QVERIFY(QSettings(QStringLiteral("vectorfluid"), QStringLiteral("vectorfluid")).fileName().contains(QLatin1String("qttest")));
}

void TestExportDialog::init()
{
    QSettings(QStringLiteral("vectorfluid"), QStringLiteral("vectorfluid")).remove(QStringLiteral("export"));
}

std::unique_ptr<app::ExportDialog> TestExportDialog::openDialog()
{
    auto dialog = std::make_unique<app::ExportDialog>(testDrawing());
    dialog->show();
    if (!QTest::qWaitForWindowExposed(dialog.get()))
        qFatal("the export dialog was not shown");
    return dialog;
}

// Types the name, presses Export.
void TestExportDialog::exportTo(app::ExportDialog& dialog, const QString& fileName)
{
    typeInto(child<QLineEdit>(dialog, "path"), fileName);
    QTest::mouseClick(child<QPushButton>(dialog, "export"), Qt::LeftButton);
}

void TestExportDialog::svgHasOnePathPerVisibleRegion_data()
{
    QTest::addColumn<QString>("curves");
    QTest::addColumn<bool>("bezier");
    QTest::newRow("bezier") << QStringLiteral("Bézier curves") << true;
    QTest::newRow("polyline") << QStringLiteral("Exact polyline") << false;
}

void TestExportDialog::svgHasOnePathPerVisibleRegion()
{
    QFETCH(QString, curves);
    QFETCH(bool, bezier);
    const auto dialog = openDialog();
    pick(child<QComboBox>(*dialog, "curves"), curves);
    pick(child<QComboBox>(*dialog, "unit"), QStringLiteral("mm"));
    typeInto(child<QDoubleSpinBox>(*dialog, "pageWidth"), QStringLiteral("254"));
    const QString file = path(QStringLiteral("picture-%1.svg").arg(QTest::currentDataTag()));
    exportTo(*dialog, file);
    QVERIFY2(dialog->lastError().isEmpty(), qPrintable(dialog->lastError()));
    QCOMPARE(dialog->result(), int(QDialog::Accepted));

    const test::ParsedSvg svg = test::parseSvg(file);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QCOMPARE(visiblePathCount(svg), kVisibleRegions);
    QVERIFY(std::abs(points(svg.width) - 720.0) < 1e-6);  // 254 mm = 10 in
    QVERIFY(std::abs(points(svg.height) - 360.0) < 1e-6);
    bool anyCurve = false;
    for (const test::ParsedPath* region : test::regionPaths(svg)) {
        for (const render::FittedContour& contour : region->contours) {
            for (const render::PathSegment& segment : contour.segments)
                anyCurve = anyCurve || !segment.isLine;
        }
    }
    QCOMPARE(anyCurve, bezier);
}

void TestExportDialog::pdfOpensInQpdf()
{
    const auto dialog = openDialog();
    pick(child<QComboBox>(*dialog, "format"), QStringLiteral("PDF"));
    const QString file = path(QStringLiteral("picture.pdf"));
    exportTo(*dialog, file);
    QVERIFY2(dialog->lastError().isEmpty(), qPrintable(dialog->lastError()));
    QVERIFY(test::readAll(file).startsWith("%PDF-"));

    const QString qpdf = QStandardPaths::findExecutable(QStringLiteral("qpdf"));
    if (qpdf.isEmpty())
        QSKIP("qpdf is not installed: the PDF was checked for its header only");
    QProcess check;
    check.setProcessChannelMode(QProcess::MergedChannels);
    check.start(qpdf, {QStringLiteral("--check"), file});
    QVERIFY(check.waitForFinished(60000));
    QVERIFY2(check.exitStatus() == QProcess::NormalExit && check.exitCode() == 0, check.readAll().constData());
}

void TestExportDialog::pngHasTheSizeTheResolutionImplies_data()
{
    QTest::addColumn<QString>("unit");
    QTest::addColumn<QString>("width");
    QTest::addColumn<QString>("dpi");
    QTest::addColumn<QSize>("size");
    QTest::newRow("inches") << QStringLiteral("in") << QStringLiteral("4") << QStringLiteral("50") << QSize(200, 100);
    QTest::newRow("points") << QStringLiteral("pt") << QStringLiteral("144") << QStringLiteral("90") << QSize(180, 90);
    QTest::newRow("pixels") << QStringLiteral("px") << QStringLiteral("300") << QStringLiteral("150") << QSize(300, 150);
}

void TestExportDialog::pngHasTheSizeTheResolutionImplies()
{
    QFETCH(QString, unit);
    QFETCH(QString, width);
    QFETCH(QString, dpi);
    QFETCH(QSize, size);
    const auto dialog = openDialog();
    pick(child<QComboBox>(*dialog, "format"), QStringLiteral("PNG"));
    pick(child<QComboBox>(*dialog, "unit"), unit);
    typeInto(child<QSpinBox>(*dialog, "dpi"), dpi);
    typeInto(child<QDoubleSpinBox>(*dialog, "pageWidth"), width);
    const QString file = path(QStringLiteral("picture-%1.png").arg(QTest::currentDataTag()));
    exportTo(*dialog, file);
    QVERIFY2(dialog->lastError().isEmpty(), qPrintable(dialog->lastError()));

    const QImage image(file);
    QCOMPARE(image.size(), size);
    QCOMPARE(image.pixelColor(0, 0), testDrawing().background);
}

void TestExportDialog::backgroundOffLeavesPngTransparent()
{
    const auto dialog = openDialog();
    QCheckBox* background = child<QCheckBox>(*dialog, "background");
    QVERIFY(background->isChecked());
    QTest::mouseClick(background, Qt::LeftButton);
    QVERIFY(!background->isChecked());
    const QString file = path(QStringLiteral("transparent.png"));
    exportTo(*dialog, file);
    QVERIFY2(dialog->lastError().isEmpty(), qPrintable(dialog->lastError()));

    const QImage image(file);
    QVERIFY(!image.isNull());
    QCOMPARE(image.pixelColor(0, 0).alpha(), 0);
    // Ink is still there: the square's centre at (0.5, 0.5) of the 2 x 1 canvas.
    QCOMPARE(image.pixelColor(image.width() / 4, image.height() / 2), QColor(200, 30, 30));
}

void TestExportDialog::pageHeightFollowsTheCanvas()
{
    const auto dialog = openDialog();
    QDoubleSpinBox* width = child<QDoubleSpinBox>(*dialog, "pageWidth");
    const QDoubleSpinBox* height = child<QDoubleSpinBox>(*dialog, "pageHeight");
    QVERIFY(child<QCheckBox>(*dialog, "keepAspect")->isChecked());
    QVERIFY(!height->isEnabled());
    typeInto(width, QStringLiteral("500"));
    QCOMPARE(height->value(), 250.0);
    pick(child<QComboBox>(*dialog, "unit"), QStringLiteral("in"));  // the same page, shown in inches
    QCOMPARE(width->value(), 6.94);
    QCOMPARE(height->value(), 3.47);
    QCOMPARE(dialog->options().pageWidth, 500.0);
    QCOMPARE(dialog->options().pageHeight, 0.0);
}

// Without the canvas's proportions the height is the user's: a square page of a 2:1 canvas has
// the canvas centred, with empty bands above and below.
void TestExportDialog::pageHeightIsFreeWithTheCanvasCentred()
{
    const auto dialog = openDialog();
    QTest::mouseClick(child<QCheckBox>(*dialog, "keepAspect"), Qt::LeftButton);
    QDoubleSpinBox* height = child<QDoubleSpinBox>(*dialog, "pageHeight");
    QVERIFY(height->isEnabled());
    typeInto(child<QDoubleSpinBox>(*dialog, "pageWidth"), QStringLiteral("200"));
    typeInto(height, QStringLiteral("200"));
    const QString file = path(QStringLiteral("square.png"));
    typeInto(child<QLineEdit>(*dialog, "path"), file);
    typeInto(child<QSpinBox>(*dialog, "dpi"), QStringLiteral("72"));  // enabled for PNG
    QCOMPARE(dialog->options().pageHeight, 200.0);
    QTest::mouseClick(child<QPushButton>(*dialog, "export"), Qt::LeftButton);
    const QImage image(file);
    QCOMPARE(image.size(), QSize(200, 200));
    QCOMPARE(qAlpha(image.pixel(100, 10)), 0);    // the band above the canvas
    QCOMPARE(qAlpha(image.pixel(100, 190)), 0);   // and below it
    QCOMPARE(qAlpha(image.pixel(100, 100)), 255); // the canvas, its background painted
}

// The first export goes to the documents folder, or home where there is none; a remembered path
// whose folder has gone goes there too. The box is wide enough for the whole path.
void TestExportDialog::defaultPathIsInAnExistingFolderAndShownWhole()
{
    QSettings settings(QStringLiteral("vectorfluid"), QStringLiteral("vectorfluid"));
    for (const QString& remembered : {QString(), path(QStringLiteral("gone/picture.pdf"))}) {
        settings.setValue(QStringLiteral("export/path"), remembered);
        const auto dialog = openDialog();
        const QLineEdit* edit = child<QLineEdit>(*dialog, "path");
        QCOMPARE(edit->text(), QDir(app::documentsFolder()).filePath(QStringLiteral("picture.svg")));
        QVERIFY(QFileInfo(edit->text()).absoluteDir().exists());
        QVERIFY2(edit->width() > edit->fontMetrics().horizontalAdvance(edit->text()),
                 qPrintable(QStringLiteral("%1 px for a path of %2").arg(edit->width()).arg(edit->fontMetrics().horizontalAdvance(edit->text()))));
    }
}

// Enter in the path box presses Export, the default button.
void TestExportDialog::returnInThePathExports()
{
    const auto dialog = openDialog();
    QLineEdit* edit = child<QLineEdit>(*dialog, "path");
    typeInto(edit, path(QStringLiteral("entered.svg")));
    QTest::keyClick(edit, Qt::Key_Return);
    QVERIFY(QFileInfo::exists(path(QStringLiteral("entered.svg"))));
    QCOMPARE(dialog->result(), int(QDialog::Accepted));
}

void TestExportDialog::unwritablePathReportsAndWritesNothing()
{
    QTemporaryDir dir;
    QVERIFY(test::writeFile(dir.filePath(QStringLiteral("blocker")), "a file, not a folder"));
    const auto dialog = openDialog();
    exportTo(*dialog, dir.filePath(QStringLiteral("blocker/picture.svg")));

    QVERIFY(!dialog->lastError().isEmpty());
    QVERIFY(!dialog->lastError().contains(u'\n'));
    QVERIFY(dialog->isVisible());  // still open to fix the path
    const QMessageBox* box = child<QMessageBox>(*dialog, "exportError");
    QVERIFY(box->isVisible());
    QCOMPARE(box->text(), dialog->lastError());
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
             QStringList{QStringLiteral("blocker")});
}

// The largest page (1,000,000 pt wide) at the highest resolution: a PNG of about 1.8e16 bytes,
// beyond any machine, refused in one line before anything is allocated; the dialog stays open.
void TestExportDialog::pngBeyondMemoryIsRefused()
{
    const auto dialog = openDialog();
    pick(child<QComboBox>(*dialog, "format"), QStringLiteral("PNG"));
    pick(child<QComboBox>(*dialog, "unit"), QStringLiteral("pt"));
    typeInto(child<QSpinBox>(*dialog, "dpi"), QStringLiteral("4800"));
    typeInto(child<QDoubleSpinBox>(*dialog, "pageWidth"), QStringLiteral("1000000"));
    const QString file = path(QStringLiteral("huge.png"));
    exportTo(*dialog, file);

    const QString error = dialog->lastError();
    QVERIFY2(error.startsWith(QStringLiteral("A 66666667 x 33333333 pixel PNG (4800 dpi) needs about ")), qPrintable(error));
    QVERIFY2(error.contains(QStringLiteral(" available")) && !error.contains(u'\n'), qPrintable(error));
    QVERIFY(dialog->isVisible());
    const QMessageBox* box = child<QMessageBox>(*dialog, "exportError");
    QVERIFY(box->isVisible());
    QCOMPARE(box->text(), error);
    QVERIFY(!QFileInfo::exists(file));
}

void TestExportDialog::formatAndSuffixStayInStep()
{
    const auto dialog = openDialog();
    QLineEdit* pathEdit = child<QLineEdit>(*dialog, "path");
    QComboBox* format = child<QComboBox>(*dialog, "format");

    const QSpinBox* dpi = child<QSpinBox>(*dialog, "dpi");
    typeInto(pathEdit, path(QStringLiteral("a.png")));
    QCOMPARE(format->currentText(), QStringLiteral("PNG"));
    QVERIFY(dpi->isEnabled());
    pick(format, QStringLiteral("EPS"));
    QCOMPARE(pathEdit->text(), path(QStringLiteral("a.eps")));
    QVERIFY(!dpi->isEnabled());  // page sizes in points need no resolution
    typeInto(pathEdit, path(QStringLiteral("b.PDF")));
    QCOMPARE(format->currentText(), QStringLiteral("PDF"));
    // A name without an export suffix gets the chosen format's.
    typeInto(pathEdit, path(QStringLiteral("c.v2")));
    QCOMPARE(format->currentText(), QStringLiteral("PDF"));
    QCOMPARE(dialog->filePath(), path(QStringLiteral("c.v2.pdf")));
    QTest::mouseClick(child<QPushButton>(*dialog, "export"), Qt::LeftButton);
    QVERIFY2(dialog->lastError().isEmpty(), qPrintable(dialog->lastError()));
    QVERIFY(test::readAll(path(QStringLiteral("c.v2.pdf"))).startsWith("%PDF-"));
}

void TestExportDialog::choicesAreRemembered()
{
    const QString file = path(QStringLiteral("remembered.png"));
    {
        const auto dialog = openDialog();
        typeInto(child<QLineEdit>(*dialog, "path"), file);  // PNG first: the resolution is for PNG
        pick(child<QComboBox>(*dialog, "unit"), QStringLiteral("in"));
        typeInto(child<QDoubleSpinBox>(*dialog, "pageWidth"), QStringLiteral("3"));
        typeInto(child<QSpinBox>(*dialog, "dpi"), QStringLiteral("40"));
        QTest::mouseClick(child<QCheckBox>(*dialog, "background"), Qt::LeftButton);
        pick(child<QComboBox>(*dialog, "curves"), QStringLiteral("Exact polyline"));
        QTest::mouseClick(child<QPushButton>(*dialog, "export"), Qt::LeftButton);
        QVERIFY2(dialog->lastError().isEmpty(), qPrintable(dialog->lastError()));
    }
    const auto dialog = openDialog();
    QCOMPARE(child<QLineEdit>(*dialog, "path")->text(), file);
    QCOMPARE(child<QComboBox>(*dialog, "format")->currentText(), QStringLiteral("PNG"));
    QCOMPARE(child<QComboBox>(*dialog, "unit")->currentText(), QStringLiteral("in"));
    QCOMPARE(child<QDoubleSpinBox>(*dialog, "pageWidth")->value(), 3.0);
    const render::ExportOptions options = dialog->options();
    QCOMPARE(options.pageWidth, 216.0);
    QCOMPARE(options.dpi, 40.0);
    QVERIFY(!options.background);
    QVERIFY(!options.bezier);
}

void TestExportDialog::copyAsSvgPutsSvgOnTheClipboard()
{
    QGuiApplication::clipboard()->clear();
    const QString error = app::copyAsSvg(testDrawing());
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const QMimeData* mime = QGuiApplication::clipboard()->mimeData();
    QVERIFY(mime);
    QVERIFY(mime->hasFormat(QStringLiteral("image/svg+xml")));
    const QByteArray svgBytes = mime->data(QStringLiteral("image/svg+xml"));
    QCOMPARE(mime->text(), QString::fromUtf8(svgBytes));

    const QString file = path(QStringLiteral("clipboard.svg"));
    QVERIFY(test::writeFile(file, svgBytes));
    const test::ParsedSvg svg = test::parseSvg(file);
    QVERIFY2(svg.error.isEmpty(), qPrintable(svg.error));
    QCOMPARE(visiblePathCount(svg), kVisibleRegions);
}

QTEST_MAIN(TestExportDialog)
#include "tst_exportdialog.moc"
