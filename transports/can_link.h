// CanLink: a Link over a SocketCAN raw socket (CANopen SDO to DSP-408 and HCS modules). Each
// send() takes whole 16-byte `struct can_frame` images (CanFrame::toImage()); each received()
// carries exactly one image. The I/O path is a non-blocking fd watched by QSocketNotifiers, so
// any fd that keeps datagram boundaries works: tests adopt one end of
// socketpair(AF_UNIX, SOCK_SEQPACKET). Owned by the session; create and use it on one thread.
#pragma once

#include "transports/can_frame.h"
#include "transports/link.h"

#include <QTimer>
#include <deque>

class QSocketNotifier;

namespace vt::link {

class CanLink : public Link
{
    Q_OBJECT
public:
    // An fd the link takes over (and closes): it must carry one 16-byte image per datagram.
    struct AdoptedFd
    {
        int fd = -1;
    };

    // Production: a CAN_RAW socket bound to the interface ("can0", "vcan0") at open().
    explicit CanLink(QString interfaceName, QObject *parent = nullptr);
    // Adopts `adopted.fd`; open() starts watching it. `name` is for description() only.
    CanLink(AdoptedFd adopted, QString name, QObject *parent = nullptr);
    ~CanLink() override;

    // Opening → Open, or failed() + Failed (no SocketCAN in this kernel, no such interface, an
    // adopted fd that was already closed); the outcome always arrives from the event loop.
    void open() override;
    // Closes the socket (an adopted fd too: it cannot be reopened afterwards).
    void close() override;
    // One or more whole 16-byte images; anything else is logged and dropped (STYLE.md rule 12).
    void send(const QByteArray &bytes) override;
    void sendFrame(const CanFrame &frame);
    // "can can0"
    QString description() const override;

    QString interfaceName() const { return m_name; }

private:
    void startOpen();
    bool openSocket(QString *reason);
    void onReadable();
    void flushPending();
    void fail(const QString &reason);
    void release();

    QString m_name;
    bool m_adopted = false;
    int m_fd = -1;
    QSocketNotifier *m_readNotifier = nullptr; // children, recreated per open
    QSocketNotifier *m_writeNotifier = nullptr;
    std::deque<QByteArray> m_pending; // images the socket had no room for yet
    QTimer m_retryTimer;              // ENOBUFS: the interface queue is full, try again shortly
    int m_retries = 0;
    quint64 m_openToken = 0;
};

} // namespace vt::link
