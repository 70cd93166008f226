#include "app/GatherDialog.h"

#include "model/SvgImport.h"
#include "model/TextOutlines.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPainterPath>
#include <QPixmap>
#include <QPushButton>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vf::app {

namespace {

// Outlines only feed a raster of the fluid grid: a spacing far below any grid's cell is plenty.
constexpr double kOutlineSpacing = 0.002;

QDoubleSpinBox* numberBox(double value, double minimum, double maximum, const QString& suffix, const char* name)
{
    auto* box = new QDoubleSpinBox;
    box->setObjectName(QLatin1String(name));
    box->setRange(minimum, maximum);
    box->setDecimals(1);
    box->setValue(value);
    box->setSuffix(suffix);
    return box;
}

// The target's shapes on the canvas, `side` pixels along its longer side.
QPixmap preview(const std::vector<std::vector<sim::Polygon>>& target, const model::Canvas& canvas, int side)
{
    const double scale = side / std::max(canvas.width, canvas.height);
    QPixmap picture(int(std::ceil(canvas.width * scale)), int(std::ceil(canvas.height * scale)));
    picture.fill(canvas.background);
    QPainter painter(&picture);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.scale(scale, scale);
    for (const std::vector<sim::Polygon>& shape : target) {
        QPainterPath path;
        path.setFillRule(Qt::OddEvenFill);
        for (const sim::Polygon& contour : shape) {
            QPolygonF polygon;
            for (const sim::Vec2& p : contour)
                polygon << QPointF(p.x, p.y);
            path.addPolygon(polygon);
            path.closeSubpath();
        }
        painter.fillPath(path, QColor(0x26, 0x46, 0x53));
    }
    return picture;
}

} // namespace

std::vector<sim::Polygon> fittedText(const QString& text, const QFont& font, const model::Canvas& canvas)
{
    std::vector<sim::Polygon> contours = model::textContours(text, font, {0.0, 0.0}, 1.0, kOutlineSpacing);
    if (contours.empty())
        return {};
    sim::Vec2 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const sim::Polygon& c : contours)
        for (const sim::Vec2& p : c)
            lo = glm::min(lo, p), hi = glm::max(hi, p);
    const sim::Vec2 size = hi - lo;
    const double scale = std::min(0.84 * canvas.width / size.x, 0.6 * canvas.height / size.y);
    const sim::Vec2 middle = 0.5 * (lo + hi), centre(0.5 * canvas.width, 0.5 * canvas.height);
    for (sim::Polygon& c : contours)
        for (sim::Vec2& p : c)
            p = centre + scale * (p - middle);
    return contours;
}

