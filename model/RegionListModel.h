#pragma once
// The document's regions for a Qt item view (the Regions dock): one row per region, the topmost
// first as in any layer list. Name (editable), colour swatch, visibility check box, drag to
// reorder. Every edit goes through the document, so each is one undoable command.
#include <QAbstractListModel>

namespace vf::model {

class Document;

class RegionListModel final : public QAbstractListModel {
    Q_OBJECT

public:
    enum Role { ColorRole = Qt::UserRole + 1 };

    explicit RegionListModel(Document& document, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    bool moveRows(const QModelIndex& sourceParent, int sourceRow, int count, const QModelIndex& destinationParent,
                  int destinationChild) override;
    Qt::DropActions supportedDropActions() const override { return Qt::MoveAction; }
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                      const QModelIndex& parent) override;

    // Row ↔ index into Document::regions() (paint order, bottom first).
    int regionIndex(int row) const { return rowCount() - 1 - row; }
    int rowOf(int regionIndex) const { return rowCount() - 1 - regionIndex; }

private:
    Document& m_document;
};

} // namespace vf::model
