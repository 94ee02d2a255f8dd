#include "tcp_link.h"

#include "link_log.h"

#include <QHostAddress>
#include <QTcpSocket>

namespace vt::link {

std::optional<TcpLink::Endpoint> TcpLink::parseEndpoint(QStringView text, quint16 defaultPort)
{
    const QString t = text.trimmed().toString();
    Endpoint ep;
    QString portText;
    if (t.startsWith(QLatin1Char('['))) {
        const qsizetype close = t.indexOf(QLatin1Char(']'));
        if (close < 0)
            return std::nullopt;
        ep.host = t.mid(1, close - 1);
        const QString rest = t.mid(close + 1);
        if (!rest.isEmpty()) {
            if (!rest.startsWith(QLatin1Char(':')))
                return std::nullopt;
            portText = rest.mid(1);
        }
    } else if (t.count(QLatin1Char(':')) == 1) {
        ep.host = t.section(QLatin1Char(':'), 0, 0);
        portText = t.section(QLatin1Char(':'), 1);
    } else {
        ep.host = t; // a bare IPv6 address or a host without port
    }
    if (ep.host.isEmpty())
        return std::nullopt;
    ep.port = defaultPort;
    if (!portText.isNull()) {
        bool ok = false;
        const uint port = portText.toUInt(&ok);
        if (!ok || port == 0 || port > 65535)
            return std::nullopt;
        ep.port = static_cast<quint16>(port);
    }
    return ep;
}

TcpLink::TcpLink(QString host, quint16 port, QObject *parent)
    : Link(parent), m_host(std::move(host)), m_port(port)
{
    m_connectTimer.setSingleShot(true);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        if (state() == LinkState::Opening) {
            fail(tr("Connection to %1 timed out after %2 ms")
                     .arg(endpointText(), QString::number(m_connectTimeout.count())));
        }
    });
}

TcpLink::~TcpLink()
{
    dropSocket();
}

void TcpLink::dropSocket()
{
    m_connectTimer.stop();
    if (!m_socket)
        return;
    // Detach first: abort() emits disconnected()/errorOccurred() synchronously.
    m_socket->disconnect(this);
    m_socket->abort();
    m_socket->deleteLater();
    m_socket = nullptr;
}

void TcpLink::fail(const QString &reason)
{
    dropSocket();
    setState(LinkState::Failed);
    emit failed(reason);
}

void TcpLink::open()
{
    if (state() == LinkState::Open || state() == LinkState::Opening)
        return;
    dropSocket();
    m_socket = new QTcpSocket(this);
    connect(m_socket, &QTcpSocket::connected, this, [this] {
        m_connectTimer.stop();
        m_socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        setState(LinkState::Open);
    });
    connect(m_socket, &QTcpSocket::readyRead, this, [this] {
        const QByteArray bytes = m_socket->readAll();
        if (!bytes.isEmpty() && state() == LinkState::Open)
            emit received(bytes);
    });
    connect(m_socket, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError error) {
        if (error == QAbstractSocket::RemoteHostClosedError)
            fail(tr("Connection to %1 closed by the peer").arg(endpointText()));
        else
            fail(tr("Connection to %1 failed: %2").arg(endpointText(), m_socket->errorString()));
    });
    connect(m_socket, &QTcpSocket::disconnected, this,
            [this] { fail(tr("Connection to %1 closed by the peer").arg(endpointText())); });
    setState(LinkState::Opening);
    m_connectTimer.start(m_connectTimeout);
    // connectToHost() may report an error synchronously (e.g. an unresolvable literal); the
    // handlers above then run inside open(). Queue the start so the outcome is always later.
    QMetaObject::invokeMethod(
        m_socket,
        [socket = m_socket, host = m_host, port = m_port] { socket->connectToHost(host, port); },
        Qt::QueuedConnection);
}

void TcpLink::close()
{
    if (state() == LinkState::Closed)
        return;
    dropSocket();
    setState(LinkState::Closed);
}

void TcpLink::send(const QByteArray &bytes)
{
    if (state() != LinkState::Open || !m_socket) {
        qCWarning(lcLink).noquote()
            << "send on" << description() << "while" << linkStateText(state()) << "- dropped"
            << bytes.size() << "bytes";
        return;
    }
    m_socket->write(bytes);
}

QString TcpLink::endpointText() const
{
    const bool v6 = m_host.contains(QLatin1Char(':'));
    const QString host = v6 ? QLatin1Char('[') + m_host + QLatin1Char(']') : m_host;
    return host + QLatin1Char(':') + QString::number(m_port);
}

QString TcpLink::description() const
{
    return QStringLiteral("tcp ") + endpointText();
}

} // namespace vt::link