GatherDialog::GatherDialog(const model::Canvas& canvas, std::vector<RegionOutline> regions, QWidget* parent)
    : QDialog(parent)
    , m_canvas(canvas)
    , m_regions(std::move(regions))
{
    setWindowTitle(tr("Gather Into"));
    m_kind = new QComboBox;
    m_kind->setObjectName(QStringLiteral("gatherTarget"));
    m_kind->addItem(tr("Text"));
    for (const RegionOutline& r : m_regions)
        m_kind->addItem(tr("Region: %1").arg(r.name));
    m_kind->addItem(tr("SVG file"));

    m_text = new QLineEdit(QStringLiteral("INK"));
    m_text->setObjectName(QStringLiteral("gatherText"));
    m_font = new QFontComboBox;
    m_font->setObjectName(QStringLiteral("gatherFont"));
    m_font->setCurrentFont(QFont(QStringLiteral("DejaVu Sans")));
    m_bold = new QCheckBox(tr("Bold"));
    m_bold->setObjectName(QStringLiteral("gatherBold"));
    m_bold->setChecked(true);
    m_file = new QLineEdit;
    m_file->setObjectName(QStringLiteral("gatherFile"));
    auto* browseButton = new QPushButton(tr("Browse…"));
    m_fileRow = new QHBoxLayout;
    m_fileRow->addWidget(m_file);
    m_fileRow->addWidget(browseButton);

    m_duration = numberBox(m_choice.duration, 0.1, 600.0, tr(" s"), "gatherDuration");
    m_duration->setToolTip(tr("Seconds of simulated time the fluid is driven"));
    m_strength = numberBox(m_choice.drive.strength, 0.0, 100000.0, {}, "gatherStrength");
    m_strength->setToolTip(tr("How hard the ink is drawn in (a spring constant, 1/s²)"));
    m_gathering = numberBox(m_choice.drive.gathering, 0.0, 1000.0, {}, "gatherGathering");
    m_gathering->setToolTip(tr("How hard the ink is drawn into the target's core, pushing water out (canvas units/s²)"));
    m_preview = new QLabel;
    m_preview->setObjectName(QStringLiteral("gatherPreview"));
    m_preview->setFrameShape(QFrame::Box);
    m_summary = new QLabel;
    m_summary->setObjectName(QStringLiteral("gatherSummary"));
    m_summary->setWordWrap(true);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);

    m_form = new QFormLayout(this);
    m_form->addRow(tr("Target:"), m_kind);
    m_form->addRow(tr("Text:"), m_text);
    m_form->addRow(tr("Font:"), m_font);
    m_form->addRow({}, m_bold);
    m_form->addRow(tr("File:"), m_fileRow);
    m_form->addRow(tr("Duration:"), m_duration);
    m_form->addRow(tr("Strength:"), m_strength);
    m_form->addRow(tr("Gathering:"), m_gathering);
    m_form->addRow(tr("Preview:"), m_preview);
    m_form->addRow(m_summary);
    m_form->addRow(m_buttons);

    connect(m_kind, &QComboBox::currentIndexChanged, this, &GatherDialog::update);
    connect(m_text, &QLineEdit::textChanged, this, &GatherDialog::update);
    connect(m_font, &QFontComboBox::currentFontChanged, this, &GatherDialog::update);
    connect(m_bold, &QCheckBox::toggled, this, &GatherDialog::update);
    connect(m_file, &QLineEdit::editingFinished, this, &GatherDialog::update);
    connect(browseButton, &QPushButton::clicked, this, &GatherDialog::browse);
    connect(m_duration, &QDoubleSpinBox::valueChanged, this, &GatherDialog::update);
    connect(m_strength, &QDoubleSpinBox::valueChanged, this, &GatherDialog::update);
    connect(m_gathering, &QDoubleSpinBox::valueChanged, this, &GatherDialog::update);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    update();
}

void GatherDialog::browse()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Gather into an SVG file"), m_file->text(),
                                                      tr("SVG files (*.svg)"));
    if (!path.isEmpty()) {
        m_file->setText(path);
        update();
    }
}

QString GatherDialog::outlineTarget()
{
    m_choice.target.clear();
    const int kind = m_kind->currentIndex();
    if (kind == 0) {
        QFont font = m_font->currentFont();
        font.setBold(m_bold->isChecked());
        m_choice.name = m_text->text().simplified();
        if (std::vector<sim::Polygon> text = fittedText(m_text->text(), font, m_canvas); !text.empty())
            m_choice.target.push_back(std::move(text));
        return m_choice.target.empty() ? tr("Type the text to gather into.") : QString();
    }
    if (kind <= int(m_regions.size())) {
        const RegionOutline& region = m_regions[std::size_t(kind - 1)];
        m_choice.name = region.name;
        m_choice.target.push_back(region.contours);
        return region.contours.empty() ? tr("The region has no ink.") : QString();
    }
    if (m_file->text().isEmpty())
        return tr("Choose an SVG file.");
    const model::SvgImport svg = model::importSvgFile(m_file->text(), m_canvas.width, m_canvas.height, kOutlineSpacing);
    if (!svg.ok())
        return svg.error;
    m_choice.name = QFileInfo(m_file->text()).fileName();
    for (const model::ImportedShape& shape : svg.shapes)
        m_choice.target.push_back(shape.contours);
    return m_choice.target.empty() ? tr("The file has no filled shapes.") : QString();
}

void GatherDialog::update()
{
    const int kind = m_kind->currentIndex();
    const bool text = kind == 0, file = kind == m_kind->count() - 1;
    for (QWidget* w : {static_cast<QWidget*>(m_text), static_cast<QWidget*>(m_font), static_cast<QWidget*>(m_bold)})
        m_form->setRowVisible(w, text);
    m_form->setRowVisible(m_fileRow, file);
    m_choice.duration = m_duration->value();
    m_choice.drive.strength = m_strength->value();
    m_choice.drive.gathering = m_gathering->value();
    const QString problem = outlineTarget();
    m_summary->setText(problem.isEmpty()
                           ? tr("The fluid draws the ink into %1 for %2 s, then flows on freely. One step of the history.")
                                 .arg(m_choice.name)
                                 .arg(m_choice.duration)
                           : problem);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
    m_preview->setPixmap(preview(m_choice.target, m_canvas, 160));
}

} // namespace vf::app
