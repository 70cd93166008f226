#pragma once
// The options of a marbling tool that is dragged on the canvas (Comb, Circular comb, Swirl), on a
// bar of their own shown while the tool is picked: whether it acts exactly or in the water, and
// for the combs how many tines, how far apart and how sharply each pulls (the sharpness u of the
// exact map: the distance at which a tine's pull has halved); the comb's tines may be waves, the
// circular comb's first circle has a radius.
#include "model/Scene.h"

#include <QToolBar>

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace vf::app {

class MarblingToolBar final : public QToolBar {
    Q_OBJECT

public:
    enum class Kind { Comb, CircularComb, Swirl };
    // Its widgets are named after the kind ("combTines", "circularCombMode", "swirlMode"...).
    explicit MarblingToolBar(Kind kind, QWidget* parent = nullptr);

    // The tool with these options and no place yet (the drag gives it one): a CombStroke,
    // CircularCombStroke or SwirlStroke.
    model::Stroke options() const;

signals:
    void changed();

private:
    QSpinBox* addCount(const QString& label, const char* name, int value);
    QDoubleSpinBox* addLength(const QString& label, const char* name, double lowest, double highest,
                              double value, const QString& toolTip);

    Kind m_kind;
    QString m_prefix;  // of the widgets' names
    QComboBox* m_mode;
    QSpinBox* m_tines = nullptr;
    QDoubleSpinBox *m_spacing = nullptr, *m_innerRadius = nullptr, *m_sharpness = nullptr;
    QDoubleSpinBox *m_amplitude = nullptr, *m_wavelength = nullptr;
};

} // namespace vf::app
