#include "app/CombToolBar.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QSpinBox>

namespace vf::app {

CombToolBar::CombToolBar(QWidget* parent)
    : QToolBar(tr("Comb"), parent)
    , m_tines(new QSpinBox(this))
    , m_spacing(new QDoubleSpinBox(this))
    , m_sharpness(new QDoubleSpinBox(this))
{
    setObjectName(QStringLiteral("combOptions"));
    m_tines->setObjectName(QStringLiteral("combTines"));
    m_tines->setRange(1, model::limits::maxTines);
    m_tines->setValue(8);
    m_spacing->setObjectName(QStringLiteral("combSpacing"));
    m_spacing->setDecimals(3);
    m_spacing->setRange(0.005, 1.0);
    m_spacing->setSingleStep(0.01);
    m_spacing->setValue(0.08);
    m_spacing->setToolTip(tr("Between neighbouring tines, in canvas units"));
    m_sharpness->setObjectName(QStringLiteral("combSharpness"));
    m_sharpness->setDecimals(3);
    m_sharpness->setRange(0.002, 0.2);
    m_sharpness->setSingleStep(0.005);
    m_sharpness->setValue(0.02);
    m_sharpness->setToolTip(tr("How near a tine its pull has halved: smaller, sharper points"));
    addWidget(new QLabel(tr(" Tines "), this));
    addWidget(m_tines);
    addWidget(new QLabel(tr(" Spacing "), this));
    addWidget(m_spacing);
    addWidget(new QLabel(tr(" Sharpness "), this));
    addWidget(m_sharpness);
    connect(m_tines, &QSpinBox::valueChanged, this, &CombToolBar::changed);
    connect(m_spacing, &QDoubleSpinBox::valueChanged, this, &CombToolBar::changed);
}

int CombToolBar::tines() const { return m_tines->value(); }

double CombToolBar::spacing() const { return m_spacing->value(); }

model::CombStroke CombToolBar::comb(sim::Vec2 from, sim::Vec2 to) const
{
    model::CombStroke c;
    c.mode = model::CombStroke::Mode::Exact;
    c.from = from;
    c.to = to;
    c.tines = tines();
    c.spacing = spacing();
    c.sharpness = m_sharpness->value();
    return c;
}

} // namespace vf::app
