// ParameterFilterModel: the editor's search and filters over the ParameterTreeModel — text in
// name, label (either language) or description; "changed only"; "differs from device"; rows that
// are not active for the module's version and mode hidden unless asked for. Modules always show;
// blocks and branches show while they hold a visible row. GUI thread.
#pragma once

#include <QSortFilterProxyModel>

namespace vt::model {

class ParameterFilterModel : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    explicit ParameterFilterModel(QObject *parent = nullptr);

    void setSearchText(const QString &text);
    void setChangedOnly(bool on);
    void setDiffersFromDeviceOnly(bool on);
    void setShowInactive(bool on);
    const QString &searchText() const { return m_search; }
    bool changedOnly() const { return m_changedOnly; }
    bool differsFromDeviceOnly() const { return m_differsOnly; }
    bool showInactive() const { return m_showInactive; }

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    QString m_search;
    bool m_changedOnly = false;
    bool m_differsOnly = false;
    bool m_showInactive = false;
};

} // namespace vt::model
