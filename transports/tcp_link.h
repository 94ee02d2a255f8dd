// TcpLink: a Link over a TCP connection (Modbus TCP gateway, node-image link, the simulator's
// TCP port). QTcpSocket is asynchronous, so no worker thread is needed: nothing here blocks.
// Owned by the session that opened it; create and use it on one thread (it owns its socket).
#pragma once

#include "transports/link.h"

#include <QTimer>
#include <chrono>
#include <optional>

class QTcpSocket;

namespace vt::link {

class TcpLink : public Link
{
    Q_OBJECT
public:
    static constexpr std::chrono::milliseconds kDefaultConnectTimeout{3000};

    struct Endpoint
    {
        QString host;
        quint16 port = 0;
    };
    // "192.168.0.10:502", "plc.local:502", "[::1]:1502"; a missing port means defaultPort.
    static std::optional<Endpoint> parseEndpoint(QStringView text, quint16 defaultPort = 502);

    TcpLink(QString host, quint16 port, QObject *parent = nullptr);
    ~TcpLink() override;

    // Opening → Open, or failed() + Failed on refusal, resolution failure or timeout.
    void open() override;
    void close() override;
    // Ignored (and logged) unless Open; QTcpSocket buffers, never blocks.
    void send(const QByteArray &bytes) override;
    // "tcp 127.0.0.1:502"
    QString description() const override;

    QString host() const { return m_host; }
    quint16 port() const { return m_port; }
    std::chrono::milliseconds connectTimeout() const { return m_connectTimeout; }
    void setConnectTimeout(std::chrono::milliseconds timeout) { m_connectTimeout = timeout; }

private:
    void fail(const QString &reason);
    void dropSocket();
    // "127.0.0.1:502", "[::1]:502"
    QString endpointText() const;

    QString m_host;
    quint16 m_port;
    std::chrono::milliseconds m_connectTimeout = kDefaultConnectTimeout;
    QTcpSocket *m_socket = nullptr; // child; a fresh one per open()
    QTimer m_connectTimer;
};

} // namespace vt::link
