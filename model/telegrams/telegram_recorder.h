// TelegramRecorder: puts every frame a Session sends and receives, and every attempt that timed
// out, into a TelegramLog with the link and protocol it used. Owner: the GUI's Workspace (one per
// connection); same thread as the session and the log, which must both outlive it (it
// disconnects when either goes).
// A request is stamped with when it went to the line where the link can tell (a serial link
// reports it with Link::frameOnWire(): after the Modbus RTU t3.5 wait and the hop to its worker);
// until then it is held back, and it goes in with the time it was handed to the link if anything
// else happens first (an answer, a timeout, the link failing or closing, the recorder's end).
#pragma once

#include "model/telegrams/telegram_log.h"

#include <QObject>
#include <QPointer>
#include <optional>

namespace vt::model {

class Session;

class TelegramRecorder : public QObject
{
    Q_OBJECT
public:
    TelegramRecorder(Session &session, TelegramLog &log, QObject *parent = nullptr);
    ~TelegramRecorder() override;

private:
    void onSent(const QByteArray &bytes, int module);
    void onOnWire(qint64 steadyNs);
    void append(TelegramRecord record);
    // The link and protocol the session uses now.
    void label(TelegramRecord &record) const;
    // The request held back goes in now, with the time it was handed to the link.
    void flushPending();

    Session &m_session;
    QPointer<TelegramLog> m_log;
    std::optional<TelegramRecord> m_pending; // a request waiting for its time on the line
    qint64 m_pendingHandedNs = 0;            // steady_clock ns: when it was handed to the link
};

} // namespace vt::model
