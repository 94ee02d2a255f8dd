#include "telegram_recorder.h"

#include "model/session/session.h"
#include "transports/link.h"

#include <algorithm>
#include <chrono>

namespace vt::model {

namespace {

TelegramRecord::Status statusOf(ReceivedKind kind)
{
    switch (kind) {
    case ReceivedKind::Answer: return TelegramRecord::Status::Ok;
    case ReceivedKind::Exception: return TelegramRecord::Status::DeviceException;
    case ReceivedKind::Unmatched:
    case ReceivedKind::Unsolicited: return TelegramRecord::Status::Unmatched;
    case ReceivedKind::Garbage: return TelegramRecord::Status::ChecksumError;
    }
    return TelegramRecord::Status::Malformed;
}

qint64 steadyNowNs()
{
    using namespace std::chrono;
    return duration_cast<nanoseconds>(steady_clock::now().time_since_epoch()).count();
}

} // namespace

TelegramRecorder::TelegramRecorder(Session &session, TelegramLog &log, QObject *parent)
    : QObject(parent), m_session(session), m_log(&log)
{
    connect(&session, &Session::frameSent, this,
            [this](const QByteArray &bytes, int module, qint64) { onSent(bytes, module); });
    connect(&session, &Session::frameReceived, this,
            [this](const QByteArray &bytes, int module, qint64, ReceivedKind kind,
                   const QString &note) {
                TelegramRecord r;
                r.direction = dev::Direction::Response;
                r.module = module;
                r.bytes = bytes;
                r.status = statusOf(kind);
                r.note = note;
                append(std::move(r));
            });
    connect(&session, &Session::attemptTimedOut, this, [this](int module, int attempt, qint64) {
        TelegramRecord r;
        r.direction = dev::Direction::Response;
        r.module = module;
        r.status = TelegramRecord::Status::Timeout;
        r.note = TelegramRecorder::tr("no answer to attempt %1").arg(attempt);
        append(std::move(r));
    });
    link::Link &l = session.link();
    connect(&l, &link::Link::frameOnWire, this, &TelegramRecorder::onOnWire);
    connect(&l, &link::Link::failed, this, &TelegramRecorder::flushPending);
    connect(&l, &link::Link::stateChanged, this, [this](link::LinkState state) {
        if (state != link::LinkState::Open)
            flushPending();
    });
}

TelegramRecorder::~TelegramRecorder()
{
    flushPending();
}

void TelegramRecorder::append(TelegramRecord record)
{
    flushPending(); // what came before this goes in before it
    if (!m_log)
        return;
    label(record);
    m_log->append(std::move(record));
}

void TelegramRecorder::label(TelegramRecord &record) const
{
    record.link = m_session.link().description();
    record.protocol = QString::fromLatin1(dev::key(m_session.adapter().protocol()));
}

void TelegramRecorder::onSent(const QByteArray &bytes, int module)
{
    TelegramRecord r;
    r.direction = dev::Direction::Request;
    r.module = module;
    r.bytes = bytes;
    if (!m_session.link().reportsWireTime() || !m_log) {
        append(std::move(r));
        return;
    }
    flushPending();
    label(r);
    r.monotonicNs = m_log->elapsedNs(); // the hand-over, should the line's time not come
    r.wallClock = QDateTime::currentDateTimeUtc();
    m_pending = std::move(r);
    m_pendingHandedNs = steadyNowNs();
}

void TelegramRecorder::onOnWire(qint64 steadyNs)
{
    // Earlier than the hand-over: a frame before it (one a fault link delayed past its timeout).
    if (!m_pending || steadyNs < m_pendingHandedNs)
        return;
    TelegramRecord r = std::move(*m_pending);
    m_pending.reset();
    if (m_log) {
        const qint64 ago = std::max<qint64>(0, steadyNowNs() - steadyNs);
        r.monotonicNs = std::max(r.monotonicNs, m_log->elapsedNs() - ago);
        r.wallClock = QDateTime::currentDateTimeUtc().addMSecs(-ago / 1'000'000);
        m_log->append(std::move(r));
    }
}

void TelegramRecorder::flushPending()
{
    if (!m_pending)
        return;
    TelegramRecord r = std::move(*m_pending);
    m_pending.reset();
    if (m_log)
        m_log->append(std::move(r));
}

} // namespace vt::model
