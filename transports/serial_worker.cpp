#include "serial_worker.h"

#include "link_log.h"
#include "serial_port_io.h"

#include <QSocketNotifier>
#include <QThread>
#include <QTimer>
#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <poll.h>
#include <sys/prctl.h>

namespace vt::link {

namespace {

// A hung-up tty reads as "no data" (read() == 0); only poll() tells a USB adapter that was
// pulled (or a pty whose master closed) from a spurious wake-up.
bool hungUp(int fd)
{
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 0) < 0)
        return false;
    return (p.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0;
}

// A frame read in one go is handed on at this size even if the line never went quiet: a
// babbling line must not keep the worker reading forever (an RTU frame is at most 256 bytes).
constexpr qsizetype kMaxFrameRead = 1024;
// Waits for silence before a write are bounded too (a line that never goes quiet).
constexpr int kMaxSilenceWaits = 64;

qint64 nowNs()
{
    using namespace std::chrono;
    return duration_cast<nanoseconds>(steady_clock::now().time_since_epoch()).count();
}

std::int64_t nowUs()
{
    return nowNs() / 1000;
}

// Waits at most `us` (microsecond precision, unlike a QTimer) for input on `fd`: true when
// something can be read (or the line hung up), false when the time passed.
bool inputWithin(int fd, std::int64_t us)
{
    pollfd p{fd, POLLIN, 0};
    const timespec wait{static_cast<time_t>(us / 1'000'000),
                        static_cast<long>(us % 1'000'000) * 1000};
    return ::ppoll(&p, 1, &wait, nullptr) > 0;
}

} // namespace

SerialWorker::SerialWorker(QObject *parent) : QObject(parent)
{
}

SerialWorker::~SerialWorker()
{
    release();
}

QString SerialWorker::openFailureText(const OpenFailure &failure, const SerialSettings &settings)
{
    const QString &name = settings.portName;
    switch (failure.kind) {
    case OpenFailure::Kind::NotFound: return tr("Serial port %1 not found").arg(name);
    case OpenFailure::Kind::PermissionDenied:
        // Opening a serial port is for the members of its group; the fix is the user's.
        return tr("Cannot open %1: permission denied. Serial ports are for the members of the "
                  "group %2: add your user to it with \"sudo usermod -aG %2 $USER\", then log "
                  "out and log in again.")
            .arg(name, failure.group);
    case OpenFailure::Kind::CannotOpen: return tr("Cannot open %1: %2").arg(name, failure.detail);
    case OpenFailure::Kind::NotATerminal:
        return tr("Cannot open %1: it is not a serial port or terminal.").arg(name);
    case OpenFailure::Kind::UnsupportedBaud:
        return tr("Cannot open %1: %2 baud is not a rate the port supports.")
            .arg(name, QString::number(settings.baudRate));
    case OpenFailure::Kind::CannotConfigure:
        return tr("Cannot apply %1 baud %2 to %3: %4")
            .arg(QString::number(settings.baudRate), settings.formatText(), name, failure.detail);
    }
    return tr("Cannot open %1: %2").arg(name, failure.detail);
}

void SerialWorker::openPort(quint64 session, const SerialSettings &settings,
                            QThread *exchangeThread)
{
    release();
    m_session = session;
    m_settings = settings;
    if (const auto problem = settings.problem()) {
        emit failed(session, *problem);
        return;
    }

    OpenFailure failure;
    m_port = openWithLibserialport(settings, &failure);
    if (!m_port && failure.kind != OpenFailure::Kind::CannotConfigure) {
        // libserialport finds ports in sysfs and reads the modem lines on open, so it refuses a
        // pseudo-terminal (socat, ser2net, tty0tty) or a /dev/serial/by-id link; any terminal
        // still opens with plain termios.
        qCDebug(lcLink).noquote() << "serial" << settings.portName
                                  << "refused by libserialport:" << failure.detail;
        m_port = openWithTermios(settings, &failure);
    }
    if (!m_port) {
        emit failed(session, openFailureText(failure, settings));
        return;
    }
    warnIfNotApplied();
    m_line.emplace(settings.baudRate, settings.bitsPerCharacter());
    // What was on the line before the port opened is unknown (another master, a late answer to
    // the program that had the port before): the first request waits t3.5 like any other.
    m_line->received(nowUs());
    // The line's waits are microseconds apart (t3.5 is 1.75 ms above 19200 baud); Linux lets a
    // thread's timed wait end up to 50 µs late by default, which would widen every gap.
    ::prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    // Whatever a previous user left in the buffers is not an answer to us.
    m_port->flush();

    m_notifier = new QSocketNotifier(m_port->descriptor(), QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &SerialWorker::onReadable);
    qCDebug(lcLink).noquote() << "serial open" << settings.portName << settings.baudRate
                              << settings.formatText();
    if (exchangeThread)
        moveToThread(exchangeThread); // the notifier (a child) goes along
    emit opened(session);
}

