// TelegramLogModel: the telegram inspector's table over a TelegramLog, with the
// inspector's filters built in. Follows the log incrementally: new records become rows at the
// bottom, records the ring drops leave from the top. Owner: the inspector; GUI thread only
// (the thread of its log). The log must outlive the model.
#pragma once

#include "telegram_log.h"

#include <QAbstractTableModel>
#include <QPointer>
#include <deque>

namespace vt::model {

class TelegramLogModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column {
        TimeColumn,
        DirectionColumn,
        LinkColumn,
        ProtocolColumn,
        ModuleColumn,
        SummaryColumn,
        StatusColumn,
        ColumnCount
    };
    enum Role {
        SeqRole = Qt::UserRole + 1, // quint64
        StatusRole,                 // int(TelegramRecord::Status)
        IsErrorRole,                // bool
        BytesRole,                  // QByteArray
    };

    explicit TelegramLogModel(const TelegramLog *log, QObject *parent = nullptr);

    // Changing the filter rebuilds the rows (a model reset).
    void setFilter(const TelegramFilter &filter);
    TelegramFilter filter() const { return m_filter; }
    // Language / dictionary of the summary column; refreshes the texts.
    void setSummaryOptions(const SummaryOptions &options);
    SummaryOptions summaryOptions() const { return m_options; }

    quint64 seqAt(int row) const;    // 0 for a bad row
    int rowOfSeq(quint64 seq) const; // -1 when filtered out or gone
    // The record behind a row; nullptr for a bad row (or in the short moment between the ring
    // dropping a record and the log's trimmed() notification).
    const TelegramRecord *recordAt(int row) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;

private:
    void rebuild();
    void onAppended(quint64 firstSeq, qsizetype count);
    void onTrimmed(quint64 firstSeq);
    void onCleared();

    QPointer<const TelegramLog> m_log;
    TelegramFilter m_filter;
    SummaryOptions m_options;
    std::deque<quint64> m_rows; // seqs of the accepted records, ascending
};

} // namespace vt::model
