#include "compare_model.h"

#include "parameter_tree_model.h"

namespace vt::model {

CompareModel::CompareModel(ParameterDocument &document, QObject *parent)
    : QAbstractTableModel(parent), m_document(document)
{
    connect(&m_document, &ParameterDocument::languageChanged, this, [this] {
        if (!m_rows.empty())
            emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
        emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    });
}

void CompareModel::compareWithDevice()
{
    m_other = Other::Device;
    m_fileValues.clear();
    refresh();
}

void CompareModel::compareWithFile(const dev::files::ParamFile &file, const QString &name)
{
    m_other = Other::File;
    m_otherName = name;
    m_fileValues.clear();
    for (int i = 0; i < m_document.moduleCount(); ++i) {
        const ParamModule &m = m_document.module(i);
        const dev::files::ModuleRecord *record = nullptr;
        for (const dev::files::ModuleRecord &r : file.modules)
            if (r.address == m.address && r.family == m.dictionary->family)
                record = &r;
        if (!record && file.modules.size() == 1 && m_document.moduleCount() == 1 &&
            file.modules[0].family == m.dictionary->family)
            record = &file.modules[0];
        if (!record)
            continue;
        const dev::files::MapReport report = dev::files::mapModule(*record, *m.dictionary);
        auto &values = m_fileValues[i];
        for (const dev::files::RowMapping &r : report.rows)
            if (r.applies() && r.meta && r.row != dev::files::RowMapping::kNoRow)
                values[r.meta] = record->values[r.row].raw;
    }
    refresh();
}

std::optional<dev::RawValue> CompareModel::otherValue(int module, const dev::ParamMeta *row) const
{
    // Only what is known to be on the device now: a stale value is not compared.
    if (m_other == Other::Device)
        return m_document.deviceCurrent(module, row) ? m_document.value(module, row, Layer::Device)
                                                     : std::nullopt;
    const auto it = m_fileValues.find(module);
    if (it == m_fileValues.end())
        return std::nullopt;
    const auto v = it->second.find(row);
    return v == it->second.end() ? std::nullopt : std::optional<dev::RawValue>(v->second);
}

void CompareModel::refresh()
{
    beginResetModel();
    m_rows.clear();
    for (int i = 0; i < m_document.moduleCount(); ++i) {
        const ParamModule &m = m_document.module(i);
        if (m_other == Other::File && !m_fileValues.count(i))
            continue;
        for (const dev::ParamMeta &meta : m.dictionary->params) {
            // Settable parameters only: display values always differ from a snapshot.
            if (meta.access != dev::Access::ReadWrite || !m.active(meta) ||
                !dev::files::isFileRow(meta))
                continue;
            const auto theirs = otherValue(i, &meta);
            if (!theirs)
                continue; // the other side does not know it: nothing to compare
            const auto mine = m.value(&meta, Layer::Working);
            if (sameValue(mine, theirs))
                continue;
            m_rows.push_back({i, &meta, mine, theirs, false});
        }
    }
    endResetModel();
}

int CompareModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int CompareModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant CompareModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case ColModule: return tr("Module");
    case ColName: return tr("Name");
    case ColLabel: return tr("Parameter");
    case ColThis: return tr("This document");
    case ColOther: return m_other == Other::Device ? tr("Device") : tr("File %1").arg(m_otherName);
    case ColTake: return tr("Take other");
    default: return {};
    }
}

QVariant CompareModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const Row &r = m_rows[static_cast<std::size_t>(index.row())];
    const dev::Language lang = m_document.language();
    if (role == Qt::CheckStateRole && index.column() == ColTake)
        return r.take ? Qt::Checked : Qt::Unchecked;
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    switch (index.column()) {
    case ColModule: return m_document.module(r.module).address;
    case ColName: return QString::fromStdString(r.meta->name);
    case ColLabel: return QString::fromStdString(r.meta->label.in(lang));
    case ColThis: return r.mine ? formatRaw(*r.meta, *r.mine, lang) : tr("(not set)");
    case ColOther: return r.theirs ? formatRaw(*r.meta, *r.theirs, lang) : tr("(not set)");
    default: return {};
    }
}

Qt::ItemFlags CompareModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == ColTake)
        f |= Qt::ItemIsUserCheckable;
    return f;
}

bool CompareModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!index.isValid() || index.column() != ColTake || role != Qt::CheckStateRole ||
        index.row() >= rowCount())
        return false;
    m_rows[static_cast<std::size_t>(index.row())].take = value.toInt() == Qt::Checked;
    emit dataChanged(index, index, {Qt::CheckStateRole});
    return true;
}

void CompareModel::setAllTaken(bool take)
{
    for (Row &r : m_rows)
        r.take = take;
    if (!m_rows.empty())
        emit dataChanged(index(0, ColTake), index(rowCount() - 1, ColTake), {Qt::CheckStateRole});
}

int CompareModel::takenCount() const
{
    int n = 0;
    for (const Row &r : m_rows)
        n += r.take ? 1 : 0;
    return n;
}

int CompareModel::applyTaken()
{
    std::vector<ParameterDocument::Change> changes;
    for (const Row &r : m_rows)
        if (r.take)
            changes.push_back({r.module, r.meta, r.theirs});
    if (changes.empty())
        return 0;
    m_document.editMany(changes, [device = m_other == Other::Device, name = m_otherName] {
        return device ? tr("Take values from the device") : tr("Take values from %1").arg(name);
    });
    refresh();
    return static_cast<int>(changes.size());
}

} // namespace vt::model
