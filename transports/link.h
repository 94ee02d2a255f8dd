// Link: the one narrow interface every byte mover implements (serial, TCP, CAN, in-process
// simulator, fault injection). A link moves whole frames or raw byte chunks; it knows nothing
// of protocols. Owned by the model::Connection that made it (a FaultLink owns the link it wraps);
// the Session only uses it. Lives on the thread it was created on and is used only from there
// (blocking links run their I/O on a worker behind queued signals).
#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

namespace vt::link {

enum class LinkState { Closed, Opening, Open, Failed };

class Link : public QObject
{
    Q_OBJECT
public:
    explicit Link(QObject *parent = nullptr) : QObject(parent) {}
    ~Link() override = default;

    // Starts opening; the result arrives as stateChanged(Open) or failed().
    virtual void open() = 0;
    virtual void close() = 0;
    // Queues bytes for sending; never blocks the calling thread.
    virtual void send(const QByteArray &bytes) = 0;
    // The most bytes the answer to the next send() can have (0: none expected or not known). A
    // link that ends frames by the line's silence hands a frame on as soon as it is this long,
    // instead of t3.5 later; the silent interval before the next request is kept all the same.
    // Default: ignored.
    virtual void expectReply(qsizetype bytes) { (void)bytes; }

    // "serial /dev/ttyUSB0 19200 8E1", "tcp 127.0.0.1:502", "sim opat" — for the status bar
    // and the telegram log.
    virtual QString description() const = 0;
    // True when the link says with frameOnWire() when each frame given to send() went to the
    // line. A serial link can hold a request back (the Modbus RTU master's t3.5 of silence, a
    // thread hop to its worker); the others send at once, so the send() is the time.
    virtual bool reportsWireTime() const { return false; }

    LinkState state() const { return m_state; }

signals:
    void received(const QByteArray &bytes);
    // The line was quiet for a frame's silent interval after the bytes received so far (a serial
    // link that sees byte timing, Modbus over Serial Line §2.5.1.1): whatever is buffered and not
    // a frame yet never will be — except, to the adapter, the start of the answer it awaits (a PC
    // sees the bytes in its driver's bursts, devices/access/modbus_adapter.cpp).
    void lineQuiet();
    // The oldest frame given to send() and not reported yet went to the driver (its first byte)
    // at this std::chrono::steady_clock time, ns since the clock's epoch. Only from links whose
    // reportsWireTime() is true; a frame that never went out (the link failed first) is not
    // reported.
    void frameOnWire(qint64 steadyNs);
    void failed(const QString &reason);
    void stateChanged(vt::link::LinkState state);

protected:
    void setState(LinkState state);

private:
    LinkState m_state = LinkState::Closed;
};

QString linkStateText(LinkState state);

} // namespace vt::link
