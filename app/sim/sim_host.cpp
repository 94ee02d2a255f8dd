// SimHost: see sim_host.h. Time: the SimClock follows a QElapsedTimer, so EEPROM commits and the
// plants run in real time; answers go out as soon as the clock has reached them.
#include "sim_host.h"

#include "app/cli/exit_codes.h"
#include "dict/dictionary_loader.h"
#include "sim/hart_device.h"
#include "sim/hart_server.h"
#include "sim/hcs_node.h"
#include "sim/modbus_rtu_server.h"
#include "sim/modbus_tcp_server.h"
#include "sim/node_config.h"
#include "sim/node_image_server.h"

#include <QHostAddress>
#include <QSocketNotifier>
#include <QTcpServer>
#include <QTcpSocket>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

namespace vt::simapp {
namespace {

constexpr int kTickMs = 1;
constexpr std::size_t kMaxPending = 64 * 1024; // nobody reads the line: stop queueing answers
// Modbus over Serial Line §2.5.1.1: above 19200 baud the 3.5-character gap is a fixed 1.75 ms.
constexpr std::int64_t kFastLineGapUs = 1750;
// --fault cut on a pty / serial port: how long the last answer may wait for its reader.
constexpr std::int64_t kCutGraceUs = 2'000'000;

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

SimHost::SimHost(SimOptions options, QObject *parent)
    : QObject(parent), m_options(std::move(options)),
      m_faults(m_options.fault.rx, m_options.fault.cutAfterFrames, m_options.seed)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(kTickMs);
    connect(&m_timer, &QTimer::timeout, this, &SimHost::tick);
}

SimHost::~SimHost()
{
    m_timer.stop();
    closeFd();
    if (m_hart)
        m_clock.detach(*m_hart);
}

dev::Result<QString, HostError> SimHost::start()
{
    if (auto error = buildDevice())
        return *error;
    // 3.5 characters of start + 8 data + parity + stop bits (Modbus over Serial Line §2.5.1.1);
    // the HART de-framer uses the same quiet time to give up a broken frame.
    const int bits = 10 + (m_options.parity == link::Parity::None ? 0 : 1);
    m_gapUs = m_options.baud > 19200 && !m_options.isHart()
                  ? kFastLineGapUs
                  : static_cast<std::int64_t>(std::ceil(3.5 * bits * 1e6 / m_options.baud));
    QString where;
    std::optional<HostError> error;
    switch (m_options.endpoint) {
    case Endpoint::Pty: error = openPty(where); break;
    case Endpoint::Serial: error = openSerial(where); break;
    case Endpoint::Tcp: error = openTcp(where); break;
    }
    if (error)
        return *error;
    m_where = where;
    m_elapsed.start();
    m_timer.start();
    return where;
}

std::optional<HostError> SimHost::buildDevice()
{
    using namespace dev::sim;
    if (m_options.isHart()) {
        const auto &set = dev::builtinDictionaries();
        const dev::Dictionary *dict = set.ok() ? set->find(m_options.family) : nullptr;
        if (!dict)
            return HostError{cli::kExitDeviceError, "no built-in dictionary " + m_options.family};
        m_hart = std::make_unique<HartDevice>(*dict);
        m_clock.attach(*m_hart);
        auto server = std::make_unique<HartServer>(*m_hart);
        m_hartServer = server.get();
        m_server = std::move(server);
        return std::nullopt;
    }
    NodeConfig config;
    config.family = m_options.family;
    config.modules = m_options.modules;
    config.mode = m_options.mode;
    auto node = makeNode(m_clock, config);
    if (!node.ok())
        return HostError{cli::kExitUsage, node.error()};
    m_node = std::move(node).value();
    switch (m_options.protocol) {
    case Protocol::ModbusRtu: {
        // One module: a point-to-point line where unit 1 reaches it (the OPAT master's SADR 0
        // would be the broadcast address). More: a multi-drop line, unit = module address.
        ModbusUnitOptions units;
        if (m_node->moduleCount() == 1)
            units.pointToPointUnit = 1;
        auto server = std::make_unique<ModbusRtuServer>(m_clock, *m_node, units);
        m_rtu = server.get();
        m_server = std::move(server);
        break;
    }
    case Protocol::ModbusTcp: {
        auto server = std::make_unique<ModbusTcpServer>(m_clock, *m_node);
        m_mbtcp = server.get();
        m_server = std::move(server);
        break;
    }
    case Protocol::NodeImage: {
        auto server = std::make_unique<NodeImageServer>(m_clock, *m_node);
        m_image = server.get();
        m_server = std::move(server);
        break;
    }
    case Protocol::Hart: return HostError{cli::kExitUsage, "HART is served for wandfluh-sd7 only"};
    }
    return std::nullopt;
}

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
    tio.c_cc[VMIN] = 0;
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
    delete m_readNotifier;
    delete m_writeNotifier;
    m_readNotifier = m_writeNotifier = nullptr;
    if (m_slaveFd >= 0)
        ::close(m_slaveFd);
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = m_slaveFd = -1;
}

