// SimHost's endpoints (see sim_host.h): a pty, a serial port (plain termios, no libserialport),
// a TCP server with its clients, a CAN socket; reading what the master sends and
// writing the answers without ever blocking the event loop.
#include "app/cli/exit_codes.h"
#include "app/sim/can_socket.h"
#include "canopen/can_frame.h"
#include "sim_host.h"
#include "transports/byte_span.h"

#include <QHostAddress>
#include <QSocketNotifier>
#include <QTcpServer>
#include <QTcpSocket>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

namespace vt::simapp {
namespace {

// Linux: EWOULDBLOCK == EAGAIN (checking both trips -Wlogical-op).
static_assert(EWOULDBLOCK == EAGAIN);

constexpr std::size_t kMaxPending = 64 * 1024; // nobody reads the line: stop queueing answers
constexpr std::size_t kCanImage = dev::canopen::kSocketCanFrameSize;
constexpr int kMaxFramesPerWakeup = 64; // a busy CAN bus must not starve the clock
constexpr std::int64_t kPtyQuietUs = 100'000;

speed_t speedFor(int baud)
{
    switch (baud) {
    case 1200: return B1200;
    case 2400: return B2400;
    case 4800: return B4800;
    case 9600: return B9600;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    default: return B19200;
    }
}

std::string errnoText(const std::string &what)
{
    return what + ": " + std::strerror(errno);
}

bool setNonBlocking(int fd)
{
    const int flags = fcntl(fd, F_GETFL);
    return flags >= 0 && fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0 &&
           fcntl(fd, F_SETFD, FD_CLOEXEC) == 0;
}

std::string hostPort(const QHostAddress &address, quint16 port)
{
    const QString host = address.protocol() == QAbstractSocket::IPv6Protocol
                             ? QLatin1Char('[') + address.toString() + QLatin1Char(']')
                             : address.toString();
    return host.toStdString() + ':' + std::to_string(port);
}

} // namespace

std::optional<HostError> SimHost::openPty(QString &where)
{
    m_fd = posix_openpt(O_RDWR | O_NOCTTY);
    if (m_fd < 0 || grantpt(m_fd) != 0 || unlockpt(m_fd) != 0 || !setNonBlocking(m_fd))
        return HostError{cli::kExitConnection, errnoText("cannot create a pseudo terminal")};
    const char *name = ptsname(m_fd);
    if (!name)
        return HostError{cli::kExitConnection, errnoText("ptsname")};
    where = QString::fromLocal8Bit(name);
    // Keeping the slave open means a client closing it is no hang-up for the master.
    m_slaveFd = open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (m_slaveFd < 0)
        return HostError{cli::kExitConnection, errnoText(std::string("cannot open ") + name)};
    // Raw bytes for clients that do not set the line up themselves. No parity: a pty carries
    // bytes, so whatever parity the client asks for is accepted.
    termios tio{};
    if (tcgetattr(m_slaveFd, &tio) == 0) {
        cfmakeraw(&tio);
        cfsetspeed(&tio, speedFor(m_options.baud));
        tcsetattr(m_slaveFd, TCSANOW, &tio);
    }
    watchFd();
    return std::nullopt;
}

std::optional<HostError> SimHost::openSerial(QString &where)
{
    const std::string path = m_options.serialPath.toStdString();
    m_fd = open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (m_fd < 0)
        return HostError{cli::kExitConnection, errnoText("cannot open " + path)};
    termios tio{};
    if (tcgetattr(m_fd, &tio) != 0)
        return HostError{cli::kExitConnection, errnoText(path + " is not a serial port")};
    cfmakeraw(&tio);
    tio.c_cflag |= CLOCAL | CREAD;
    tio.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | PARODD | CRTSCTS);
    if (m_options.parity != link::Parity::None)
        tio.c_cflag |= PARENB;
    if (m_options.parity == link::Parity::Odd)
        tio.c_cflag |= PARODD;
    // VMIN 1: with O_NONBLOCK an empty line reads EAGAIN. VMIN 0 / VTIME 0 would read 0, which
    // onFdReadable cannot tell from a hang-up (n_tty returns 0 for both).
    tio.c_cc[VMIN] = 1;
    tio.c_cc[VTIME] = 0;
    cfsetispeed(&tio, speedFor(m_options.baud));
    cfsetospeed(&tio, speedFor(m_options.baud));
    if (tcsetattr(m_fd, TCSANOW, &tio) != 0)
        return HostError{cli::kExitConnection, errnoText("cannot set up " + path)};
    tcflush(m_fd, TCIOFLUSH);
    where = m_options.serialPath;
    watchFd();
    return std::nullopt;
}

