#include "parameter_filter_model.h"

#include "param_roles.h"

namespace vt::model {

ParameterFilterModel::ParameterFilterModel(QObject *parent) : QSortFilterProxyModel(parent)
{
    setRecursiveFilteringEnabled(true);
    // Values change under the filters (a read, an edit): re-evaluate rows as their data changes.
    setDynamicSortFilter(true);
}

void ParameterFilterModel::setSearchText(const QString &text)
{
    if (text == m_search)
        return;
    m_search = text;
    invalidateRowsFilter();
}

void ParameterFilterModel::setChangedOnly(bool on)
{
    m_changedOnly = on;
    invalidateRowsFilter();
}

void ParameterFilterModel::setDiffersFromDeviceOnly(bool on)
{
    m_differsOnly = on;
    invalidateRowsFilter();
}

void ParameterFilterModel::setShowInactive(bool on)
{
    m_showInactive = on;
    invalidateRowsFilter();
}

bool ParameterFilterModel::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
    const auto kind = static_cast<NodeKind>(index.data(NodeKindRole).toInt());
    if (kind == NodeKind::Module)
        return true;
    if (kind != NodeKind::Parameter)
        return false; // shown through recursive filtering while a row below is visible
    if (!m_showInactive && index.data(InactiveRole).toBool())
        return false;
    if (m_changedOnly && !index.data(ChangedRole).toBool())
        return false;
    if (m_differsOnly && !index.data(DiffersFromDeviceRole).toBool())
        return false;
    const QString search = m_search.trimmed();
    return search.isEmpty() ||
           index.data(SearchTextRole).toString().contains(search, Qt::CaseInsensitive);
}

} // namespace vt::model
