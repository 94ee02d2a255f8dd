#include "pty_pair.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace vt::test {

PtyPair::PtyPair()
{
    const int fd = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (fd < 0 || ::grantpt(fd) != 0 || ::unlockpt(fd) != 0) {
        m_error = QStringLiteral("pty: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        if (fd >= 0)
            ::close(fd);
        return;
    }
    const char *name = ::ptsname(fd);
    if (!name) {
        m_error = QStringLiteral("ptsname failed");
        ::close(fd);
        return;
    }
    m_slavePath = QString::fromLocal8Bit(name);
    const int flags = ::fcntl(fd, F_GETFL);
    ::fcntl(fd, F_SETFL, flags | O_NONBLOCK);
    m_master = fd;
}

PtyPair::~PtyPair()
{
    closeMaster();
}

void PtyPair::startReading()
{
    if (m_master < 0 || m_notifier)
        return;
    m_notifier = std::make_unique<QSocketNotifier>(m_master, QSocketNotifier::Read);
    QObject::connect(m_notifier.get(), &QSocketNotifier::activated, [this] { onReadable(); });
}

void PtyPair::onReadable()
{
    char buffer[4096];
    const ssize_t n = ::read(m_master, buffer, sizeof buffer);
    if (n > 0) {
        m_received.append(buffer, static_cast<qsizetype>(n));
    } else if (n < 0 && errno != EAGAIN && m_notifier) {
        m_notifier->setEnabled(false); // the slave went away (EIO): stop polling a hang-up
    }
}

bool PtyPair::write(const QByteArray &bytes)
{
    if (m_master < 0)
        return false;
    const ssize_t n = ::write(m_master, bytes.constData(), static_cast<size_t>(bytes.size()));
    return n == bytes.size();
}

bool PtyPair::slaveTermios(termios *out) const
{
    return m_master >= 0 && ::tcgetattr(m_master, out) == 0;
}

void PtyPair::closeMaster()
{
    if (m_notifier) {
        m_notifier->setEnabled(false);
        m_notifier.reset();
    }
    if (m_master >= 0) {
        ::close(m_master);
        m_master = -1;
    }
}

} // namespace vt::test