std::optional<HostError> SimHost::openTcp(QString &where)
{
    m_tcp = new QTcpServer(this);
    const QHostAddress address(m_options.tcpHost);
    if (!m_tcp->listen(address, m_options.tcpPort))
        return HostError{cli::kExitConnection, "cannot listen on " +
                                                   hostPort(address, m_options.tcpPort) + ": " +
                                                   m_tcp->errorString().toStdString()};
    connect(m_tcp, &QTcpServer::newConnection, this, &SimHost::onNewConnection);
    where = QString::fromStdString(hostPort(m_tcp->serverAddress(), m_tcp->serverPort()));
    return std::nullopt;
}

std::optional<HostError> SimHost::openCan(QString &where)
{
    const bool adopted = m_options.endpoint == Endpoint::CanFd;
    auto fd = adopted ? adoptCanFd(m_options.canFd)
                      : openCanSocket(m_options.canInterface, m_options.node);
    if (!fd.ok())
        return fd.error();
    m_fd = *fd;
    const std::string node = " node " + std::to_string(m_options.node);
    where = QString::fromStdString(adopted ? "can-fd " + std::to_string(m_fd) + node
                                           : "can:" + m_options.canInterface + node);
    watchFd();
    return std::nullopt;
}

void SimHost::watchFd()
{
    m_readNotifier = new QSocketNotifier(m_fd, QSocketNotifier::Read, this);
    connect(m_readNotifier, &QSocketNotifier::activated, this, &SimHost::onFdReadable);
    m_writeNotifier = new QSocketNotifier(m_fd, QSocketNotifier::Write, this);
    m_writeNotifier->setEnabled(false);
    connect(m_writeNotifier, &QSocketNotifier::activated, this, &SimHost::onFdWritable);
}

void SimHost::closeFd()
{
    // Disabled before the fd closes, deleted later: this may run inside their own activated().
    for (QSocketNotifier *notifier : {m_readNotifier, m_writeNotifier}) {
        if (notifier) {
            notifier->setEnabled(false);
            notifier->deleteLater();
        }
    }
    m_readNotifier = m_writeNotifier = nullptr;
    if (m_slaveFd >= 0)
        ::close(m_slaveFd);
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = m_slaveFd = -1;
}

void SimHost::onFdReadable()
{
    if (m_options.isCan()) {
        readCanFrames();
        return;
    }
    std::uint8_t buf[4096];
    while (m_fd >= 0) {
        const ssize_t n = ::read(m_fd, buf, sizeof buf);
        if (n > 0) {
            received(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)));
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EINTR))
            return;
        fail(n == 0 ? "lost " + m_where.toStdString() + ": end of file"
                    : errnoText("lost " + m_where.toStdString()));
        return;
    }
}

// One datagram = one struct can_frame; anything else (a CAN FD frame, a stray datagram) is
// dropped whole, so the SDO server never sees a frame boundary out of step.
void SimHost::readCanFrames()
{
    std::uint8_t buf[80]; // room for a CAN FD frame (72 bytes), which is no classic frame
    for (int i = 0; i < kMaxFramesPerWakeup && m_fd >= 0; ++i) {
        const ssize_t n = ::recv(m_fd, buf, sizeof buf, MSG_DONTWAIT);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && errno == EAGAIN)
            return;
        if (n <= 0) {
            fail(n == 0 ? "lost " + m_where.toStdString() + ": the peer closed it"
                        : errnoText("lost " + m_where.toStdString()));
            return;
        }
        const std::span<const std::uint8_t> image(buf, static_cast<std::size_t>(n));
        if (image.size() != kCanImage || !dev::canopen::fromSocketCan(image).ok()) {
            note("dropped a " + std::to_string(n) + "-byte datagram that is no classic can_frame");
            continue;
        }
        received(image);
    }
}

