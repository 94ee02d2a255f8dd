// ParameterTreeModel: the parameter editor's tree — module → block → branch → parameter — over a
// ParameterDocument. Columns name, label, value (display units), device value, file value, range,
// access; metadata for delegates through param_roles.h. Edits become undoable document edits;
// a refused edit says why (editRefused). GUI thread.
#pragma once

#include "model/params/param_roles.h"
#include "model/params/parameter_document.h"

#include <QAbstractItemModel>
#include <map>
#include <vector>

namespace vt::model {

class ParameterTreeModel : public QAbstractItemModel
{
    Q_OBJECT
public:
    enum Column {
        ColName,
        ColLabel,
        ColValue,
        ColDevice,
        ColFile,
        ColRange,
        ColAccess,
        ColumnCount
    };

    explicit ParameterTreeModel(ParameterDocument &document, QObject *parent = nullptr);
    ~ParameterTreeModel() override;

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    ParameterDocument &document() const { return m_document; }
    // The index (column ColName) of a parameter row; invalid when the module has no such row.
    QModelIndex indexOf(int module, const dev::ParamMeta *row, int column = ColName) const;
    QModelIndex moduleIndex(int module) const;
    const dev::ParamMeta *metaAt(const QModelIndex &index) const;
    int moduleAt(const QModelIndex &index) const; // -1 for an invalid index
    // The last refusal of setData, in the document's language.
    const QString &lastError() const { return m_lastError; }
    // The Range column's text: "0,000 … 10,000 V", "4 choices", "bit field" (also the report's).
    static QString rangeText(const dev::ParamMeta &row, dev::Language lang);

signals:
    // An edit was refused; `message` names why (the limits in display units for a range error).
    void editRefused(const QModelIndex &index, const QString &message);

private:
    struct Node
    {
        NodeKind kind = NodeKind::Module;
        int parent = -1; // node index; -1 for modules
        int row = 0;     // position among the parent's children
        int module = 0;
        std::string block;
        int branch = 0;
        const dev::ParamMeta *meta = nullptr;
        std::vector<int> children;
    };
    void rebuild();
    void refreshAll();
    void refreshModule(int module);
    void refreshRow(int module, const dev::ParamMeta *row);
    const Node *nodeAt(const QModelIndex &index) const;
    QVariant paramData(const Node &node, int column, int role) const;
    QVariant moduleData(const Node &node, int column, int role) const;
    QString valueText(int module, const dev::ParamMeta &row, Layer layer) const;
    // "Read 12 seconds ago", or why the device value is not current; empty without one.
    QString deviceAgeText(int module, const dev::ParamMeta &row) const;
    QString helpText(int module, const dev::ParamMeta &row) const;

    ParameterDocument &m_document;
    std::vector<Node> m_nodes;
    std::vector<int> m_modules; // node index of each module
    std::map<std::pair<int, const dev::ParamMeta *>, int> m_rowNode;
    QString m_lastError;
};

// Text of a raw value as the editor shows it (enum label, bits, "1.000 V", a quoted string).
QString formatRaw(const dev::ParamMeta &row, const dev::RawValue &value, dev::Language lang);
// The module's status word (the first bit-field row of its display block) as text, if known.
QString stateWordText(const ParameterDocument &document, int module);

} // namespace vt::model
