#include "model/RegionListModel.h"

#include "model/Document.h"

#include <QMimeData>

namespace vf::model {

namespace {

const QString rowMimeType = QStringLiteral("application/x-vectorfluid-region-row");

} // namespace

RegionListModel::RegionListModel(Document& document, QObject* parent)
    : QAbstractListModel(parent)
    , m_document(document)
{
    connect(&document, &Document::regionsAboutToBeReset, this, &RegionListModel::beginResetModel);
    connect(&document, &Document::regionsReset, this, &RegionListModel::endResetModel);
    connect(&document, &Document::regionAboutToMove, this, [this](int from, int to) {
        // Rows run top first; Qt's destination is the row the moved one goes before, counted
        // before the move.
        const int source = rowOf(from), target = rowOf(to);
        beginMoveRows({}, source, source, {}, target > source ? target + 1 : target);
    });
    connect(&document, &Document::regionMoved, this, &RegionListModel::endMoveRows);
    connect(&document, &Document::regionChanged, this, [this](int i) {
        const QModelIndex changed = index(rowOf(i));
        emit dataChanged(changed, changed);
    });
}

int RegionListModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_document.regions().size());
}

QVariant RegionListModel::data(const QModelIndex& index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const RegionLook& look = m_document.regions()[regionIndex(index.row())];
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        return look.name;
    case Qt::DecorationRole:
    case ColorRole:
        return look.color;
    case Qt::CheckStateRole:
        return look.visible ? Qt::Checked : Qt::Unchecked;
    case Qt::ToolTipRole:
        return tr("%1 — %2").arg(look.name, look.color.name(QColor::HexArgb));
    default:
        return {};
    }
}

bool RegionListModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return false;
    const int region = regionIndex(index.row());
    switch (role) {
    case Qt::EditRole:
        return m_document.setRegionName(region, value.toString());
    case ColorRole:
        return m_document.setRegionColor(region, value.value<QColor>());
    case Qt::CheckStateRole:
        return m_document.setRegionVisible(region, value.toInt() == Qt::Checked);
    default:
        return false;
    }
}

Qt::ItemFlags RegionListModel::flags(const QModelIndex& index) const
{
    if (!index.isValid())
        return Qt::ItemIsDropEnabled;
    return Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsEditable | Qt::ItemIsUserCheckable
        | Qt::ItemIsDragEnabled | Qt::ItemNeverHasChildren;
}

bool RegionListModel::moveRows(const QModelIndex& sourceParent, int sourceRow, int count,
                               const QModelIndex& destinationParent, int destinationChild)
{
    // One region at a time: a move is one command. `destinationChild` is the row the region is
    // put before, counted before the move, as QAbstractItemModel::moveRows has it.
    if (sourceParent.isValid() || destinationParent.isValid() || count != 1)
        return false;
    const int targetRow = destinationChild > sourceRow ? destinationChild - 1 : destinationChild;
    if (targetRow < 0 || targetRow >= rowCount() || sourceRow < 0 || sourceRow >= rowCount())
        return false;
    return m_document.moveRegion(regionIndex(sourceRow), regionIndex(targetRow));
}

QStringList RegionListModel::mimeTypes() const
{
    return {rowMimeType};
}

QMimeData* RegionListModel::mimeData(const QModelIndexList& indexes) const
{
    if (indexes.size() != 1)
        return nullptr;
    auto* data = new QMimeData;
    data->setData(rowMimeType, QByteArray::number(indexes.front().row()));
    return data;
}

bool RegionListModel::canDropMimeData(const QMimeData* data, Qt::DropAction action, int, int, const QModelIndex&) const
{
    return action == Qt::MoveAction && data && data->hasFormat(rowMimeType);
}

bool RegionListModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                                   const QModelIndex& parent)
{
    if (!canDropMimeData(data, action, row, column, parent))
        return false;
    bool ok = false;
    const int source = data->data(rowMimeType).toInt(&ok);
    if (!ok)
        return false;
    // Dropped onto an item: before it; into empty space below the rows: at the bottom.
    const int before = row >= 0 ? row : (parent.isValid() ? parent.row() : rowCount());
    moveRows({}, source, 1, {}, before);
    // The move is done; returning false keeps the view from also removing the dragged row.
    return false;
}

} // namespace vf::model
