// SerialPortIo: one open serial port as SerialWorker drives it — a descriptor to watch for
// input, non-blocking reads, bounded writes. Two ways to open one: libserialport, which knows
// real UARTs and USB adapters but looks every name up in sysfs and reads the modem lines on
// open, and plain POSIX termios for any other terminal (a pseudo-terminal from socat, ser2net or
// tty0tty, a Bluetooth or network serial device), which libserialport refuses.
// Owned and used by SerialWorker on its worker thread only.
#pragma once

#include "transports/serial_settings.h"

#include <QString>
#include <cstddef>
#include <memory>
#include <optional>

namespace vt::link {

// What the driver reports holding, to warn when it did not take the settings.
struct LineFormat
{
    int baudRate = 0;
    int dataBits = 0;
    Parity parity = Parity::None;
    StopBits stopBits = StopBits::One;

    bool matches(const SerialSettings &s) const
    {
        return baudRate == s.baudRate && dataBits == s.dataBits && parity == s.parity &&
               stopBits == s.stopBits;
    }
};

class SerialPortIo
{
public:
    virtual ~SerialPortIo() = default;

    virtual int descriptor() const = 0;
    // Bytes read; 0 when nothing waits; -1 on an error (errorText()).
    virtual long long read(char *buffer, std::size_t size) = 0;
    // Bytes written before `timeoutMs` passed, or -1 on an error (errorText()).
    virtual long long write(const char *data, std::size_t size, unsigned timeoutMs) = 0;
    // Bytes the driver took at once (0 when its buffer is full), or -1 on an error: never waits.
    virtual long long writeSome(const char *data, std::size_t size) = 0;
    // Drops what either direction holds.
    virtual void flush() = 0;
    virtual std::optional<LineFormat> lineFormat() = 0;
    // The system's text for the last error ("No such file or directory").
    virtual QString errorText() const = 0;
};

// Why a port did not open; SerialWorker words it.
struct OpenFailure
{
    enum class Kind {
        NotFound,         // no such device
        PermissionDenied, // the user may not open it: group names the group that may
        CannotOpen,       // open() refused for another reason: detail says why (busy …)
        NotATerminal,     // a file or device that is no tty
        UnsupportedBaud,  // termios has no such rate
        CannotConfigure   // the driver refused the line settings: detail says why
    };
    Kind kind = Kind::NotFound;
    QString detail;
    QString group; // PermissionDenied: the group to join (serialPortGroup())
};

// The kind of failure an open() that set errno `code` is.
OpenFailure::Kind openFailureKind(int code);
// The group whose members may open the port at `path`: the device's own group when it grants
// read and write (dialout on Debian, uucp on Arch), else the usual serial group, dialout.
QString serialPortGroup(const QString &path);
// The failure of an open() of `path` that set errno `code`, with the system's text and, for a
// permission problem, the group to join.
OpenFailure openFailure(const QString &path, int code, const QString &systemText);

// libserialport: nullptr when it cannot find or open the port (*failure says why; the termios
// way may still succeed then) or refuses the line settings (CannotConfigure: final).
std::unique_ptr<SerialPortIo> openWithLibserialport(const SerialSettings &settings,
                                                    OpenFailure *failure);
// POSIX open(O_NOCTTY) + termios, raw mode: nullptr (*failure says why) when the path is
// missing, no terminal or refuses the settings.
std::unique_ptr<SerialPortIo> openWithTermios(const SerialSettings &settings, OpenFailure *failure);

} // namespace vt::link
