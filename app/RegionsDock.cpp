#include "app/RegionsDock.h"

#include "app/SimulationController.h"

#include <QAction>
#include <QColorDialog>
#include <QHBoxLayout>
#include <QListView>
#include <QMenu>
#include <QPushButton>
#include <QVBoxLayout>

#include <functional>

namespace vf::app {

namespace {

// Rows the list shows without scrolling when the window opens.
constexpr int kRowsShown = 8;

// Where a duplicate lands, as a fraction of the canvas width right and down of the original:
// enough to see that there are two.
constexpr double kDuplicateOffset = 0.02;

} // namespace

RegionsDock::RegionsDock(model::Document& document, model::RegionListModel& model, SimulationController& simulation,
                         QWidget* parent)
    : QDockWidget(tr("Regions"), parent)
    , m_document(document)
    , m_model(model)
    , m_simulation(simulation)
{
    setObjectName(QStringLiteral("regionsDock"));
    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    m_view = new QListView(content);
    m_view->setObjectName(QStringLiteral("regionView"));
    m_view->setModel(&m_model);
    m_view->setDragDropMode(QAbstractItemView::InternalMove);
    m_view->setDefaultDropAction(Qt::MoveAction);
    m_view->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::SelectedClicked);
    fitRows();
    layout->addWidget(m_view);

    m_delete = new QAction(tr("&Delete Region"), this);
    m_delete->setObjectName(QStringLiteral("deleteRegion"));
    m_delete->setShortcut(QKeySequence::Delete);
    connect(m_delete, &QAction::triggered, this, &RegionsDock::deleteCurrent);
    m_duplicate = new QAction(tr("D&uplicate Region"), this);
    m_duplicate->setObjectName(QStringLiteral("duplicateRegion"));
    m_duplicate->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    connect(m_duplicate, &QAction::triggered, this, &RegionsDock::duplicateCurrent);

    auto* buttons = new QHBoxLayout;
    const struct {
        QString text;
        const char* name;
        std::function<void()> action;
    } buttonList[] = {
        {tr("Colour…"), "recolour", [this] { recolourCurrent(); }},
        {tr("Raise"), "raise", [this] { raiseCurrent(1); }},
        {tr("Lower"), "lower", [this] { raiseCurrent(-1); }},
    };
    auto* menu = new QMenu(m_view);
    menu->addAction(m_duplicate);
    menu->addAction(m_delete);
    menu->addSeparator();
    for (const auto& b : buttonList) {
        auto* button = new QPushButton(b.text, content);
        button->setObjectName(QLatin1String(b.name));
        connect(button, &QPushButton::clicked, this, b.action);
        buttons->addWidget(button);
        menu->addAction(b.text, this, b.action);
    }
    layout->addLayout(buttons);
    setWidget(content);

    m_view->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_view, &QWidget::customContextMenuRequested, this, [this, menu](QPoint at) {
        const QModelIndex index = m_view->indexAt(at);
        if (!index.isValid())
            return;
        m_view->setCurrentIndex(index);
        menu->popup(m_view->viewport()->mapToGlobal(at));
    });
    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this, &RegionsDock::announceSelection);
    connect(&m_model, &QAbstractItemModel::modelReset, this, &RegionsDock::announceSelection);
    connect(&m_model, &QAbstractItemModel::modelReset, this, &RegionsDock::fitRows);
    connect(&m_model, &QAbstractItemModel::rowsMoved, this, &RegionsDock::announceSelection);
    announceSelection();
}

void RegionsDock::fitRows()
{
    // The delegate's own row height (swatch, check box, name) once there is a row to measure.
    const int row = m_model.rowCount() > 0 ? m_view->sizeHintForRow(0) : m_view->fontMetrics().height() + 8;
    m_view->setMinimumHeight(kRowsShown * row + 2 * m_view->frameWidth());
}

int RegionsDock::currentRegion() const
{
    const QModelIndex index = m_view->currentIndex();
    return index.isValid() ? m_model.regionIndex(index.row()) : -1;
}

void RegionsDock::announceSelection()
{
    const int region = currentRegion();
    m_delete->setEnabled(region >= 0);
    m_duplicate->setEnabled(region >= 0);
    emit selectedRegionChanged(region >= 0 ? m_document.regions()[std::size_t(region)].simIndex : -1);
}

void RegionsDock::selectRegion(int simIndex)
{
    const model::RegionTable& regions = m_document.regions();
    for (std::size_t i = 0; i < regions.size(); ++i) {
        if (regions[i].simIndex == simIndex) {
            m_view->setCurrentIndex(m_model.index(m_model.rowOf(int(i))));
            return;
        }
    }
    m_view->setCurrentIndex({});
    m_view->clearSelection();
}

void RegionsDock::deleteCurrent()
{
    const int region = currentRegion();
    if (region >= 0 && !m_document.deleteRegion(region))
        emit refused(tr("The scene's own drops are still landing; play on and delete again"));
}

void RegionsDock::duplicateCurrent()
{
    const int region = currentRegion();
    const auto frame = m_simulation.frame();
    if (region < 0 || !frame)
        return;
    const auto simIndex = std::size_t(m_document.regions()[std::size_t(region)].simIndex);
    if (simIndex >= frame->regions.size())
        return;
    std::vector<sim::Polygon> contours = frame->regions[simIndex];
    const sim::Vec2 offset(kDuplicateOffset * frame->width);
    for (sim::Polygon& contour : contours)
        for (sim::Vec2& p : contour)
            p += offset;
    if (!m_document.duplicateRegion(region, contours))
        emit refused(tr("The scene's own drops are still landing; play on and duplicate again"));
    else
        selectRegion(int(m_document.regions().size()) - 1);  // the copy, the newest simulation region
}

void RegionsDock::recolourCurrent()
{
    const QModelIndex index = m_view->currentIndex();
    if (!index.isValid())
        return;
    const QColor current = index.data(model::RegionListModel::ColorRole).value<QColor>();
    const QColor chosen = QColorDialog::getColor(current, this, tr("Region colour"), QColorDialog::ShowAlphaChannel);
    if (chosen.isValid())
        m_model.setData(index, chosen, model::RegionListModel::ColorRole);
}

void RegionsDock::raiseCurrent(int by)
{
    // Up the list is up the paint order.
    const QModelIndex index = m_view->currentIndex();
    if (!index.isValid())
        return;
    const int row = index.row();
    const int target = row - by;
    if (target < 0 || target >= m_model.rowCount())
        return;
    m_model.moveRows({}, row, 1, {}, by > 0 ? target : target + 1);  // the current row moves with it
}

} // namespace vf::app
