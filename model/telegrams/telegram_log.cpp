#include "telegram_log.h"

#include "core/hex.h"
#include "inspect/describe_any.h"
#include "inspect/logged_frame.h"
#include "transports/byte_span.h"

#include <QIODevice>
#include <QTextStream>
#include <cstring>
#include <span>

namespace vt::model {

using Status = TelegramRecord::Status;

bool TelegramFilter::accepts(const TelegramRecord &r) const
{
    if (module >= 0 && r.module != module)
        return false;
    if (!protocol.isEmpty() && r.protocol != protocol)
        return false;
    return !errorsOnly || r.isError();
}

TelegramLog::TelegramLog(QObject *parent)
    : TelegramLog(kDefaultMaxRecords, kDefaultMaxBytes, parent)
{
}

TelegramLog::TelegramLog(qsizetype maxRecords, qint64 maxBytes, QObject *parent)
    : QObject(parent), m_maxRecords(qMax<qsizetype>(1, maxRecords)),
      m_maxBytes(qMax<qint64>(0, maxBytes))
{
    reserveRing(m_maxRecords);
    m_clock.start();
    m_notifyTimer.setSingleShot(true);
    m_notifyTimer.setInterval(kDefaultNotifyIntervalMs);
    connect(&m_notifyTimer, &QTimer::timeout, this, &TelegramLog::flush);
}

namespace {

// A slot's frame buffer as it is when empty: room for kReservedFrameBytes, so copying a frame of
// up to that size into it allocates nothing.
QByteArray reservedBytes(qsizetype size)
{
    QByteArray bytes;
    bytes.reserve(qMax(size, TelegramLog::kReservedFrameBytes));
    return bytes;
}

// Copies `from` into the slot's own buffer (no allocation when it fits and nobody shares it).
void copyBytes(QByteArray &slot, const QByteArray &from)
{
    if (!slot.isDetached() || slot.capacity() < from.size())
        slot = reservedBytes(from.size());
    slot.resize(from.size());
    if (!from.isEmpty())
        std::memcpy(slot.data(), from.constData(), static_cast<std::size_t>(from.size()));
}

// The string the log keeps for the last record, reused while the text stays the same.
const QString &shared(QString &last, const QString &text)
{
    if (last != text)
        last = text;
    return last;
}

} // namespace

void TelegramLog::reserveRing(qsizetype capacity)
{
    std::vector<TelegramRecord> ring(static_cast<std::size_t>(capacity));
    for (TelegramRecord &r : ring)
        r.bytes = reservedBytes(0);
    const qsizetype keep = qMin(m_size, capacity);
    for (qsizetype i = 0; i < keep; ++i)
        ring[static_cast<std::size_t>(i)] = std::move(m_ring[slot(m_size - keep + i)]);
    for (qsizetype i = 0; i < m_size - keep; ++i) {
        m_bytes -= recordCost(m_ring[slot(i)]);
        ++m_dropped;
    }
    const bool dropped = keep < m_size;
    m_ring = std::move(ring);
    m_head = 0;
    m_size = keep;
    if (dropped)
        scheduleNotify();
}

void TelegramLog::setLimits(qsizetype maxRecords, qint64 maxBytes)
{
    m_maxRecords = qMax<qsizetype>(1, maxRecords);
    m_maxBytes = qMax<qint64>(0, maxBytes);
    if (m_maxRecords != static_cast<qsizetype>(m_ring.size()))
        reserveRing(m_maxRecords);
    enforceLimits();
}

qint64 TelegramLog::recordCost(const TelegramRecord &r)
{
    return static_cast<qint64>(sizeof(TelegramRecord)) + r.bytes.size() +
           r.note.size() * static_cast<qint64>(sizeof(QChar));
}

quint64 TelegramLog::append(TelegramRecord record)
{
    record.seq = m_nextSeq++;
    if (record.monotonicNs < 0)
        record.monotonicNs = m_clock.nsecsElapsed();
    if (!record.wallClock.isValid())
        record.wallClock = QDateTime::currentDateTimeUtc();
    if (m_size == static_cast<qsizetype>(m_ring.size()))
        dropOldest();
    TelegramRecord &r = m_ring[slot(m_size)];
    ++m_size;
    r.seq = record.seq;
    r.monotonicNs = record.monotonicNs;
    r.wallClock = record.wallClock;
    r.direction = record.direction;
    r.link = shared(m_link, record.link);
    r.protocol = shared(m_protocol, record.protocol);
    r.module = record.module;
    copyBytes(r.bytes, record.bytes);
    r.status = record.status;
    r.note = std::move(record.note);
    m_bytes += recordCost(r);
    enforceLimits();
    scheduleNotify();
    return m_nextSeq - 1;
}

quint64 TelegramLog::append(vt::dev::Direction direction, const QString &link,
                            const QString &protocol, int module, const QByteArray &bytes,
                            Status status, const QString &note)
{
    TelegramRecord r;
    r.direction = direction;
    r.link = link;
    r.protocol = protocol;
    r.module = module;
    r.bytes = bytes;
    r.status = status;
    r.note = note;
    return append(std::move(r));
}

quint64 TelegramLog::appendTimeout(const QString &link, const QString &protocol, int module,
                                   const QString &note)
{
    // A timeout is the missing response to the last request.
    return append(vt::dev::Direction::Response, link, protocol, module, {}, Status::Timeout, note);
}

void TelegramLog::clear()
{
    while (m_size > 0)
        dropOldest();
    m_head = 0;
    m_bytes = 0;
    m_dropped = 0;
    m_reportedFirst = m_reportedEnd = m_nextSeq;
    m_notifyTimer.stop();
    emit cleared();
}

const TelegramRecord *TelegramLog::find(quint64 seq) const
{
    if (seq < firstSeq() || seq >= m_nextSeq)
        return nullptr;
    return &at(static_cast<qsizetype>(seq - firstSeq()));
}

void TelegramLog::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    m_paused = paused;
    emit pausedChanged(paused);
    if (!paused)
        flush(); // resuming is a user action: show what was recorded at once
}

