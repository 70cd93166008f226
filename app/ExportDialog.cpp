#include "app/ExportDialog.h"

#include "app/Folders.h"
#include "app/MemoryBudget.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSpinBox>

#include <cmath>

namespace vf::app {
namespace {

struct FormatEntry {
    const char* name;
    const char* suffix;
};
constexpr FormatEntry kFormats[] = {{"SVG", "svg"}, {"PDF", "pdf"}, {"EPS", "eps"}, {"PNG", "png"}};

constexpr double kPointsPerInch = 72.0;
constexpr double kMillimetresPerInch = 25.4;
const QString kPixels = QStringLiteral("px");

// The path with the format's suffix: an export suffix already there is replaced, anything else
// (no suffix, or a dot in a plain name) is kept and the suffix appended.
QString pathForFormat(const QString& path, const QString& suffix)
{
    QString base = path;
    if (render::isExportSuffix(path))
        base.chop(QFileInfo(path).suffix().size() + 1);
    return base + u'.' + suffix;
}

// Explicit names, so that the settings do not depend on what main() set up.
QSettings appSettings()
{
    return QSettings(QStringLiteral("vectorfluid"), QStringLiteral("vectorfluid"));
}

} // namespace

ExportDialog::ExportDialog(model::Drawing drawing, QWidget* parent) : QDialog(parent), m_drawing(std::move(drawing))
{
    setWindowTitle(tr("Export"));

    m_path = new QLineEdit;
    m_path->setObjectName(QStringLiteral("path"));
    auto* browse = new QPushButton(tr("Browse…"));
    browse->setObjectName(QStringLiteral("browse"));
    browse->setAutoDefault(false);  // Enter in a field exports; it never opens the file dialog
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path, 1);
    pathRow->addWidget(browse);

    m_format = new QComboBox;
    m_format->setObjectName(QStringLiteral("format"));
    for (const FormatEntry& format : kFormats)
        m_format->addItem(QString::fromLatin1(format.name), QString::fromLatin1(format.suffix));

    m_pageWidthBox = new QDoubleSpinBox;
    m_pageWidthBox->setObjectName(QStringLiteral("pageWidth"));
    m_pageWidthBox->setRange(0.01, 1e6);
    m_pageWidthBox->setDecimals(2);
    m_unit = new QComboBox;
    m_unit->setObjectName(QStringLiteral("unit"));
    for (const QString& unit : {QStringLiteral("pt"), QStringLiteral("mm"), QStringLiteral("in"), kPixels})
        m_unit->addItem(unit, unit);
    auto* widthRow = new QHBoxLayout;
    widthRow->addWidget(m_pageWidthBox, 1);
    widthRow->addWidget(m_unit);
    m_pageHeightBox = new QDoubleSpinBox;
    m_pageHeightBox->setObjectName(QStringLiteral("pageHeight"));
    m_pageHeightBox->setRange(0.01, 1e6);
    m_pageHeightBox->setDecimals(2);
    m_keepAspect = new QCheckBox(tr("Canvas proportions"));
    m_keepAspect->setObjectName(QStringLiteral("keepAspect"));
    m_keepAspect->setToolTip(tr("The height follows the width; off, the canvas is centred on a page of any size"));
    auto* heightRow = new QHBoxLayout;
    heightRow->addWidget(m_pageHeightBox, 1);
    heightRow->addWidget(m_keepAspect);

    m_dpi = new QSpinBox;
    m_dpi->setObjectName(QStringLiteral("dpi"));
    m_dpi->setRange(1, 4800);
    m_dpi->setSuffix(tr(" dpi"));

