// Serial port enumeration through libserialport: what the connect dialog and `valvetune-cli
// --list-ports` offer. Reads sysfs and opens only the legacy 8250 ports (non-blocking) to see
// whether they exist, so it returns promptly; reentrant, callable from any thread.
#pragma once

#include <QString>
#include <cstdint>
#include <optional>
#include <vector>

namespace vt::link {

enum class SerialTransport { Native, Usb, Bluetooth };

struct SerialPortInfo
{
    QString name;        // "/dev/ttyUSB0"
    QString description; // "FT232R USB UART", or the device name when nothing better is known
    SerialTransport transport = SerialTransport::Native;
    std::optional<std::uint16_t> usbVid;
    std::optional<std::uint16_t> usbPid;
    QString manufacturer; // USB only
    QString serialNumber; // USB only

    // "/dev/ttyUSB0 — FT232R USB UART (0403:6001)" for lists.
    QString displayText() const;
};

// Sorted by name; empty when there are no ports or the platform cannot enumerate them.
std::vector<SerialPortInfo> availableSerialPorts();

} // namespace vt::link