void SimHost::onFdWritable()
{
    if (m_options.isCan()) {
        flushCan();
        return;
    }
    while (!m_outPending.empty()) {
        const ssize_t n = ::write(m_fd, m_outPending.data(), m_outPending.size());
        if (n < 0) {
            if (errno == EAGAIN || errno == EINTR)
                return; // the notifier stays on
            fail(errnoText("lost " + m_where.toStdString()));
            return;
        }
        m_outPending.erase(m_outPending.begin(), m_outPending.begin() + n);
    }
    m_writeNotifier->setEnabled(false);
}

void SimHost::writeLine(const std::vector<std::uint8_t> &bytes)
{
    if (m_wire) { // every byte in its own time on the wire
        if (!m_wire->transmit(bytes))
            fail(errnoText("lost " + m_where.toStdString()));
        return;
    }
    std::size_t done = 0;
    if (m_outPending.empty()) {
        while (done < bytes.size()) {
            const ssize_t n = ::write(m_fd, bytes.data() + done, bytes.size() - done);
            if (n < 0) {
                if (errno == EINTR)
                    continue;
                if (errno == EAGAIN)
                    break;
                fail(errnoText("lost " + m_where.toStdString()));
                return;
            }
            done += static_cast<std::size_t>(n);
        }
    }
    if (done == bytes.size())
        return;
    if (m_outPending.size() + bytes.size() - done > kMaxPending) {
        note("nobody reads " + m_where.toStdString() + ": answer discarded");
        return;
    }
    m_outPending.insert(m_outPending.end(), bytes.begin() + static_cast<std::ptrdiff_t>(done),
                        bytes.end());
    m_writeNotifier->setEnabled(true);
}

void SimHost::writeCan(const std::vector<std::uint8_t> &bytes)
{
    const std::size_t whole = bytes.size() / kCanImage * kCanImage; // the server sends images
    if (m_outPending.size() + whole > kMaxPending) {
        note("nobody reads " + m_where.toStdString() + ": answer discarded");
        return;
    }
    m_outPending.insert(m_outPending.end(), bytes.begin(),
                        bytes.begin() + static_cast<std::ptrdiff_t>(whole));
    flushCan();
}

// One image per datagram. ENOBUFS (the interface's transmit queue is full) leaves the images
// pending for the next tick: the socket still polls writable, so a write notifier would spin.
void SimHost::flushCan()
{
    while (m_fd >= 0 && m_outPending.size() >= kCanImage) {
        const ssize_t n = ::send(m_fd, m_outPending.data(), kCanImage, MSG_DONTWAIT | MSG_NOSIGNAL);
        if (n == static_cast<ssize_t>(kCanImage)) {
            m_outPending.erase(m_outPending.begin(),
                               m_outPending.begin() + static_cast<std::ptrdiff_t>(kCanImage));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && errno == EAGAIN) {
            m_writeNotifier->setEnabled(true);
            return;
        }
        if (n < 0 && errno == ENOBUFS)
            return;
        fail(n < 0 ? errnoText("lost " + m_where.toStdString())
                   : "lost " + m_where.toStdString() + ": short write");
        return;
    }
    if (m_writeNotifier)
        m_writeNotifier->setEnabled(false);
}

// A pty's slave shows what the client has not read yet (FIONREAD), but the kernel moves bytes
// from the master to the slave in a worker: right after a write the count can still be 0. So
// a pty counts as drained once the answer was seen waiting and is gone, or after kPtyQuietUs
// in which nothing was seen (the client read it between two ticks).
bool SimHost::lineDrained(std::int64_t nowUs)
{
    int queued = 0;
    if (!m_outPending.empty())
        return false;
    if (m_options.isCan()) // datagrams leave whole: sent is gone
        return true;
    if (m_slaveFd < 0) // serial: all transmitted
        return ioctl(m_fd, TIOCOUTQ, &queued) != 0 || queued == 0;
    if (ioctl(m_slaveFd, FIONREAD, &queued) != 0)
        return true;
    if (queued > 0) {
        m_cutSeenQueued = true;
        m_quietSinceUs = -1;
        return false;
    }
    if (m_cutSeenQueued)
        return true;
    if (m_quietSinceUs < 0)
        m_quietSinceUs = nowUs;
    return nowUs - m_quietSinceUs >= kPtyQuietUs;
}

