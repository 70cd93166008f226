#include "app/PatternDialog.h"

#include "model/Patterns.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>

#include <cmath>
#include <limits>

namespace vf::app {

namespace {

using Kind = model::PatternStroke::Kind;
constexpr Kind kKinds[] = {Kind::Stone, Kind::GelGit, Kind::Chevron, Kind::Nonpareil, Kind::Bouquet};

QDoubleSpinBox* lengthBox(double value, double minimum, double maximum, const char* name, const QString& tip)
{
    auto* box = new QDoubleSpinBox;
    box->setObjectName(QLatin1String(name));
    box->setDecimals(3);
    box->setRange(minimum, maximum);
    box->setSingleStep(minimum);
    box->setValue(value);
    box->setToolTip(tip);
    return box;
}

} // namespace

PatternDialog::PatternDialog(const model::PatternStroke& pattern, const model::Canvas& canvas, QWidget* parent)
    : QDialog(parent)
    , m_start(pattern)
    , m_canvas(canvas)
    , m_kind(new QComboBox)
    , m_dropRadius(lengthBox(pattern.dropRadius, 0.005, 0.5, "patternDropRadius", tr("The stone's drops")))
    , m_spacing(lengthBox(pattern.spacing, 0.01, 0.5, "patternSpacing", tr("Between the gel-git's lines")))
    , m_fineSpacing(lengthBox(pattern.fineSpacing, 0.005, 0.2, "patternFineSpacing", tr("Between the nonpareil's tines")))
    , m_shift(lengthBox(pattern.shift, 0.005, 0.5, "patternShift", tr("How far a pass drags the ink at its tines")))
    , m_sharpness(lengthBox(pattern.sharpness, 0.001, 0.2, "patternSharpness",
                            tr("How near a tine its pull has halved")))
    , m_seed(new QSpinBox)
    , m_summary(new QLabel)
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel))
{
    setWindowTitle(tr("Pattern"));
    m_kind->setObjectName(QStringLiteral("patternKind"));
    for (Kind kind : kKinds)
        m_kind->addItem(model::patternName(kind));
    m_kind->setCurrentIndex(int(pattern.kind));
    m_seed->setObjectName(QStringLiteral("patternSeed"));
    m_seed->setRange(0, std::numeric_limits<int>::max());
    m_seed->setValue(int(std::min<std::uint64_t>(pattern.seed, std::numeric_limits<int>::max())));
    m_seed->setToolTip(tr("Where the stone's drops fall: the same seed, the same drops"));
    m_summary->setObjectName(QStringLiteral("patternSummary"));
    m_summary->setWordWrap(true);

    auto* form = new QFormLayout(this);
    form->addRow(tr("&Pattern:"), m_kind);
    form->addRow(tr("&Drop radius:"), m_dropRadius);
    form->addRow(tr("&Line spacing:"), m_spacing);
    form->addRow(tr("&Fine spacing:"), m_fineSpacing);
    form->addRow(tr("P&ull:"), m_shift);
    form->addRow(tr("S&harpness:"), m_sharpness);
    form->addRow(tr("S&eed:"), m_seed);
    form->addRow(m_summary);
    form->addRow(m_buttons);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_kind, &QComboBox::currentIndexChanged, this, &PatternDialog::updateSummary);
    connect(m_seed, &QSpinBox::valueChanged, this, &PatternDialog::updateSummary);
    for (QDoubleSpinBox* box : {m_dropRadius, m_spacing, m_fineSpacing, m_shift, m_sharpness})
        connect(box, &QDoubleSpinBox::valueChanged, this, &PatternDialog::updateSummary);
    updateSummary();
}

model::PatternStroke PatternDialog::pattern() const
{
    model::PatternStroke p = m_start;
    p.kind = kKinds[m_kind->currentIndex()];
    p.dropRadius = m_dropRadius->value();
    p.spacing = m_spacing->value();
    p.fineSpacing = m_fineSpacing->value();
    p.shift = m_shift->value();
    p.sharpness = m_sharpness->value();
    p.seed = std::uint64_t(m_seed->value());
    return p;
}

void PatternDialog::updateSummary()
{
    const model::PatternStroke p = pattern();
    const auto problem = model::patternProblem(p, m_canvas);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(!problem);
    if (problem) {
        m_summary->setText(problem->message);
        return;
    }
    const model::PatternSize size = model::patternSize(p, m_canvas);
    m_summary->setText(tr("Drops: %1, in %2 inks; then comb passes: %3. One step of the history.")
                           .arg(size.drops)
                           .arg(p.colors.size())
                           .arg(size.passes));
}

} // namespace vf::app