void TelegramLog::setNotifyInterval(int ms)
{
    m_notifyTimer.setInterval(qMax(0, ms));
}

void TelegramLog::enforceLimits()
{
    bool dropped = false;
    while (size() > m_maxRecords || (m_bytes > m_maxBytes && m_size > 1)) {
        dropOldest();
        dropped = true;
    }
    if (dropped)
        scheduleNotify();
}

void TelegramLog::dropOldest()
{
    TelegramRecord &r = m_ring[m_head];
    m_bytes -= recordCost(r);
    // What the cap counted goes now: a long frame's own buffer and the note.
    if (r.bytes.capacity() > kKeptFrameBytes)
        r.bytes = reservedBytes(0);
    r.note = QString();
    m_head = (m_head + 1) % m_ring.size();
    --m_size;
    ++m_dropped;
}

void TelegramLog::scheduleNotify()
{
    if (!m_notifyTimer.isActive())
        m_notifyTimer.start();
}

void TelegramLog::flush()
{
    m_notifyTimer.stop();
    const quint64 first = firstSeq();
    if (first > m_reportedFirst) {
        const bool reportedOnesGone = m_reportedFirst < m_reportedEnd;
        m_reportedFirst = first;
        m_reportedEnd =
            qMax(m_reportedEnd, first); // dropped before being announced: never announced
        if (reportedOnesGone)
            emit trimmed(first);
    }
    if (!m_paused && m_nextSeq > m_reportedEnd) {
        const quint64 from = m_reportedEnd;
        m_reportedEnd = m_nextSeq;
        emit appended(from, static_cast<qsizetype>(m_nextSeq - from));
    }
}

// ---- texts ---------------------------------------------------------------------------------

QString TelegramLog::statusText(Status status)
{
    switch (status) {
    case Status::Ok: return tr("ok");
    case Status::DeviceException: return tr("device exception");
    case Status::ChecksumError: return tr("checksum error");
    case Status::Malformed: return tr("malformed");
    case Status::Timeout: return tr("timeout");
    case Status::Unmatched: return tr("unmatched");
    }
    return {};
}

QString TelegramLog::statusKey(Status status)
{
    switch (status) {
    case Status::Ok: return QStringLiteral("ok");
    case Status::DeviceException: return QStringLiteral("device-exception");
    case Status::ChecksumError: return QStringLiteral("checksum-error");
    case Status::Malformed: return QStringLiteral("malformed");
    case Status::Timeout: return QStringLiteral("timeout");
    case Status::Unmatched: return QStringLiteral("unmatched");
    }
    return {};
}

QString TelegramLog::directionText(vt::dev::Direction direction)
{
    return direction == vt::dev::Direction::Request ? tr("out") : tr("in");
}

namespace {

QString fromStd(const std::string &s)
{
    return QString::fromStdString(s);
}

} // namespace

QString TelegramLog::hexText(const QByteArray &bytes)
{
    return fromStd(vt::dev::toHex(vt::link::byteSpan(bytes)));
}

QString TelegramLog::summary(const TelegramRecord &r, const SummaryOptions &options)
{
    if (r.status == Status::Timeout)
        return r.note.isEmpty() ? tr("no reply") : tr("no reply: %1").arg(r.note);
    // describeLogged: the node image is the gateway telegram with padding, and a CANopen record
    // is a 16-byte SocketCAN image that is unwrapped first.
    const auto link = r.linkProtocol();
    if (!link)
        return tr("%n byte(s)", nullptr, static_cast<int>(r.bytes.size()));
    vt::dev::AnyOptions any;
    any.family = options.family;
    any.direction = r.direction;
    any.dictionary = options.dictionary;
    any.dsp408 = options.dsp408;
    any.registerBytes = options.registerBytes;
    const auto described =
        vt::dev::inspect::describeLogged(*link, vt::link::byteSpan(r.bytes), any);
    if (!described)
        return fromStd(described.error());
    if (!described->summary.en.empty())
        return fromStd(described->summary.in(options.language));
    if (described->error)
        return fromStd(vt::dev::describeError(*described->error).in(options.language));
    return {};
}

