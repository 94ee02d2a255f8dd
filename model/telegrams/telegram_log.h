// TelegramLog: the bounded record of every frame in and out of a session that the
// telegram inspector lists, filters and saves. Owner: the session's owner (app);
// GUI thread only — appends, reads and signals all happen on the thread the log lives on.
//
// Memory is reserved at construction, so a log reaching its cap does not add megabytes later: a
// ring of maxRecords records, each with room for a frame of kReservedFrameBytes (frames up to
// that size are copied into it; longer ones get a larger buffer, see kKeptFrameBytes). The link
// and protocol texts of consecutive records share one string. With the defaults: 100 000 ×
// (sizeof(TelegramRecord) + one heap block of kReservedFrameBytes) ≈ 20 MB (docs/PERFORMANCE.md,
// "GUI resident memory over 30 minutes").
#pragma once

#include "core/direction.h"
#include "core/link_protocol.h"
#include "core/local_text.h"
#include "dsp408/gateway.h"
#include "dsp408/options.h"
#include "hcs/types.h"

#include <QByteArray>
#include <QDateTime>
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>
#include <iterator>
#include <optional>
#include <vector>

class QIODevice;

namespace vt::dev {
struct Dictionary;
}

namespace vt::model {

struct TelegramRecord
{
    enum class Status : quint8 {
        Ok,
        DeviceException, // a well-formed exception reply; note = the exception text
        ChecksumError,
        Malformed, // not a frame of the protocol; note = why
        Timeout,   // no reply in time; a record without bytes
        Unmatched, // a valid frame that answers no outstanding request
    };

    quint64 seq = 0;         // set by the log: contiguous, never reused (not even after clear())
    qint64 monotonicNs = -1; // since the log's start; < 0 = stamped by append()
    QDateTime wallClock;     // UTC, for saving; invalid = stamped by append()
    vt::dev::Direction direction = vt::dev::Direction::Request; // a master's out = Request
    QString link;     // Link::description(): "serial /dev/ttyUSB0 19200 8E1"
    QString protocol; // the link protocol's key, as saved: "modbus-rtu", "node-image", …
    int module = -1;  // module address; -1 = unknown
    QByteArray bytes; // empty for Timeout
    Status status = Status::Ok;
    QString note; // exception text / reason

    bool isError() const { return status != Status::Ok; }
    // The link protocol the key names; nullopt for a key no link has.
    std::optional<vt::dev::LinkProtocol> linkProtocol() const
    {
        return vt::dev::fromKey<vt::dev::LinkProtocol>(protocol.toStdString());
    }
};

// The inspector's filters; the same filter selects what is saved.
struct TelegramFilter
{
    int module = -1;  // -1 = every module
    QString protocol; // empty = every protocol
    bool errorsOnly = false;

    bool accepts(const TelegramRecord &r) const;
    bool operator==(const TelegramFilter &) const = default;
};

// How summaries are worded: the language and what describeAny needs to name parameters.
struct SummaryOptions
{
    vt::dev::Language language = vt::dev::Language::English;
    vt::dev::hcs::Family family = vt::dev::hcs::Family::Dma; // Modbus / gateway exception texts
    const vt::dev::Dictionary *dictionary = nullptr;         // not owned; nullptr = raw IDs
    // The ED1's image layout and gateway register byte order as the link is configured.
    vt::dev::dsp408::Options dsp408;
    vt::dev::dsp408::RegisterByteOrder registerBytes =
        vt::dev::dsp408::RegisterByteOrder::FirstByteHigh;
};

class TelegramLog : public QObject
{
    Q_OBJECT
public:
    static constexpr qsizetype kDefaultMaxRecords = 100'000;
    // Room each ring slot reserves for a frame's bytes: Modbus RTU/TCP requests and short replies
    // (a TCP read of 5 registers: 19 bytes) and CANopen records (16 bytes) fit. A slot keeps a
    // buffer grown for a longer frame up to kKeptFrameBytes (a 42-byte node image), so such links
    // do not allocate per frame either once the ring went round; longer buffers go with their
    // record.
    static constexpr qsizetype kReservedFrameBytes = 32;
    static constexpr qsizetype kKeptFrameBytes = 64;
    static constexpr qint64 kDefaultMaxBytes = 64 * 1024 * 1024;
    static constexpr int kDefaultNotifyIntervalMs =
        20; // ≤ 50 notifications/s however fast frames arrive

    explicit TelegramLog(QObject *parent = nullptr);
    TelegramLog(qsizetype maxRecords, qint64 maxBytes, QObject *parent = nullptr);

    // Both caps hold after every append(); the newest record is always kept, even when it alone
    // exceeds maxBytes. Lowering a cap drops the oldest records at once.
    void setLimits(qsizetype maxRecords, qint64 maxBytes);
    qsizetype maxRecords() const { return m_maxRecords; }
    qint64 maxBytes() const { return m_maxBytes; }
    // What one record counts against maxBytes: its struct, its bytes and its note.
    static qint64 recordCost(const TelegramRecord &r);

