#pragma once
// The Regions dock: the document's regions, the topmost first. Rename in place, recolour, hide,
// reorder (drag or Raise/Lower), duplicate and delete (the Delete and Duplicate actions, also in
// the list's context menu); the current row is the selected region, which the canvas outlines.
#include "model/Document.h"
#include "model/RegionListModel.h"

#include <QDockWidget>

class QAction;
class QListView;

namespace vf::app {

class SimulationController;

class RegionsDock final : public QDockWidget {
    Q_OBJECT

public:
    RegionsDock(model::Document& document, model::RegionListModel& model, SimulationController& simulation,
                QWidget* parent);

    QListView& view() { return *m_view; }
    QAction* deleteAction() const { return m_delete; }
    QAction* duplicateAction() const { return m_duplicate; }

    // Makes the region (by simulation index) the current row; -1 clears the selection.
    void selectRegion(int simIndex);

signals:
    // The selected region by simulation index, -1 for none.
    void selectedRegionChanged(int simIndex);
    // A one-line reason an action was refused, for the status bar.
    void refused(const QString& reason);

private:
    // Index into Document::regions() of the current row, or -1.
    int currentRegion() const;
    void deleteCurrent();
    void duplicateCurrent();
    void recolourCurrent();
    void raiseCurrent(int by);
    void announceSelection();
    void fitRows();

    model::Document& m_document;
    model::RegionListModel& m_model;
    SimulationController& m_simulation;
    QListView* m_view;
    QAction* m_delete;
    QAction* m_duplicate;
};

} // namespace vf::app
