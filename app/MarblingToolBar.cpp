#include "app/MarblingToolBar.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSpinBox>

namespace vf::app {

namespace {

const char* prefixOf(MarblingToolBar::Kind kind)
{
    switch (kind) {
    case MarblingToolBar::Kind::Comb:
        return "comb";
    case MarblingToolBar::Kind::CircularComb:
        return "circularComb";
    case MarblingToolBar::Kind::Swirl:
        break;
    }
    return "swirl";
}

} // namespace

MarblingToolBar::MarblingToolBar(Kind kind, QWidget* parent)
    : QToolBar(parent)
    , m_kind(kind)
    , m_prefix(QLatin1String(prefixOf(kind)))
    , m_mode(new QComboBox(this))
{
    setWindowTitle(kind == Kind::Comb ? tr("Comb") : kind == Kind::CircularComb ? tr("Circular comb") : tr("Swirl"));
    setObjectName(m_prefix + QStringLiteral("Options"));
    m_mode->setObjectName(m_prefix + QStringLiteral("Mode"));
    m_mode->addItem(tr("Exact"));
    m_mode->addItem(tr("In the water"));
    m_mode->setToolTip(tr("Exact: the ink is moved at once by an area-keeping map. In the water: the "
                          "tool's pens push the water while you drag"));
    addWidget(m_mode);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &MarblingToolBar::changed);
    if (kind == Kind::Swirl)
        return;

    const bool straight = kind == Kind::Comb;
    m_tines = addCount(tr("Tines"), "Tines", straight ? 8 : 5);
    m_spacing = addLength(tr("Spacing"), "Spacing", 0.005, 1.0, straight ? 0.08 : 0.05,
                          straight ? tr("Between neighbouring tines, in canvas units")
                                   : tr("Between neighbouring tines' circles, in canvas units"));
    if (!straight)
        m_innerRadius = addLength(tr("Inner radius"), "InnerRadius", 0.005, 2.0, 0.05,
                                  tr("The radius of the first tine's circle about the centre, in canvas units"));
    m_sharpness = addLength(tr("Sharpness"), "Sharpness", 0.002, 0.2, 0.02,
                            tr("How near a tine its pull has halved: smaller, sharper points (exact)"));
    if (straight) {
        m_amplitude = addLength(tr("Wave"), "Amplitude", 0.0, 0.5, 0.0,
                                tr("How far the tines wave to either side, in canvas units; 0: straight (exact)"));
        m_wavelength = addLength(tr("Wavelength"), "Wavelength", 0.01, 2.0, 0.2,
                                 tr("The length of one wave along the stroke, in canvas units (exact)"));
    }
}

QSpinBox* MarblingToolBar::addCount(const QString& label, const char* name, int value)
{
    auto* box = new QSpinBox(this);
    box->setObjectName(m_prefix + QLatin1String(name));
    box->setRange(1, model::limits::maxTines);
    box->setValue(value);
    addWidget(new QLabel(QStringLiteral(" %1 ").arg(label), this));
    addWidget(box);
    connect(box, &QSpinBox::valueChanged, this, &MarblingToolBar::changed);
    return box;
}

QDoubleSpinBox* MarblingToolBar::addLength(const QString& label, const char* name, double lowest, double highest,
                                           double value, const QString& toolTip)
{
    auto* box = new QDoubleSpinBox(this);
    box->setObjectName(m_prefix + QLatin1String(name));
    box->setDecimals(3);
    box->setRange(lowest, highest);
    box->setSingleStep(0.005);
    box->setValue(value);
    box->setToolTip(toolTip);
    addWidget(new QLabel(QStringLiteral(" %1 ").arg(label), this));
    addWidget(box);
    connect(box, &QDoubleSpinBox::valueChanged, this, &MarblingToolBar::changed);
    return box;
}

model::Stroke MarblingToolBar::options() const
{
    const auto mode = m_mode->currentIndex() == 0 ? model::CombStroke::Mode::Exact : model::CombStroke::Mode::Water;
    switch (m_kind) {
    case Kind::Comb: {
        model::CombStroke comb;
        comb.mode = mode;
        comb.tines = m_tines->value();
        comb.spacing = m_spacing->value();
        comb.sharpness = m_sharpness->value();
        comb.amplitude = m_amplitude->value();
        comb.wavelength = m_wavelength->value();
        return comb;
    }
    case Kind::CircularComb: {
        model::CircularCombStroke comb;
        comb.mode = mode;
        comb.innerRadius = m_innerRadius->value();
        comb.tines = m_tines->value();
        comb.spacing = m_spacing->value();
        comb.sharpness = m_sharpness->value();
        return comb;
    }
    case Kind::Swirl:
        break;
    }
    model::SwirlStroke swirl;
    swirl.mode = mode;
    return swirl;
}

} // namespace vf::app
