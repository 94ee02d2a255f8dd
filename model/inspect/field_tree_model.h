// FieldTreeModel: a frame's dev::Description as a tree for the inspector's detail pane — a
// field of depth d + 1 is a child of the nearest field before it with depth d (STYLE.md rule 7:
// the codecs describe, this only arranges). Owner: the inspector view; GUI thread only.
#pragma once

#include "core/field_span.h"
#include "core/local_text.h"

#include <QAbstractItemModel>
#include <vector>

namespace vt::model {

class FieldTreeModel : public QAbstractItemModel
{
    Q_OBJECT
public:
    enum Column { FieldColumn, BytesColumn, ValueColumn, MeaningColumn, ColumnCount };
    enum Role {
        OffsetRole = Qt::UserRole + 1, // int: first byte of the field
        LengthRole,                    // int: bytes covered (0 = explanatory row)
        KeyRole,                       // QString: the codec's stable key
    };

    explicit FieldTreeModel(QObject *parent = nullptr);

    // Replaces the tree (a model reset). Fields whose depth jumps by more than one hang under
    // the deepest open parent, so a codec's slip cannot break the tree.
    void setDescription(const vt::dev::Description &description);
    void clear();
    const vt::dev::Description &description() const { return m_description; }
    void setLanguage(vt::dev::Language language);
    vt::dev::Language language() const { return m_language; }

    // The deepest field whose bytes cover `offset` (the hex view's click); invalid when none.
    QModelIndex indexForByte(int offset) const;
    // The field with this key (first in frame order); invalid when absent.
    QModelIndex indexForKey(const QString &key) const;
    const vt::dev::FieldSpan *fieldAt(const QModelIndex &index) const;

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    struct Node
    {
        int parent = -1;           // node index; -1 = top level
        int row = 0;               // row under its parent
        std::vector<int> children; // node indices
    };
    QModelIndex indexOfNode(int node, int column = 0) const;
    void build();

    vt::dev::Description m_description;
    vt::dev::Language m_language = vt::dev::Language::English;
    std::vector<Node> m_nodes; // one per field, same order
    std::vector<int> m_roots;
};

} // namespace vt::model
