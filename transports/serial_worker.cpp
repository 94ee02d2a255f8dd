#include "serial_worker.h"

#include "link_log.h"

#include <QSocketNotifier>
#include <algorithm>
#include <array>
#include <libserialport.h>
#include <poll.h>

namespace vt::link {

namespace {

sp_parity toSp(Parity parity)
{
    switch (parity) {
    case Parity::None: return SP_PARITY_NONE;
    case Parity::Even: return SP_PARITY_EVEN;
    case Parity::Odd: return SP_PARITY_ODD;
    }
    return SP_PARITY_NONE;
}

// A hung-up tty reads as "no data" (read() == 0) through libserialport; only poll() tells a USB
// adapter that was pulled (or a pty whose master closed) from a spurious wake-up.
bool hungUp(int fd)
{
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 0) < 0)
        return false;
    return (p.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0;
}

} // namespace

SerialWorker::SerialWorker(QObject *parent) : QObject(parent)
{
}

SerialWorker::~SerialWorker()
{
    release();
}

QString SerialWorker::lastError()
{
    char *message = sp_last_error_message();
    QString text = message ? QString::fromLocal8Bit(message).trimmed() : QString();
    sp_free_error_message(message);
    return text;
}

void SerialWorker::openPort(quint64 session, const SerialSettings &settings)
{
    release();
    m_session = session;
    m_settings = settings;
    if (const auto problem = settings.problem()) {
        emit failed(session, *problem);
        return;
    }

    const QByteArray name = settings.portName.toLocal8Bit();
    sp_port *port = nullptr;
    if (sp_get_port_by_name(name.constData(), &port) != SP_OK) {
        // libserialport looks the name up in sysfs; a missing entry means no such device.
        emit failed(session, tr("Serial port %1 not found").arg(settings.portName));
        return;
    }
    if (sp_open(port, SP_MODE_READ_WRITE) != SP_OK) {
        const QString why = lastError();
        sp_free_port(port);
        emit failed(session, tr("Cannot open %1: %2").arg(settings.portName, why));
        return;
    }
    m_port = port;

    sp_port_config *config = nullptr;
    bool configured = sp_new_config(&config) == SP_OK;
    configured = configured && sp_set_config_baudrate(config, settings.baudRate) == SP_OK &&
                 sp_set_config_bits(config, settings.dataBits) == SP_OK &&
                 sp_set_config_parity(config, toSp(settings.parity)) == SP_OK &&
                 sp_set_config_stopbits(config, static_cast<int>(settings.stopBits)) == SP_OK &&
                 sp_set_config_flowcontrol(config, SP_FLOWCONTROL_NONE) == SP_OK &&
                 sp_set_config(m_port, config) == SP_OK;
    sp_free_config(config);
    if (!configured) {
        fail(tr("Cannot apply %1 baud %2 to %3: %4")
                 .arg(QString::number(settings.baudRate), settings.formatText(), settings.portName,
                      lastError()));
        return;
    }
    warnIfNotApplied();
    // Whatever a previous user left in the buffers is not an answer to us.
    sp_flush(m_port, SP_BUF_BOTH);

    int fd = -1;
    if (sp_get_port_handle(m_port, &fd) != SP_OK || fd < 0) {
        fail(tr("Cannot open %1: no file descriptor").arg(settings.portName));
        return;
    }
    m_notifier = new QSocketNotifier(fd, QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &SerialWorker::onReadable);
    qCDebug(lcLink).noquote() << "serial open" << settings.portName << settings.baudRate
                              << settings.formatText();
    emit opened(session);
}

void SerialWorker::warnIfNotApplied() const
{
    // Some drivers (cheap USB adapters, ptys) accept tcsetattr() yet keep their own parity or
    // character size; the session would only see timeouts, so say it in the log.
    sp_port_config *actual = nullptr;
    if (sp_new_config(&actual) != SP_OK)
        return;
    int baud = 0;
    int bits = 0;
    int stop = 0;
    sp_parity parity = SP_PARITY_INVALID;
    if (sp_get_config(m_port, actual) == SP_OK && sp_get_config_baudrate(actual, &baud) == SP_OK &&
        sp_get_config_bits(actual, &bits) == SP_OK &&
        sp_get_config_parity(actual, &parity) == SP_OK &&
        sp_get_config_stopbits(actual, &stop) == SP_OK &&
        (baud != m_settings.baudRate || bits != m_settings.dataBits ||
         parity != toSp(m_settings.parity) || stop != static_cast<int>(m_settings.stopBits))) {
        const char reported = parity == SP_PARITY_NONE   ? 'N'
                              : parity == SP_PARITY_EVEN ? 'E'
                              : parity == SP_PARITY_ODD  ? 'O'
                                                         : '?';
        qCWarning(lcLink).noquote().nospace()
            << "serial " << m_settings.portName << ": the driver did not take "
            << m_settings.baudRate << " " << m_settings.formatText() << "; it reports " << baud
            << " " << bits << reported << stop;
    }
    sp_free_config(actual);
}

void SerialWorker::closePort()
{
    release();
}

void SerialWorker::write(quint64 session, const QByteArray &bytes)
{
    if (session != m_session || !m_port || bytes.isEmpty())
        return;
    // Bounded: twice the wire time plus slack, so a stuck adapter fails instead of hanging the
    // worker (and with it the link's destructor) forever.
    const qint64 wireMs =
        bytes.size() * m_settings.bitsPerCharacter() * 1000 / std::max(1, m_settings.baudRate);
    const auto timeout = static_cast<unsigned>(std::min<qint64>(2 * wireMs + 500, 60'000));
    const auto size = static_cast<size_t>(bytes.size());
    const sp_return written = sp_blocking_write(m_port, bytes.constData(), size, timeout);
    if (written < 0)
        fail(tr("Write to %1 failed: %2").arg(m_settings.portName, lastError()));
    else if (static_cast<size_t>(written) < size)
        fail(tr("Write to %1 timed out").arg(m_settings.portName));
}

void SerialWorker::onReadable()
{
    if (!m_port)
        return;
    std::array<char, 4096> buffer{};
    const sp_return n = sp_nonblocking_read(m_port, buffer.data(), buffer.size());
    if (n > 0) {
        emit received(m_session, QByteArray(buffer.data(), n));
        return;
    }
    if (n < 0) {
        fail(tr("Read from %1 failed: %2").arg(m_settings.portName, lastError()));
        return;
    }
    int fd = -1;
    if (sp_get_port_handle(m_port, &fd) == SP_OK && hungUp(fd))
        fail(tr("Serial port %1 was disconnected").arg(m_settings.portName));
}

void SerialWorker::fail(const QString &reason)
{
    qCDebug(lcLink).noquote() << "serial failed" << m_settings.portName << reason;
    // Release first: the device must be free for a reopen by the time the link hears of it.
    release();
    emit failed(m_session, reason);
}

void SerialWorker::release()
{
    if (m_notifier) {
        // Disabled before the port closes, deleted later: release() may run inside the
        // notifier's own activated() emission.
        m_notifier->setEnabled(false);
        m_notifier->deleteLater();
        m_notifier = nullptr;
    }
    if (m_port) {
        sp_close(m_port);
        sp_free_port(m_port);
        m_port = nullptr;
    }
}

} // namespace vt::link
