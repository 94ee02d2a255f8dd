// The libserialport way of SerialPortIo (serial_port_io.h): sp_get_port_by_name() (a sysfs
// look-up on Linux), sp_open() (which reads the modem control lines), sp_set_config().
#include "serial_port_io.h"

#include <libserialport.h>

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

// libserialport's description of its last error ("No such file or directory").
QString lastError()
{
    char *message = sp_last_error_message();
    QString text = message ? QString::fromLocal8Bit(message).trimmed() : QString();
    sp_free_error_message(message);
    return text;
}

class SpPort final : public SerialPortIo
{
public:
    explicit SpPort(sp_port *port) : m_port(port) { sp_get_port_handle(m_port, &m_fd); }
    ~SpPort() override
    {
        sp_close(m_port);
        sp_free_port(m_port);
    }
    SpPort(const SpPort &) = delete;
    SpPort &operator=(const SpPort &) = delete;

    int descriptor() const override { return m_fd; }

    long long read(char *buffer, std::size_t size) override
    {
        const sp_return n = sp_nonblocking_read(m_port, buffer, size);
        if (n < 0)
            m_error = lastError();
        return n < 0 ? -1 : n;
    }

    long long write(const char *data, std::size_t size, unsigned timeoutMs) override
    {
        const sp_return n = sp_blocking_write(m_port, data, size, timeoutMs);
        if (n < 0)
            m_error = lastError();
        return n < 0 ? -1 : n;
    }

    long long writeSome(const char *data, std::size_t size) override
    {
        const sp_return n = sp_nonblocking_write(m_port, data, size);
        if (n < 0)
            m_error = lastError();
        return n < 0 ? -1 : n;
    }

    void flush() override { sp_flush(m_port, SP_BUF_BOTH); }

    std::optional<LineFormat> lineFormat() override
    {
        sp_port_config *actual = nullptr;
        if (sp_new_config(&actual) != SP_OK)
            return std::nullopt;
        int baud = 0;
        int bits = 0;
        int stop = 0;
        sp_parity parity = SP_PARITY_INVALID;
        std::optional<LineFormat> format;
        if (sp_get_config(m_port, actual) == SP_OK &&
            sp_get_config_baudrate(actual, &baud) == SP_OK &&
            sp_get_config_bits(actual, &bits) == SP_OK &&
            sp_get_config_parity(actual, &parity) == SP_OK &&
            sp_get_config_stopbits(actual, &stop) == SP_OK) {
            format = LineFormat{baud, bits,
                                parity == SP_PARITY_ODD    ? Parity::Odd
                                : parity == SP_PARITY_EVEN ? Parity::Even
                                                           : Parity::None,
                                stop == 2 ? StopBits::Two : StopBits::One};
        }
        sp_free_config(actual);
        return format;
    }

    QString errorText() const override { return m_error; }

private:
    sp_port *m_port;
    int m_fd = -1;
    QString m_error;
};

} // namespace

std::unique_ptr<SerialPortIo> openWithLibserialport(const SerialSettings &settings,
                                                    OpenFailure *failure)
{
    const QByteArray name = settings.portName.toLocal8Bit();
    sp_port *port = nullptr;
    if (sp_get_port_by_name(name.constData(), &port) != SP_OK) {
        // No sysfs entry: no such device, or one libserialport does not know (a pty, a
        // /dev/serial/by-id link).
        *failure = {OpenFailure::Kind::NotFound, lastError(), {}};
        return nullptr;
    }
    if (const sp_return opened = sp_open(port, SP_MODE_READ_WRITE); opened != SP_OK) {
        // SP_ERR_FAIL: the system refused, and sp_last_error_code() is its errno.
        *failure = opened == SP_ERR_FAIL
                       ? openFailure(settings.portName, sp_last_error_code(), lastError())
                       : OpenFailure{OpenFailure::Kind::CannotOpen, lastError(), {}};
        sp_free_port(port);
        return nullptr;
    }
    auto io = std::make_unique<SpPort>(port);
    sp_port_config *config = nullptr;
    bool configured = sp_new_config(&config) == SP_OK;
    configured = configured && sp_set_config_baudrate(config, settings.baudRate) == SP_OK &&
                 sp_set_config_bits(config, settings.dataBits) == SP_OK &&
                 sp_set_config_parity(config, toSp(settings.parity)) == SP_OK &&
                 sp_set_config_stopbits(config, static_cast<int>(settings.stopBits)) == SP_OK &&
                 sp_set_config_flowcontrol(config, SP_FLOWCONTROL_NONE) == SP_OK &&
                 sp_set_config(port, config) == SP_OK;
    sp_free_config(config);
    if (!configured || io->descriptor() < 0) {
        *failure = {OpenFailure::Kind::CannotConfigure, lastError(), {}};
        return nullptr;
    }
    return io;
}

} // namespace vt::link
