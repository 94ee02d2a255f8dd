#include "can_link.h"

#include "link_log.h"

#include <QSocketNotifier>
#include <array>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

namespace vt::link {

namespace {

// Linux: EWOULDBLOCK == EAGAIN (checking both trips -Wlogical-op).
static_assert(EWOULDBLOCK == EAGAIN);

constexpr int kMaxFramesPerWakeup = 64; // stay responsive on a busy bus
constexpr int kRetryMs = 5;
constexpr int kMaxRetries = 200; // ~1 s of "interface queue full" before giving up
constexpr std::size_t kMaxPending = 4096;

QString errnoText(int error)
{
    return QString::fromLocal8Bit(std::strerror(error));
}

// send() so that a peer that went away yields EPIPE instead of SIGPIPE; write() for an adopted
// fd that is not a socket.
ssize_t sendImage(int fd, const QByteArray &image)
{
    const auto size = static_cast<size_t>(image.size());
    const ssize_t n = ::send(fd, image.constData(), size, MSG_NOSIGNAL);
    if (n < 0 && errno == ENOTSOCK)
        return ::write(fd, image.constData(), size);
    return n;
}

} // namespace

CanLink::CanLink(QString interfaceName, QObject *parent)
    : Link(parent), m_name(std::move(interfaceName))
{
    m_retryTimer.setSingleShot(true);
    connect(&m_retryTimer, &QTimer::timeout, this, &CanLink::flushPending);
}

CanLink::CanLink(AdoptedFd adopted, QString name, QObject *parent)
    : CanLink(std::move(name), parent)
{
    m_adopted = true;
    m_fd = adopted.fd;
}

CanLink::~CanLink()
{
    release();
}

QString CanLink::description() const
{
    return QStringLiteral("can ") + m_name;
}

void CanLink::open()
{
    if (state() == LinkState::Open || state() == LinkState::Opening)
        return;
    setState(LinkState::Opening);
    const quint64 token = ++m_openToken;
    QTimer::singleShot(0, this, [this, token] {
        if (token == m_openToken && state() == LinkState::Opening)
            startOpen();
    });
}

void CanLink::startOpen()
{
    QString reason;
    if (!openSocket(&reason)) {
        fail(reason);
        return;
    }
    m_readNotifier = new QSocketNotifier(m_fd, QSocketNotifier::Read, this);
    connect(m_readNotifier, &QSocketNotifier::activated, this, &CanLink::onReadable);
    m_writeNotifier = new QSocketNotifier(m_fd, QSocketNotifier::Write, this);
    m_writeNotifier->setEnabled(false);
    connect(m_writeNotifier, &QSocketNotifier::activated, this, &CanLink::flushPending);
    setState(LinkState::Open);
}

bool CanLink::openSocket(QString *reason)
{
    if (m_adopted) {
        if (m_fd < 0) {
            *reason = tr("CAN socket %1 was closed and cannot be reopened").arg(m_name);
            return false;
        }
        const int flags = ::fcntl(m_fd, F_GETFL);
        if (flags < 0 || ::fcntl(m_fd, F_SETFL, flags | O_NONBLOCK) < 0) {
            *reason = tr("CAN socket %1 is unusable: %2").arg(m_name, errnoText(errno));
            return false;
        }
        return true;
    }

    const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
    if (fd < 0) {
        const int error = errno;
        if (error == EAFNOSUPPORT || error == EPROTONOSUPPORT || error == EINVAL) {
            *reason = tr("Cannot open CAN interface %1: SocketCAN is not available in this "
                         "kernel (%2)")
                          .arg(m_name, errnoText(error));
        } else {
            *reason = tr("Cannot open CAN interface %1: %2").arg(m_name, errnoText(error));
        }
        return false;
    }
    const QByteArray name = m_name.toLocal8Bit();
    const unsigned index = name.isEmpty() ? 0 : ::if_nametoindex(name.constData());
    if (index == 0) {
        ::close(fd);
        *reason = tr("Cannot open CAN interface %1: no such network interface").arg(m_name);
        return false;
    }
    sockaddr_can address;
    std::memset(&address, 0, sizeof address);
    address.can_family = AF_CAN;
    address.can_ifindex = static_cast<int>(index);
    if (::bind(fd, reinterpret_cast<const sockaddr *>(&address), sizeof address) < 0) {
        const int error = errno;
        ::close(fd);
        *reason = tr("Cannot open CAN interface %1: %2").arg(m_name, errnoText(error));
        return false;
    }
    m_fd = fd;
    return true;
}

void CanLink::close()
{
    if (state() == LinkState::Closed)
        return;
    ++m_openToken;
    release();
    setState(LinkState::Closed);
}

void CanLink::sendFrame(const CanFrame &frame)
{
    if (!frame.isValid()) {
        qCWarning(lcLink).noquote()
            << description() << "dropped an invalid CAN frame, id" << Qt::hex << frame.id << "with"
            << Qt::dec << frame.data.size() << "bytes";
        return;
    }
    send(frame.toImage());
}

void CanLink::send(const QByteArray &bytes)
{
    if (state() != LinkState::Open) {
        qCWarning(lcLink).noquote()
            << "send on" << description() << "while" << linkStateText(state()) << "- dropped"
            << bytes.size() << "bytes";
        return;
    }
    if (bytes.isEmpty() || bytes.size() % CanFrame::kImageSize != 0) {
        qCWarning(lcLink).noquote() << description() << "dropped" << bytes.size()
                                    << "bytes: not a whole number of 16-byte can_frame images";
        return;
    }
    for (qsizetype at = 0; at < bytes.size(); at += CanFrame::kImageSize) {
        const QByteArray image = bytes.mid(at, CanFrame::kImageSize);
        if (!CanFrame::fromImage(image)) {
            qCWarning(lcLink).noquote()
                << description() << "dropped a can_frame image with len > 8";
            continue;
        }
        if (m_pending.size() >= kMaxPending) {
            fail(tr("CAN interface %1: transmit backlog overflow").arg(m_name));
            return;
        }
        m_pending.push_back(image);
    }
    flushPending();
}

void CanLink::flushPending()
{
    while (m_fd >= 0 && !m_pending.empty()) {
        const ssize_t n = sendImage(m_fd, m_pending.front());
        if (n == CanFrame::kImageSize) {
            m_pending.pop_front();
            m_retries = 0;
            continue;
        }
        if (n >= 0) {
            fail(tr("CAN interface %1: short write (%2 bytes)").arg(m_name).arg(n));
            return;
        }
        const int error = errno;
        if (error == EINTR)
            continue;
        if (error == EAGAIN) {
            m_writeNotifier->setEnabled(true);
            return;
        }
        if (error == ENOBUFS) {
            // The interface's transmit queue is full; the socket still polls writable, so a
            // write notifier would spin. Back off instead, and give up on a dead bus.
            if (++m_retries > kMaxRetries) {
                fail(tr("CAN interface %1: transmit queue stays full (bus off?)").arg(m_name));
                return;
            }
            m_retryTimer.start(kRetryMs);
            return;
        }
        fail(tr("CAN interface %1: write failed: %2").arg(m_name, errnoText(error)));
        return;
    }
    if (m_writeNotifier)
        m_writeNotifier->setEnabled(false);
}

void CanLink::onReadable()
{
    std::array<char, 80> buffer{}; // room for a CAN FD frame (72 bytes), which we drop
    for (int i = 0; i < kMaxFramesPerWakeup && m_fd >= 0; ++i) {
        const ssize_t n = ::read(m_fd, buffer.data(), buffer.size());
        if (n < 0) {
            const int error = errno;
            if (error == EINTR)
                continue;
            if (error == EAGAIN)
                return;
            fail(tr("CAN interface %1: read failed: %2").arg(m_name, errnoText(error)));
            return;
        }
        if (n == 0) {
            fail(tr("CAN interface %1: socket closed").arg(m_name));
            return;
        }
        const QByteArray image(buffer.data(), static_cast<qsizetype>(n));
        if (n != CanFrame::kImageSize || !CanFrame::fromImage(image)) {
            qCWarning(lcLink).noquote() << description() << "dropped a" << n
                                        << "byte datagram that is no classic can_frame";
            continue;
        }
        emit received(image); // a receiver may close the link: the loop checks m_fd
    }
}

void CanLink::fail(const QString &reason)
{
    qCDebug(lcLink).noquote() << description() << "failed:" << reason;
    release();
    setState(LinkState::Failed);
    emit failed(reason);
}

void CanLink::release()
{
    m_retryTimer.stop();
    m_retries = 0;
    m_pending.clear();
    // Disabled before the fd closes, deleted later: release() may run inside their own
    // activated() emission.
    for (QSocketNotifier *notifier : {m_readNotifier, m_writeNotifier}) {
        if (notifier) {
            notifier->setEnabled(false);
            notifier->deleteLater();
        }
    }
    m_readNotifier = nullptr;
    m_writeNotifier = nullptr;
    if (m_fd >= 0) {
        ::close(m_fd);
        m_fd = -1;
    }
}

} // namespace vt::link