void SimHost::onNewConnection()
{
    while (m_tcp->hasPendingConnections()) {
        QTcpSocket *socket = m_tcp->nextPendingConnection();
        if (socket->state() != QAbstractSocket::ConnectedState) {
            socket->deleteLater(); // gone before it was taken
            continue;
        }
        const std::string peer = hostPort(socket->peerAddress(), socket->peerPort());
        std::unique_ptr<dev::ByteServer> own = m_device->connectionServer();
        if (!own && !m_clients.empty()) {
            if (m_options.protocol != dev::LinkProtocol::Dsp408Image) {
                refuse(socket, peer);
                continue;
            }
            takeOver(peer);
        }
        if (!own)
            m_device->reset(); // the node image's new master: fresh images, the next answered
        const int number = ++m_clientsSeen;
        // Each connection draws its own fault schedule: the first the seed's (as the in-process
        // FaultLink does), the next ones the following seeds, so a reconnect replays nothing.
        auto client = std::make_unique<TcpClient>(
            TcpClient{socket, own ? own.get() : &m_device->server(), std::move(own),
                      FaultFilter(m_options.fault.rx, m_options.fault.cutAfterFrames,
                                  m_options.seed + static_cast<std::uint32_t>(number - 1)),
                      number, " (client " + std::to_string(number) + ")"});
        m_clients.push_back(std::move(client));
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        connect(socket, &QTcpSocket::readyRead, this,
                [this, socket] { onClientReadyRead(socket); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] { onClientGone(socket); });
        if (m_options.verbose)
            logLine("client " + std::to_string(number) + " " + peer + " connected");
        if (socket->bytesAvailable() > 0)
            onClientReadyRead(socket);
    }
}

// The node image is the process image of one master: the PLC that owns the node's cyclic data
// (DMA Profinet manual §1: data exchange "with an PROFINET IO-Controller", §1.4: a module answers
// when a message differs from "the previous message"; OPAT manual §1.5: TADR is "defined by the
// DP-Master"). A second master's images would mix with the first's, so it is closed at once: it
// learns that the node is taken instead of waiting for answers that never come.
void SimHost::refuse(QTcpSocket *socket, const std::string &peer)
{
    note("node image: refused " + peer + ": the node's process image belongs to client " +
         std::to_string(m_clients.front()->number) + ", its one master");
    connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
    socket->disconnectFromHost();
}

void SimHost::takeOver(const std::string &peer)
{
    for (const auto &client : m_clients) {
        note("dsp408-image: " + peer + " is the image's master now; client " +
             std::to_string(client->number) + " closed");
        client->socket->disconnect(this);
        connect(client->socket, &QTcpSocket::disconnected, client->socket, &QObject::deleteLater);
        client->socket->disconnectFromHost();
    }
    m_clients.clear();
}

SimHost::TcpClient *SimHost::clientOf(const QTcpSocket *socket)
{
    for (const auto &client : m_clients)
        if (client->socket == socket)
            return client.get();
    return nullptr;
}

void SimHost::onClientReadyRead(QTcpSocket *socket)
{
    TcpClient *client = clientOf(socket);
    if (!client)
        return;
    const QByteArray data = socket->readAll();
    arrived(link::byteSpan(data), client->tag);
    client->server->receive(link::byteSpan(data));
    serve();
}

void SimHost::onClientGone(QTcpSocket *socket)
{
    TcpClient *client = clientOf(socket);
    if (!client)
        return;
    if (m_options.verbose)
        logLine("client " + std::to_string(client->number) + " disconnected");
    std::erase_if(m_clients, [socket](const auto &c) { return c->socket == socket; });
    socket->deleteLater();
}

} // namespace vt::simapp