void SimHost::onFdReadable()
{
    std::uint8_t buf[4096];
    for (;;) {
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

void SimHost::onFdWritable()
{
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

void SimHost::onNewConnection()
{
    while (!m_client && m_tcp->hasPendingConnections()) {
        QTcpSocket *socket = m_tcp->nextPendingConnection();
        if (socket->state() != QAbstractSocket::ConnectedState) {
            socket->deleteLater(); // gone before its turn
            continue;
        }
        m_client = socket;
        m_tcp->pauseAccepting(); // the next client waits in the backlog for its turn
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        resetServer();
        connect(socket, &QTcpSocket::readyRead, this, &SimHost::onClientReadyRead);
        connect(socket, &QTcpSocket::disconnected, this, &SimHost::onClientGone);
        if (m_options.verbose)
            logLine("client " + hostPort(socket->peerAddress(), socket->peerPort()) + " connected");
        if (socket->bytesAvailable() > 0)
            onClientReadyRead();
    }
}

void SimHost::onClientReadyRead()
{
    if (!m_client)
        return;
    const QByteArray data = m_client->readAll();
    received(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t *>(data.constData()),
                                           static_cast<std::size_t>(data.size())));
}

void SimHost::onClientGone()
{
    auto *socket = qobject_cast<QTcpSocket *>(sender());
    if (!socket || socket != m_client)
        return;
    if (m_options.verbose)
        logLine("client disconnected");
    m_client = nullptr;
    socket->deleteLater();
    m_tcp->resumeAccepting();
    onNewConnection();
}

void SimHost::resetServer()
{
    if (m_mbtcp)
        m_mbtcp->reset();
    if (m_image)
        m_image->reset();
    m_faults.reset();
    m_inLog.clear();
}

void SimHost::received(std::span<const std::uint8_t> bytes)
{
    const std::int64_t now = nowUs();
    m_clock.advanceTo(now); // the request arrives at this time, its answer is stamped with it
    m_lastByteUs = now;
    m_burst = true;
    if (m_options.verbose) {
        if (m_tcp)
            logFrame("<-", bytes); // TCP keeps no gaps: one line per segment
        else
            m_inLog.insert(m_inLog.end(), bytes.begin(), bytes.end());
    }
    m_server->receive(bytes);
    serve();
}

void SimHost::tick()
{
    const std::int64_t now = nowUs();
    m_clock.advanceTo(now);
    if (m_cutPending) {
        if ((now >= m_cutEarliestUs && lineDrained()) || now >= m_cutLatestUs)
            finishCut();
        return;
    }
    if (m_burst && now - m_lastByteUs >= m_gapUs) {
        m_burst = false;
        flushInLog();
        if (m_rtu)
            m_rtu->silence();
        if (m_hartServer)
            m_hartServer->gap();
    }
    serve();
}

void SimHost::serve()
{
    if (m_ending || m_cutPending)
        return;
    const std::int64_t now = m_clock.nowUs();
    std::vector<std::uint8_t> answer = m_server->drain();
    if (!answer.empty()) {
        flushInLog();
        // Over TCP only a connected client gets answers; a pty / serial line always has a peer.
        if (m_tcp && !m_client)
            answer.clear();
    }
    if (!answer.empty()) {
        const std::vector<std::uint8_t> copy =
            m_options.verbose ? answer : std::vector<std::uint8_t>{};
        switch (m_faults.push(std::move(answer), now)) {
        case FaultFilter::Verdict::Passed: break;
        case FaultFilter::Verdict::Dropped: logFrame("->", copy, " (fault: dropped)"); break;
        case FaultFilter::Verdict::AfterCut: logFrame("->", copy, " (fault: after the cut)"); break;
        }
    }
    for (const FaultFilter::Answer &a : m_faults.release(nowUs())) {
        logFrame("->", a.bytes,
                 a.corrupted ? (a.delayed ? " (fault: corrupted, delayed)" : " (fault: corrupted)")
                             : (a.delayed ? " (fault: delayed)" : ""));
        send(a.bytes);
    }
    if (m_faults.cutDue())
        cut();
}

void SimHost::send(const std::vector<std::uint8_t> &bytes)
{
    if (m_tcp) {
        if (m_client)
            m_client->write(reinterpret_cast<const char *>(bytes.data()),
                            static_cast<qint64>(bytes.size()));
        return;
    }
    if (m_fd < 0)
        return;
    m_lastSentBytes = bytes.size();
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

void SimHost::cut()
{
    const std::string count = std::to_string(m_faults.answers());
    if (m_tcp) {
        QTcpSocket *socket = m_client;
        if (!socket)
            return;
        note("fault cut after " + count + " answers: closing the connection");
        m_client = nullptr;
        socket->disconnect(this); // its last bytes are not served
        connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
        socket->disconnectFromHost(); // after the answers already written
        m_faults.reset();
        m_tcp->resumeAccepting();
        onNewConnection();
        return;
    }
    // A pty or serial port closed at once would lose the last answer (a hang-up flushes the
    // queues): like a cable pulled after the bytes left, close once they are out.
    if (m_cutPending)
        return;
    note("fault cut after " + count + " answers: closing " + m_where.toStdString());
    m_cutPending = true;
    const std::int64_t charUs = m_gapUs * 2 / 7; // one character
    m_cutEarliestUs = nowUs() + m_gapUs + static_cast<std::int64_t>(m_lastSentBytes) * charUs;
    m_cutLatestUs = m_cutEarliestUs + kCutGraceUs;
}

bool SimHost::lineDrained() const
{
    int queued = 0;
    if (!m_outPending.empty())
        return false;
    if (m_slaveFd >= 0) // pty: the client has read everything we wrote
        return ioctl(m_slaveFd, FIONREAD, &queued) != 0 || queued == 0;
    return ioctl(m_fd, TIOCOUTQ, &queued) != 0 || queued == 0; // serial: all transmitted
}

void SimHost::finishCut()
{
    m_ending = true;
    m_timer.stop();
    closeFd();
    Q_EMIT finished(cli::kExitOk);
}

void SimHost::fail(const std::string &message)
{
    if (m_ending)
        return;
    note(message);
    m_ending = true;
    m_timer.stop();
    closeFd();
    Q_EMIT finished(cli::kExitConnection);
}

void SimHost::flushInLog()
{
    if (m_inLog.empty())
        return;
    logFrame("<-", m_inLog);
    m_inLog.clear();
}

void SimHost::logFrame(const char *direction, std::span<const std::uint8_t> bytes, const char *note)
{
    if (!m_options.verbose)
        return;
    std::string hex;
    hex.reserve(bytes.size() * 3);
    static const char kDigits[] = "0123456789ABCDEF";
    for (const std::uint8_t b : bytes) {
        hex += hex.empty() ? "" : " ";
        hex += kDigits[b >> 4];
        hex += kDigits[b & 0x0F];
    }
    logLine(std::string(direction) + ' ' + hex + note);
}

void SimHost::note(const std::string &text)
{
    std::fprintf(stderr, "valvetune-sim: %s\n", text.c_str());
}

void SimHost::logLine(const std::string &text)
{
    // Monotonic seconds since the start, then the text: one line per event on stderr.
    const std::int64_t us = m_elapsed.isValid() ? nowUs() : 0;
    std::fprintf(stderr, "[%5lld.%06lld] %s\n", static_cast<long long>(us / 1'000'000),
                 static_cast<long long>(us % 1'000'000), text.c_str());
}

} // namespace vt::simapp
