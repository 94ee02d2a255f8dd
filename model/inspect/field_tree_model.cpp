#include "field_tree_model.h"

namespace vt::model {

namespace {
QString fromStd(const std::string &s)
{
    return QString::fromStdString(s);
}
} // namespace

FieldTreeModel::FieldTreeModel(QObject *parent) : QAbstractItemModel(parent)
{
}

void FieldTreeModel::setDescription(const vt::dev::Description &description)
{
    beginResetModel();
    m_description = description;
    build();
    endResetModel();
}

void FieldTreeModel::clear()
{
    setDescription({});
}

void FieldTreeModel::setLanguage(vt::dev::Language language)
{
    if (language == m_language)
        return;
    m_language = language;
    // Only the meaning texts change: keep the view's selection and expansion.
    if (!m_roots.empty())
        emit dataChanged(index(0, MeaningColumn),
                         index(static_cast<int>(m_roots.size()) - 1, MeaningColumn));
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        const auto &children = m_nodes[i].children;
        if (children.empty())
            continue;
        const QModelIndex parent = indexOfNode(static_cast<int>(i));
        emit dataChanged(index(0, MeaningColumn, parent),
                         index(static_cast<int>(children.size()) - 1, MeaningColumn, parent));
    }
}

void FieldTreeModel::build()
{
    m_nodes.assign(m_description.fields.size(), Node{});
    m_roots.clear();
    std::vector<int> open; // open[d] = the last node seen at depth d
    for (std::size_t i = 0; i < m_description.fields.size(); ++i) {
        const int depth = std::max(0, m_description.fields[i].depth);
        const int level = std::min<int>(depth, static_cast<int>(open.size()));
        open.resize(static_cast<std::size_t>(level));
        Node &n = m_nodes[i];
        if (level == 0) {
            n.parent = -1;
            n.row = static_cast<int>(m_roots.size());
            m_roots.push_back(static_cast<int>(i));
        } else {
            n.parent = open.back();
            auto &siblings = m_nodes[static_cast<std::size_t>(n.parent)].children;
            n.row = static_cast<int>(siblings.size());
            siblings.push_back(static_cast<int>(i));
        }
        open.push_back(static_cast<int>(i));
    }
}

QModelIndex FieldTreeModel::indexOfNode(int node, int column) const
{
    if (node < 0 || node >= static_cast<int>(m_nodes.size()))
        return {};
    return createIndex(m_nodes[static_cast<std::size_t>(node)].row, column,
                       static_cast<quintptr>(node));
}

QModelIndex FieldTreeModel::indexForByte(int offset) const
{
    if (offset < 0)
        return {};
    int best = -1;
    int bestDepth = -1;
    std::size_t bestLength = 0;
    for (std::size_t i = 0; i < m_description.fields.size(); ++i) {
        const auto &f = m_description.fields[i];
        const auto o = static_cast<std::size_t>(offset);
        if (f.length == 0 || o < f.offset || o >= f.offset + f.length)
            continue;
        // Deepest in the tree; among equals the narrowest (a bit row inside its byte).
        int depth = 0;
        for (int p = m_nodes[i].parent; p >= 0; p = m_nodes[static_cast<std::size_t>(p)].parent)
            ++depth;
        if (depth > bestDepth || (depth == bestDepth && f.length < bestLength)) {
            best = static_cast<int>(i);
            bestDepth = depth;
            bestLength = f.length;
        }
    }
    return indexOfNode(best);
}

QModelIndex FieldTreeModel::indexForKey(const QString &key) const
{
    const std::string k = key.toStdString();
    for (std::size_t i = 0; i < m_description.fields.size(); ++i)
        if (m_description.fields[i].key == k)
            return indexOfNode(static_cast<int>(i));
    return {};
}

const vt::dev::FieldSpan *FieldTreeModel::fieldAt(const QModelIndex &index) const
{
    if (!index.isValid() || index.model() != this)
        return nullptr;
    const auto node = static_cast<std::size_t>(index.internalId());
    return node < m_description.fields.size() ? &m_description.fields[node] : nullptr;
}

QModelIndex FieldTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    if (row < 0 || column < 0 || column >= ColumnCount)
        return {};
    const std::vector<int> *list = &m_roots;
    if (parent.isValid()) {
        if (parent.column() != 0)
            return {};
        list = &m_nodes[static_cast<std::size_t>(parent.internalId())].children;
    }
    if (row >= static_cast<int>(list->size()))
        return {};
    return createIndex(row, column, static_cast<quintptr>((*list)[static_cast<std::size_t>(row)]));
}

QModelIndex FieldTreeModel::parent(const QModelIndex &child) const
{
    if (!child.isValid())
        return {};
    const int p = m_nodes[static_cast<std::size_t>(child.internalId())].parent;
    return p < 0 ? QModelIndex() : indexOfNode(p);
}

int FieldTreeModel::rowCount(const QModelIndex &parent) const
{
    if (!parent.isValid())
        return static_cast<int>(m_roots.size());
    if (parent.column() != 0)
        return 0;
    return static_cast<int>(m_nodes[static_cast<std::size_t>(parent.internalId())].children.size());
}

int FieldTreeModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

QVariant FieldTreeModel::data(const QModelIndex &index, int role) const
{
    const vt::dev::FieldSpan *f = fieldAt(index);
    if (!f)
        return {};
    switch (role) {
    case Qt::DisplayRole:
    case Qt::ToolTipRole:
        switch (index.column()) {
        case FieldColumn: return fromStd(f->key);
        case BytesColumn:
            if (f->length == 0)
                return QString();
            if (f->length == 1)
                return QString::number(f->offset);
            return QStringLiteral("%1–%2").arg(f->offset).arg(f->offset + f->length - 1);
        case ValueColumn: return fromStd(f->value);
        case MeaningColumn: return fromStd(f->text.in(m_language));
        }
        return {};
    case OffsetRole: return static_cast<int>(f->offset);
    case LengthRole: return static_cast<int>(f->length);
    case KeyRole: return fromStd(f->key);
    }
    return {};
}

QVariant FieldTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case FieldColumn: return tr("Field");
    case BytesColumn: return tr("Bytes");
    case ValueColumn: return tr("Value");
    case MeaningColumn: return tr("Meaning");
    }
    return {};
}

} // namespace vt::model