void SerialWorker::warnIfNotApplied() const
{
    // Some drivers (cheap USB adapters, ptys) accept tcsetattr() yet keep their own parity or
    // character size; the session would only see timeouts, so say it in the log.
    const auto actual = m_port->lineFormat();
    if (!actual || actual->matches(m_settings))
        return;
    qCWarning(lcLink).noquote().nospace()
        << "serial " << m_settings.portName << ": the driver did not take " << m_settings.baudRate
        << " " << m_settings.formatText() << "; it reports " << actual->baudRate << " "
        << actual->dataBits << parityLetter(actual->parity) << static_cast<int>(actual->stopBits);
}

void SerialWorker::closePort()
{
    release();
}

void SerialWorker::write(quint64 session, const QByteArray &bytes, qsizetype replyBytes)
{
    if (session != m_session || !m_port || bytes.isEmpty())
        return;
    m_replyBytes = 0; // what arrives before the write is not its answer
    // Bounded: twice the wire time plus slack, so a stuck adapter fails instead of hanging the
    // worker (and with it the link's destructor) forever.
    const qint64 wireMs =
        bytes.size() * m_settings.bitsPerCharacter() * 1000 / std::max(1, m_settings.baudRate);
    const auto timeout = static_cast<unsigned>(std::min<qint64>(2 * wireMs + 500, 60'000));
    const auto size = static_cast<std::size_t>(bytes.size());
    if (!m_settings.silentInterval && !m_settings.frameEndBySilence) {
        writeWithoutWaiting(bytes, timeout);
        m_replyBytes = replyBytes;
        return;
    }
    if (m_settings.silentInterval) {
        waitForSilence();
        if (!m_port || session != m_session)
            return; // the port failed while the line was watched
    }
    const qint64 startNs = nowNs();
    const long long written = m_port->write(bytes.constData(), size, timeout);
    if (written > 0) {
        m_line->sent(static_cast<std::size_t>(written), nowUs());
        emit wrote(session, startNs);
    }
    m_replyBytes = replyBytes;
    if (written < 0)
        fail(tr("Write to %1 failed: %2").arg(m_settings.portName, m_port->errorText()));
    else if (static_cast<std::size_t>(written) < size)
        fail(tr("Write to %1 timed out").arg(m_settings.portName));
}

void SerialWorker::writeWithoutWaiting(const QByteArray &bytes, unsigned timeoutMs)
{
    m_frameStarts.push_back(m_output.size());
    m_output.append(bytes);
    if (!m_outputDeadline) {
        m_outputDeadline = new QTimer(this);
        m_outputDeadline->setSingleShot(true);
        connect(m_outputDeadline, &QTimer::timeout, this,
                [this] { fail(tr("Write to %1 timed out").arg(m_settings.portName)); });
    }
    if (!m_outputDeadline->isActive())
        m_outputDeadline->start(static_cast<int>(timeoutMs));
    writeOut();
}

void SerialWorker::writeOut()
{
    if (!m_port)
        return;
    const long long n =
        m_port->writeSome(m_output.constData(), static_cast<std::size_t>(m_output.size()));
    if (n < 0) {
        fail(tr("Write to %1 failed: %2").arg(m_settings.portName, m_port->errorText()));
        return;
    }
    if (n > 0) {
        const qint64 takenNs = nowNs();
        m_line->sent(static_cast<std::size_t>(n), nowUs());
        m_output.remove(0, static_cast<qsizetype>(n));
        int started = 0; // reported after the bookkeeping: a slot may close the port
        for (; !m_frameStarts.empty() && m_frameStarts.front() < n; ++started)
            m_frameStarts.pop_front();
        for (qsizetype &start : m_frameStarts)
            start -= static_cast<qsizetype>(n);
        const quint64 session = m_session;
        for (; started > 0 && m_port && session == m_session; --started)
            emit wrote(session, takenNs);
        if (!m_port || session != m_session)
            return;
    }
    if (m_output.isEmpty()) {
        m_outputDeadline->stop();
        if (m_writeNotifier)
            m_writeNotifier->setEnabled(false);
        return;
    }
    // The driver's buffer is full (a slow line, a peer that does not read): on when it has room.
    if (!m_writeNotifier) {
        m_writeNotifier = new QSocketNotifier(m_port->descriptor(), QSocketNotifier::Write, this);
        connect(m_writeNotifier, &QSocketNotifier::activated, this, &SerialWorker::writeOut);
    }
    m_writeNotifier->setEnabled(true);
}

void SerialWorker::waitForSilence()
{
    // Modbus over Serial Line §2.5.1.1: a request starts after at least t3.5 of silence, counted
    // from the last byte on the line in either direction. Bytes arriving meanwhile (a late
    // answer, another station) are read, handed on and restart the count.
    for (int i = 0; i < kMaxSilenceWaits && m_port; ++i) {
        const std::int64_t wait = m_line->sendAllowedAtUs() - nowUs();
        if (wait <= 0)
            return;
        if (inputWithin(m_port->descriptor(), wait))
            onReadable();
    }
}

bool SerialWorker::readFrame(QByteArray &frame, bool &quiet)
{
    std::array<char, 4096> buffer{};
    quiet = false;
    for (;;) {
        const long long n = m_port->read(buffer.data(), buffer.size());
        if (n < 0 || (n == 0 && hungUp(m_port->descriptor()))) {
            if (hungUp(m_port->descriptor()))
                fail(tr("Serial port %1 was disconnected").arg(m_settings.portName));
            else
                fail(tr("Read from %1 failed: %2").arg(m_settings.portName, m_port->errorText()));
            return false;
        }
        if (n > 0) {
            frame.append(buffer.data(), static_cast<qsizetype>(n));
            m_line->received(nowUs());
        }
        if (!m_settings.frameEndBySilence || frame.size() >= kMaxFrameRead)
            return true;
        // The awaited answer is whole by its size: on to the session now, so that it decides on
        // the next request while the line keeps its t3.5 (waitForSilence() before the write).
        // Waiting here for the quiet would add two thread hops to every exchange's gap.
        if (m_replyBytes > 0 && frame.size() >= m_replyBytes) {
            m_replyBytes = 0;
            return true;
        }
        // §2.5.1.1: the frame goes on while bytes follow within t3.5 and ends with the silence.
        const std::int64_t left = m_line->frameEndsAtUs() - nowUs();
        if (left <= 0 || !inputWithin(m_port->descriptor(), left)) {
            quiet = true;
            return true;
        }
    }
}

void SerialWorker::onReadable()
{
    if (!m_port)
        return;
    QByteArray frame;
    bool quiet = false;
    if (!readFrame(frame, quiet))
        return;
    if (!frame.isEmpty() || quiet)
        emit received(m_session, frame, quiet);
}

void SerialWorker::fail(const QString &reason)
{
    qCDebug(lcLink).noquote() << "serial failed" << m_settings.portName << reason;
    // Output still waiting is dropped, so closing does not wait for it to drain (a stuck port).
    if (m_port)
        m_port->flush();
    // Release first: the device must be free for a reopen by the time the link hears of it.
    release();
    emit failed(m_session, reason);
}

void SerialWorker::release()
{
    // Disabled before the port closes, deleted later: release() may run inside a notifier's own
    // activated() emission.
    for (QSocketNotifier **notifier : {&m_notifier, &m_writeNotifier}) {
        if (*notifier) {
            (*notifier)->setEnabled(false);
            (*notifier)->deleteLater();
            *notifier = nullptr;
        }
    }
    m_output.clear();
    m_frameStarts.clear();
    if (m_outputDeadline)
        m_outputDeadline->stop();
    m_port.reset();
}

} // namespace vt::link
