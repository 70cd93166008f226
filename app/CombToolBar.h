#pragma once
// The Comb tool's options: how many tines, how far apart, and how sharply each pulls (the
// sharpness u of the exact comb: the distance at which a tine's pull has halved). Shown while the
// Comb tool is picked.
#include "model/Scene.h"

#include <QToolBar>

class QDoubleSpinBox;
class QSpinBox;

namespace vf::app {

class CombToolBar final : public QToolBar {
    Q_OBJECT

public:
    explicit CombToolBar(QWidget* parent = nullptr);

    int tines() const;
    double spacing() const;
    // The exact comb drawn from `from` to `to` with these options (canvas units).
    model::CombStroke comb(sim::Vec2 from, sim::Vec2 to) const;

signals:
    void changed();

private:
    QSpinBox* m_tines;
    QDoubleSpinBox *m_spacing, *m_sharpness;
};

} // namespace vf::app