    // O(1) amortised. Stamps seq (and the times when unset); returns the seq.
    quint64 append(TelegramRecord record);
    quint64 append(vt::dev::Direction direction, const QString &link, const QString &protocol,
                   int module, const QByteArray &bytes,
                   TelegramRecord::Status status = TelegramRecord::Status::Ok,
                   const QString &note = {});
    quint64 appendTimeout(const QString &link, const QString &protocol, int module,
                          const QString &note = {});
    // Removes every record and resets droppedCount(); emits cleared() at once.
    void clear();

    qsizetype size() const { return m_size; }
    bool isEmpty() const { return m_size == 0; }
    quint64 firstSeq() const
    {
        return m_nextSeq - static_cast<quint64>(m_size);
    } // == nextSeq() when empty
    quint64 nextSeq() const { return m_nextSeq; }
    quint64 droppedCount() const { return m_dropped; } // dropped by the caps since start / clear()
    qint64 storedBytes() const { return m_bytes; }
    quint64 announcedEnd() const { return m_reportedEnd; } // appended() has covered every seq below
    qint64 elapsedNs() const
    {
        return m_clock.nsecsElapsed();
    } // the clock records are stamped with

    const TelegramRecord *find(quint64 seq) const; // nullptr once dropped (or not yet appended)
    const TelegramRecord &at(qsizetype index) const { return m_ring[slot(index)]; } // 0 = oldest

    // Oldest to newest.
    class ConstIterator
    {
    public:
        using iterator_category = std::forward_iterator_tag;
        using value_type = TelegramRecord;
        using difference_type = std::ptrdiff_t;
        using pointer = const TelegramRecord *;
        using reference = const TelegramRecord &;
        ConstIterator() = default;
        ConstIterator(const TelegramLog *log, qsizetype index) : m_log(log), m_index(index) {}
        reference operator*() const { return m_log->at(m_index); }
        pointer operator->() const { return &m_log->at(m_index); }
        ConstIterator &operator++()
        {
            ++m_index;
            return *this;
        }
        ConstIterator operator++(int)
        {
            ConstIterator before = *this;
            ++m_index;
            return before;
        }
        bool operator==(const ConstIterator &) const = default;

    private:
        const TelegramLog *m_log = nullptr;
        qsizetype m_index = 0;
    };
    ConstIterator begin() const { return {this, 0}; }
    ConstIterator end() const { return {this, m_size}; }

    // Pause freezes the views, not the recording: a paused log keeps every frame (a capture must
    // not have holes) but withholds appended() until resumed, then reports what arrived in one
    // batch. trimmed() is still emitted while paused, so frozen views lose their oldest rows
    // when the ring is full.
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }

    void setNotifyInterval(int ms);
    // Emits the pending trimmed()/appended() now instead of on the coalescing timer.
    void flush();

    // Saving. CSV keeps machine keys (stable for scripts), the text dump is for people.
    // Both write only records the filter accepts; false (and *error) on a write error.
    bool writeCsv(QIODevice &out, const SummaryOptions &options = {},
                  const TelegramFilter &filter = {}, QString *error = nullptr) const;
    bool writeText(QIODevice &out, const SummaryOptions &options = {},
                   const TelegramFilter &filter = {}, QString *error = nullptr) const;

    // One line for the list: describeAny's summary in the chosen language; timeouts say so.
    static QString summary(const TelegramRecord &r, const SummaryOptions &options = {});
    static QString statusText(TelegramRecord::Status status);   // translated, for people
    static QString statusKey(TelegramRecord::Status status);    // "ok", "checksum-error", … (CSV)
    static QString directionText(vt::dev::Direction direction); // translated "out" / "in"
    static QString hexText(const QByteArray &bytes);            // "01 03 00 07"

signals:
    // Coalesced: records [firstSeq, firstSeq + count) are new. Records that were appended and
    // dropped within one batch are never announced.
    void appended(quint64 firstSeq, qsizetype count);
    // Coalesced, emitted before appended(): every record below firstSeq is gone. Between a drop
    // and this signal, find() already returns nullptr for the dropped seqs.
    void trimmed(quint64 firstSeq);
    void cleared();
    void pausedChanged(bool paused);

private:
    std::size_t slot(qsizetype index) const
    {
        return (m_head + static_cast<std::size_t>(index)) % m_ring.size();
    }
    void reserveRing(qsizetype capacity); // keeps the newest records that fit
    void dropOldest();
    void enforceLimits();
    void scheduleNotify();

    std::vector<TelegramRecord> m_ring; // maxRecords slots, allocated once per cap
    std::size_t m_head = 0;             // slot of the oldest record
    qsizetype m_size = 0;
    QString m_link, m_protocol; // the texts of the last record, shared by the next ones
    qsizetype m_maxRecords;
    qint64 m_maxBytes;
    qint64 m_bytes = 0;
    quint64 m_nextSeq = 0;
    quint64 m_dropped = 0;
    quint64 m_reportedFirst = 0; // consumers were told that records from here on exist …
    quint64 m_reportedEnd = 0;   // … up to here (exclusive)
    bool m_paused = false;
    QElapsedTimer m_clock;
    QTimer m_notifyTimer;
};

} // namespace vt::model