// ---- saving --------------------------------------------------------------------------------

namespace {

// German files use ';' between fields and ',' as decimal sign, English ones ',' and '.' (what
// spreadsheets expect in each); the first line says which (German and English issue).
QChar csvSeparator(vt::dev::Language language)
{
    return language == vt::dev::Language::German ? QLatin1Char(';') : QLatin1Char(',');
}

QString csvField(const QString &text, QChar separator)
{
    if (!text.contains(separator) && !text.contains(QLatin1Char('"')) &&
        !text.contains(QLatin1Char('\n')) && !text.contains(QLatin1Char('\r')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

// Exact nanoseconds as decimal seconds: "12.000345678".
QString secondsText(qint64 ns, int decimals)
{
    const qint64 sec = ns / 1'000'000'000;
    qint64 frac = ns % 1'000'000'000;
    for (int d = 9; d > decimals; --d)
        frac /= 10;
    return QStringLiteral("%1.%2").arg(sec).arg(frac, decimals, 10, QLatin1Char('0'));
}

bool finish(QTextStream &stream, QIODevice &out, QString *error)
{
    stream.flush();
    if (stream.status() == QTextStream::Ok)
        return true;
    if (error)
        *error = out.errorString();
    return false;
}

} // namespace

bool TelegramLog::writeCsv(QIODevice &out, const SummaryOptions &options,
                           const TelegramFilter &filter, QString *error) const
{
    const bool german = options.language == vt::dev::Language::German;
    const QChar sep = csvSeparator(options.language);
    QTextStream s(&out);
    // The statement line is in the file's language, not the UI's: it must agree with the
    // separator and decimal sign the file uses.
    s << (german ? "# ValveTune-Telegrammprotokoll. Trennzeichen: Semikolon (;). Dezimalzeichen: "
                   "Komma (,). Kodierung: UTF-8.\n"
                 : "# ValveTune telegram log. Separator: comma (,). Decimal sign: point (.). "
                   "Encoding: UTF-8.\n");
    const QStringList header{"seq",    "time_s", "wall_clock_utc", "direction", "link", "protocol",
                             "module", "bytes",  "status",         "summary",   "note"};
    s << header.join(sep) << '\n';
    for (const TelegramRecord &r : *this) {
        if (!filter.accepts(r))
            continue;
        QString seconds = secondsText(r.monotonicNs, 9);
        if (german)
            seconds.replace(QLatin1Char('.'), QLatin1Char(','));
        s << r.seq << sep << seconds << sep << r.wallClock.toUTC().toString(Qt::ISODateWithMs)
          << sep << (r.direction == vt::dev::Direction::Request ? "request" : "response") << sep
          << csvField(r.link, sep) << sep << csvField(r.protocol, sep) << sep
          << (r.module >= 0 ? QString::number(r.module) : QString()) << sep << hexText(r.bytes)
          << sep << statusKey(r.status) << sep << csvField(summary(r, options), sep) << sep
          << csvField(r.note, sep) << '\n';
    }
    return finish(s, out, error);
}

bool TelegramLog::writeText(QIODevice &out, const SummaryOptions &options,
                            const TelegramFilter &filter, QString *error) const
{
    QTextStream s(&out);
    s << tr("ValveTune telegram log: %n record(s)", nullptr, static_cast<int>(size()));
    if (m_dropped > 0)
        s << ", "
          << tr("%n older record(s) dropped", nullptr,
                static_cast<int>(qMin<quint64>(m_dropped, INT_MAX)));
    s << '\n';
    for (const TelegramRecord &r : *this) {
        if (!filter.accepts(r))
            continue;
        s << '\n'
          << '#' << r.seq << "  " << secondsText(r.monotonicNs, 6) << " s  "
          << r.wallClock.toUTC().toString(Qt::ISODateWithMs) << "  " << directionText(r.direction)
          << "  " << r.protocol << "  ";
        if (r.module >= 0)
            s << tr("module %1").arg(r.module) << "  ";
        s << r.link << '\n';
        s << "    " << summary(r, options) << '\n';
        if (!r.bytes.isEmpty())
            s << "    " << hexText(r.bytes) << '\n';
        s << "    " << statusText(r.status);
        if (!r.note.isEmpty())
            s << ": " << r.note;
        s << '\n';
    }
    return finish(s, out, error);
}

} // namespace vt::model