    m_background = new QCheckBox(tr("Paint the canvas background"));
    m_background->setObjectName(QStringLiteral("background"));
    m_curves = new QComboBox;
    m_curves->setObjectName(QStringLiteral("curves"));
    m_curves->addItem(tr("Bézier curves"), true);
    m_curves->addItem(tr("Exact polyline"), false);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel);
    QPushButton* exportButton = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    exportButton->setObjectName(QStringLiteral("export"));

    auto* form = new QFormLayout(this);
    form->addRow(tr("File:"), pathRow);
    form->addRow(tr("Format:"), m_format);
    form->addRow(tr("Page width:"), widthRow);
    form->addRow(tr("Page height:"), heightRow);
    form->addRow(tr("Resolution:"), m_dpi);
    form->addRow(tr("Background:"), m_background);
    form->addRow(tr("Curves:"), m_curves);
    form->addRow(buttons);
    // Only once the button is in the dialog: setDefault() tells the dialog, which otherwise makes
    // the first button (Cancel) the one Enter presses.
    exportButton->setDefault(true);

    restoreSettings();
    // Wide enough for the whole path, as far as the screen allows.
    const int pathWidth = m_path->fontMetrics().horizontalAdvance(m_path->text()) + 4 * m_path->fontMetrics().averageCharWidth();
    m_path->setMinimumWidth(std::min(pathWidth, screen()->availableGeometry().width() / 2));

    connect(browse, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(m_path, &QLineEdit::textChanged, this, &ExportDialog::pathEdited);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportDialog::formatPicked);
    connect(m_pageWidthBox, &QDoubleSpinBox::valueChanged, this, &ExportDialog::pageWidthEdited);
    connect(m_pageHeightBox, &QDoubleSpinBox::valueChanged, this, &ExportDialog::pageHeightEdited);
    connect(m_keepAspect, &QCheckBox::toggled, this, &ExportDialog::keepAspectToggled);
    connect(m_unit, &QComboBox::currentIndexChanged, this, &ExportDialog::unitPicked);
    connect(m_dpi, &QSpinBox::valueChanged, this, &ExportDialog::dpiEdited);
    connect(buttons, &QDialogButtonBox::accepted, this, &ExportDialog::exportFile);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    pathEdited();
    keepAspectToggled(m_keepAspect->isChecked());
}

QString ExportDialog::filePath() const
{
    return pathForFormat(m_path->text().trimmed(), m_format->currentData().toString());
}

render::ExportOptions ExportDialog::options() const
{
    render::ExportOptions options;
    options.bezier = m_curves->currentData().toBool();
    options.pageWidth = m_pageWidth;
    options.pageHeight = m_keepAspect->isChecked() ? 0.0 : m_pageHeight;
    options.dpi = m_dpi->value();
    options.background = m_background->isChecked();
    return options;
}

void ExportDialog::browse()
{
    QStringList filters;
    for (const FormatEntry& format : kFormats)
        filters << QStringLiteral("%1 (*.%2)").arg(QLatin1String(format.name), QLatin1String(format.suffix));
    QFileDialog dialog(this, tr("Export to"), m_path->text());
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setNameFilters(filters);
    dialog.selectNameFilter(filters.value(m_format->currentIndex()));
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return;
    const QString chosen = dialog.selectedFiles().constFirst();
    const qsizetype filter = std::max<qsizetype>(0, filters.indexOf(dialog.selectedNameFilter()));
    m_path->setText(render::isExportSuffix(chosen) ? chosen
                                                   : pathForFormat(chosen, QString::fromLatin1(kFormats[filter].suffix)));
}

void ExportDialog::exportFile()
{
    if (m_path->text().trimmed().isEmpty()) {
        m_lastError = tr("Choose a file to export to.");
    } else if (m_lastError = checkPngMemory(); m_lastError.isEmpty()) {
        m_path->setText(filePath());
        QGuiApplication::setOverrideCursor(Qt::WaitCursor);
        m_lastError = render::exportDrawing(m_drawing, filePath(), options());
        QGuiApplication::restoreOverrideCursor();
    }
    if (!m_lastError.isEmpty())
        return showError();
    saveSettings();
    accept();
}

// A PNG is painted whole in memory: one the memory available cannot hold, by the estimate with
// which `vectorfluid render` refuses a --dpi, is refused before anything is allocated (it would
// otherwise swap the machine to a halt, or fail only after a long wait).
QString ExportDialog::checkPngMemory() const
{
    if (m_format->currentData().toString() != QLatin1String("png"))
        return {};
    const render::RasterSize pixels = render::pngPixels(m_drawing, options());
    const double available = availableMemory();
    if (available <= 0 || pngBytes(pixels) <= available)
        return {};
    return tr("A %1 x %2 pixel PNG (%3 dpi) needs about %4 of memory, more than the %5 available: "
              "lower the resolution or the page size.")
        .arg(pixels.width, 0, 'f', 0)
        .arg(pixels.height, 0, 'f', 0)
        .arg(m_dpi->value())
        .arg(bytesText(pngBytes(pixels)), bytesText(available));
}

