// SerialLink: a Link over a serial port (RS232/RS485 adapter, HART modem) through libserialport.
// All port I/O runs in a SerialWorker on a private worker QThread reached only through queued
// calls, so the thread that owns the link never waits on the port (STYLE.md rule 9).
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
    // "serial /dev/ttyUSB0 19200 8E1"
    QString description() const override;

    const SerialSettings &settings() const { return m_settings; }
    // Takes effect at the next open().
    void setSettings(const SerialSettings &settings) { m_settings = settings; }

private:
    void onOpened(quint64 session);
    void onFailed(quint64 session, const QString &reason);
    void onReceived(quint64 session, const QByteArray &bytes, bool quiet);
    void ensureWorker();

    SerialSettings m_settings;
    QThread m_thread;
    SerialWorker *m_worker = nullptr; // lives on m_thread; deleted there when it finishes
    quint64 m_session = 0;
    qsizetype m_replyBytes = 0; // expectReply() for the next send()
};

} // namespace vt::link
