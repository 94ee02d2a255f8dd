// SerialLink: a Link over a serial port (RS232/RS485 adapter, HART modem) through libserialport.
// Port I/O runs in a SerialWorker, opened and closed on a private worker QThread reached only
// through queued calls, so the thread that owns the link never waits on the port (STYLE.md
// rule 9). With the Modbus RTU line timing on (the default) the exchanges run there too: the
// worker waits for the line's silences. Without it nothing waits, and the open worker moves to
// the link's own thread: a request is written and an answer handed on without a thread hop
// (two wake-ups less per exchange, which is what a virtual port or gateway without wire time is
// left with), still without blocking — what the driver cannot take at once goes on later.
// Owned by whoever opened it (the session); create, use and destroy it on one thread. Destroying
// it joins the worker thread, which waits at most for a write in progress (bounded timeout).
#pragma once

#include "transports/link.h"
#include "transports/serial_settings.h"

#include <QThread>

namespace vt::link {

class SerialWorker;

class SerialLink : public Link
{
    Q_OBJECT
public:
    explicit SerialLink(SerialSettings settings, QObject *parent = nullptr);
    ~SerialLink() override;

    // Opening → Open, or failed() + Failed; the outcome always arrives later, from the event
    // loop. open() on an Open or Opening link does nothing; after Failed it reopens.
    void open() override;
    // Closed at once; the port is released on the worker shortly after. Bytes still in flight
    // from the old session are discarded.
    void close() override;
    // Ignored (and logged) unless Open.
    void send(const QByteArray &bytes) override;
    // For the next send() only.
    void expectReply(qsizetype bytes) override { m_replyBytes = bytes; }
    // Open, and the exchanges run on the link's own thread (no line timing), not the worker's.
    bool exchangesOnLinkThread() const { return m_exchangesHere; }
    // "serial /dev/ttyUSB0 19200 8E1"
    QString description() const override;
    // frameOnWire(): when the worker handed each frame to the driver, after the t3.5 wait.
    bool reportsWireTime() const override { return true; }

    const SerialSettings &settings() const { return m_settings; }
    // Takes effect at the next open().
    void setSettings(const SerialSettings &settings) { m_settings = settings; }

private:
    void onOpened(quint64 session);
    void onFailed(quint64 session, const QString &reason);
    void onReceived(quint64 session, const QByteArray &bytes, bool quiet);
    void onWrote(quint64 session, qint64 steadyNs);
    void ensureWorker();
    // Queues the worker's move back to the worker thread (a no-op when it is there): whatever
    // is queued for it afterwards runs there.
    void takeWorkerHome();

    SerialSettings m_settings;
    QThread m_thread;
    // Lives on m_thread (on this thread while open without line timing); deleted where it lives.
    SerialWorker *m_worker = nullptr;
    quint64 m_session = 0;
    qsizetype m_replyBytes = 0;         // expectReply() for the next send()
    bool m_exchangesHereAtOpen = false; // the settings of the pending open() have no line timing
    bool m_exchangesHere = false;       // the worker is on this thread: send() calls it directly
};

} // namespace vt::link
