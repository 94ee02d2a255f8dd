#include "telegram_log_model.h"

#include <QLocale>
#include <algorithm>

namespace vt::model {

TelegramLogModel::TelegramLogModel(const TelegramLog *log, QObject *parent)
    : QAbstractTableModel(parent), m_log(log)
{
    if (!m_log)
        return;
    connect(m_log, &TelegramLog::appended, this, &TelegramLogModel::onAppended);
    connect(m_log, &TelegramLog::trimmed, this, &TelegramLogModel::onTrimmed);
    connect(m_log, &TelegramLog::cleared, this, &TelegramLogModel::onCleared);
    connect(m_log, &QObject::destroyed, this, &TelegramLogModel::onCleared);
    rebuild();
}

void TelegramLogModel::setFilter(const TelegramFilter &filter)
{
    if (filter == m_filter)
        return;
    beginResetModel();
    m_filter = filter;
    rebuild();
    endResetModel();
}

void TelegramLogModel::setSummaryOptions(const SummaryOptions &options)
{
    m_options = options;
    if (!m_rows.empty())
        emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

void TelegramLogModel::rebuild()
{
    m_rows.clear();
    if (!m_log)
        return;
    // Only what the log has announced: a paused log's newest records stay hidden until resumed.
    for (const TelegramRecord &r : *m_log) {
        if (r.seq >= m_log->announcedEnd())
            break;
        if (m_filter.accepts(r))
            m_rows.push_back(r.seq);
    }
}

void TelegramLogModel::onAppended(quint64 firstSeq, qsizetype count)
{
    std::vector<quint64> accepted;
    for (quint64 seq = firstSeq; seq < firstSeq + static_cast<quint64>(count); ++seq) {
        const TelegramRecord *r = m_log ? m_log->find(seq) : nullptr;
        if (r && m_filter.accepts(*r) && (m_rows.empty() || seq > m_rows.back()))
            accepted.push_back(seq);
    }
    if (accepted.empty())
        return;
    const int first = rowCount();
    beginInsertRows({}, first, first + static_cast<int>(accepted.size()) - 1);
    m_rows.insert(m_rows.end(), accepted.begin(), accepted.end());
    endInsertRows();
}

void TelegramLogModel::onTrimmed(quint64 firstSeq)
{
    const auto gone = std::lower_bound(m_rows.begin(), m_rows.end(), firstSeq);
    const auto count = static_cast<int>(gone - m_rows.begin());
    if (count == 0)
        return;
    beginRemoveRows({}, 0, count - 1);
    m_rows.erase(m_rows.begin(), gone);
    endRemoveRows();
}

void TelegramLogModel::onCleared()
{
    if (m_rows.empty())
        return;
    beginResetModel();
    m_rows.clear();
    endResetModel();
}

quint64 TelegramLogModel::seqAt(int row) const
{
    if (row < 0 || row >= rowCount())
        return 0;
    return m_rows[static_cast<std::size_t>(row)];
}

int TelegramLogModel::rowOfSeq(quint64 seq) const
{
    const auto it = std::lower_bound(m_rows.begin(), m_rows.end(), seq);
    if (it == m_rows.end() || *it != seq)
        return -1;
    return static_cast<int>(it - m_rows.begin());
}

const TelegramRecord *TelegramLogModel::recordAt(int row) const
{
    if (!m_log || row < 0 || row >= rowCount())
        return nullptr;
    return m_log->find(m_rows[static_cast<std::size_t>(row)]);
}

int TelegramLogModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int TelegramLogModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant TelegramLogModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const TelegramRecord *r = recordAt(index.row());
    if (!r)
        return {};
    switch (role) {
    case SeqRole: return QVariant::fromValue(r->seq);
    case StatusRole: return static_cast<int>(r->status);
    case IsErrorRole: return r->isError();
    case BytesRole: return r->bytes;
    case Qt::ToolTipRole:
        if (index.column() == SummaryColumn)
            return TelegramLog::hexText(r->bytes);
        if (index.column() == StatusColumn)
            return r->note.isEmpty() ? QVariant() : QVariant(r->note);
        return {};
    case Qt::TextAlignmentRole:
        if (index.column() == TimeColumn || index.column() == ModuleColumn)
            return QVariant::fromValue(Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
        return {};
    case Qt::DisplayRole: break;
    default: return {};
    }
    switch (index.column()) {
    case TimeColumn: return QLocale().toString(static_cast<double>(r->monotonicNs) / 1e9, 'f', 6);
    case DirectionColumn: return TelegramLog::directionText(r->direction);
    case LinkColumn: return r->link;
    case ProtocolColumn: return r->protocol;
    case ModuleColumn: return r->module >= 0 ? QVariant(r->module) : QVariant(QString());
    case SummaryColumn: return TelegramLog::summary(*r, m_options);
    case StatusColumn:
        return r->note.isEmpty() || r->status == TelegramRecord::Status::Timeout
                   ? TelegramLog::statusText(r->status)
                   : TelegramLog::statusText(r->status) + QStringLiteral(": ") + r->note;
    default: return {};
    }
}

QVariant TelegramLogModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case TimeColumn: return tr("Time [s]");
    case DirectionColumn: return tr("Dir");
    case LinkColumn: return tr("Link");
    case ProtocolColumn: return tr("Protocol");
    case ModuleColumn: return tr("Module");
    case SummaryColumn: return tr("Summary");
    case StatusColumn: return tr("Status");
    default: return {};
    }
}

QHash<int, QByteArray> TelegramLogModel::roleNames() const
{
    QHash<int, QByteArray> names = QAbstractTableModel::roleNames();
    names.insert(SeqRole, "seq");
    names.insert(StatusRole, "status");
    names.insert(IsErrorRole, "isError");
    names.insert(BytesRole, "bytes");
    return names;
}

} // namespace vt::model
