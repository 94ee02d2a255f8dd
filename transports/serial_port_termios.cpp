// The POSIX way of SerialPortIo (serial_port_io.h): open(O_NOCTTY | O_NONBLOCK), isatty(),
// tcsetattr() with termios_line.h's raw line. Reads and writes go straight to the descriptor.
#include "link_log.h"
#include "serial_port_io.h"
#include "termios_line.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

namespace vt::link {

namespace {

QString systemError(int code)
{
    return QString::fromLocal8Bit(std::strerror(code));
}

class TermiosPort final : public SerialPortIo
{
public:
    explicit TermiosPort(int fd) : m_fd(fd) {}
    ~TermiosPort() override { ::close(m_fd); }
    TermiosPort(const TermiosPort &) = delete;
    TermiosPort &operator=(const TermiosPort &) = delete;

    int descriptor() const override { return m_fd; }

    long long read(char *buffer, std::size_t size) override
    {
        const ssize_t n = ::read(m_fd, buffer, size);
        if (n >= 0)
            return n;
        if (errno == EAGAIN || errno == EINTR)
            return 0;
        m_errno = errno;
        return -1;
    }

    long long write(const char *data, std::size_t size, unsigned timeoutMs) override
    {
        std::size_t done = 0;
        int left = static_cast<int>(timeoutMs);
        while (done < size) {
            const ssize_t n = ::write(m_fd, data + done, size - done);
            if (n > 0) {
                done += static_cast<std::size_t>(n);
                continue;
            }
            if (n < 0 && errno != EAGAIN && errno != EINTR) {
                m_errno = errno;
                return -1;
            }
            // The output buffer is full (a slow line, a peer that does not read): wait for room,
            // within the bound the worker set.
            if (left <= 0)
                break;
            pollfd p{m_fd, POLLOUT, 0};
            const int slice = left < 50 ? left : 50;
            if (::poll(&p, 1, slice) < 0 && errno != EINTR) {
                m_errno = errno;
                return -1;
            }
            left -= slice;
        }
        return static_cast<long long>(done);
    }

    long long writeSome(const char *data, std::size_t size) override
    {
        return write(data, size, 0);
    }

    void flush() override { ::tcflush(m_fd, TCIOFLUSH); }

    std::optional<LineFormat> lineFormat() override
    {
        termios t{};
        if (::tcgetattr(m_fd, &t) != 0)
            return std::nullopt;
        LineFormat f;
        f.baudRate = termiosBaud(::cfgetospeed(&t));
        switch (t.c_cflag & CSIZE) {
        case CS5: f.dataBits = 5; break;
        case CS6: f.dataBits = 6; break;
        case CS7: f.dataBits = 7; break;
        default: f.dataBits = 8; break;
        }
        f.parity = (t.c_cflag & PARENB) == 0 ? Parity::None
                   : (t.c_cflag & PARODD)    ? Parity::Odd
                                             : Parity::Even;
        f.stopBits = (t.c_cflag & CSTOPB) ? StopBits::Two : StopBits::One;
        return f;
    }

    QString errorText() const override { return systemError(m_errno); }

private:
    int m_fd;
    int m_errno = 0;
};

} // namespace

std::unique_ptr<SerialPortIo> openWithTermios(const SerialSettings &settings, OpenFailure *failure)
{
    const QByteArray path = settings.portName.toLocal8Bit();
    // O_NOCTTY: the port never becomes the controlling terminal of a CLI run from a shell, so a
    // hang-up on it sends no SIGHUP; O_NONBLOCK: a line without carrier does not block open().
    const int fd = ::open(path.constData(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const int code = errno;
        *failure = openFailure(settings.portName, code, systemError(code));
        return nullptr;
    }
    if (!::isatty(fd)) {
        ::close(fd);
        *failure = {OpenFailure::Kind::NotATerminal, {}, {}};
        return nullptr;
    }
    termios t{};
    if (::tcgetattr(fd, &t) != 0) {
        const int code = errno;
        ::close(fd);
        *failure = {OpenFailure::Kind::CannotOpen, systemError(code), {}};
        return nullptr;
    }
    if (!applyLineSettings(t, settings)) {
        ::close(fd);
        *failure = {OpenFailure::Kind::UnsupportedBaud, {}, {}};
        return nullptr;
    }
    // A pty keeps CS8 without parity whatever is asked (the kernel's pty driver clears CSIZE
    // and PARENB), and once it holds the rest of the request, asking again is answered EINVAL
    // (nothing it can store would change). Both leave the line as set as it can be; SerialWorker
    // logs what was not taken.
    if (::tcsetattr(fd, TCSANOW, &t) != 0) {
        const int code = errno;
        termios held{};
        if (code == EINVAL && ::tcgetattr(fd, &held) == 0 && differsOnlyInCharacterFormat(held, t))
            return std::make_unique<TermiosPort>(fd);
        ::close(fd);
        *failure = {OpenFailure::Kind::CannotConfigure, systemError(code), {}};
        return nullptr;
    }
    qCDebug(lcLink).noquote() << "serial" << settings.portName
                              << "opened with termios (libserialport refused it)";
    return std::make_unique<TermiosPort>(fd);
}

} // namespace vt::link