// Window-modal but not blocking (open(), not exec()), so that nothing waits on the box.
void ExportDialog::showError()
{
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Export failed"), m_lastError, QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("exportError"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void ExportDialog::formatPicked()
{
    if (!m_path->text().trimmed().isEmpty())
        m_path->setText(filePath());
    updateEnabled();
}

void ExportDialog::pathEdited()
{
    const int format = m_format->findData(QFileInfo(m_path->text().trimmed()).suffix().toLower());
    if (format >= 0) {
        const QSignalBlocker blocker(m_format); // the suffix is already right
        m_format->setCurrentIndex(format);
    }
    updateEnabled();
}

void ExportDialog::pageWidthEdited()
{
    m_pageWidth = m_pageWidthBox->value() * pointsPerUnit();
    if (m_keepAspect->isChecked())
        followCanvasAspect();
}

void ExportDialog::pageHeightEdited()
{
    m_pageHeight = m_pageHeightBox->value() * pointsPerUnit();
}

void ExportDialog::keepAspectToggled(bool keep)
{
    m_pageHeightBox->setEnabled(!keep);
    if (keep)
        followCanvasAspect();
    else
        showPageSize();
}

void ExportDialog::followCanvasAspect()
{
    m_pageHeight = m_drawing.width > 0 ? m_pageWidth * m_drawing.height / m_drawing.width : m_pageWidth;
    showPageSize();
}

// The page keeps its size; only the numbers shown change.
void ExportDialog::unitPicked()
{
    showPageSize();
    updateEnabled();
}

void ExportDialog::showPageSize()
{
    const QSignalBlocker widthBlocker(m_pageWidthBox), heightBlocker(m_pageHeightBox);
    m_pageWidthBox->setValue(m_pageWidth / pointsPerUnit());
    m_pageHeightBox->setValue(m_pageHeight / pointsPerUnit());
}

// A size in pixels keeps its pixel counts; the page's size in points follows the resolution.
void ExportDialog::dpiEdited()
{
    if (m_unit->currentData().toString() != kPixels)
        return;
    pageWidthEdited();
    if (!m_keepAspect->isChecked())
        pageHeightEdited();
}

void ExportDialog::updateEnabled()
{
    m_dpi->setEnabled(m_format->currentData().toString() == QLatin1String("png") || m_unit->currentData().toString() == kPixels);
}

double ExportDialog::pointsPerUnit() const
{
    const QString unit = m_unit->currentData().toString();
    if (unit == QLatin1String("mm"))
        return kPointsPerInch / kMillimetresPerInch;
    if (unit == QLatin1String("in"))
        return kPointsPerInch;
    if (unit == kPixels)
        return kPointsPerInch / m_dpi->value();
    return 1.0;
}

// Runs before the widgets' signals are connected: each stored value goes through its widget,
// which clamps whatever an old or hand-edited settings file holds.
void ExportDialog::restoreSettings()
{
    QSettings settings = appSettings();
    settings.beginGroup(QStringLiteral("export"));
    const render::ExportOptions defaults;
    // The last path, while its folder is still there.
    const QString last = settings.value(QStringLiteral("path")).toString();
    m_path->setText(!last.isEmpty() && QFileInfo(last).absoluteDir().exists()
                        ? last : QDir(documentsFolder()).filePath(QStringLiteral("picture.svg")));
    m_dpi->setValue(settings.value(QStringLiteral("dpi"), defaults.dpi).toInt());
    m_unit->setCurrentIndex(std::max(0, m_unit->findData(settings.value(QStringLiteral("unit")).toString())));
    m_pageWidthBox->setValue(settings.value(QStringLiteral("pageWidth"), defaults.pageWidth).toDouble() / pointsPerUnit());
    m_pageWidth = m_pageWidthBox->value() * pointsPerUnit();
    m_pageHeight = settings.value(QStringLiteral("pageHeight"), m_pageWidth).toDouble();
    m_keepAspect->setChecked(settings.value(QStringLiteral("keepAspect"), true).toBool());
    m_background->setChecked(settings.value(QStringLiteral("background"), defaults.background).toBool());
    m_curves->setCurrentIndex(m_curves->findData(settings.value(QStringLiteral("bezier"), defaults.bezier).toBool()));
}

void ExportDialog::saveSettings() const
{
    QSettings settings = appSettings();
    settings.beginGroup(QStringLiteral("export"));
    const render::ExportOptions chosen = options();
    settings.setValue(QStringLiteral("path"), filePath());
    settings.setValue(QStringLiteral("dpi"), m_dpi->value());
    settings.setValue(QStringLiteral("unit"), m_unit->currentData());
    settings.setValue(QStringLiteral("pageWidth"), chosen.pageWidth);
    settings.setValue(QStringLiteral("pageHeight"), m_pageHeight);
    settings.setValue(QStringLiteral("keepAspect"), m_keepAspect->isChecked());
    settings.setValue(QStringLiteral("background"), chosen.background);
    settings.setValue(QStringLiteral("bezier"), chosen.bezier);
}

} // namespace vf::app
