// SerialSettings: the line settings of one serial port (port name, baud, data bits, parity, stop
// bits) with the presets the manuals prescribe. A plain value; copy it freely between threads.
#pragma once

#include <QString>
#include <QStringView>
#include <optional>

namespace vt::link {

enum class Parity { None, Even, Odd };
enum class StopBits { One = 1, Two = 2 };

struct SerialSettings
{
    QString portName; // "/dev/ttyUSB0"
    int baudRate = 19200;
    int dataBits = 8; // 5..8
    Parity parity = Parity::Even;
    StopBits stopBits = StopBits::One;
    // Modbus RTU line timing (Modbus over Serial Line §2.5.1.1, devices/modbus/rtu_timing.h):
    // keep t3.5 of silence after the last byte on the line before each write, and deliver what
    // arrives as one chunk per frame, ended by t3.5 of silence (followed by Link::lineQuiet()).
    // On for Modbus RTU (hcsDefault), off for other protocols (HART has its own rules).
    bool silentInterval = false;
    bool frameEndBySilence = false;

    // ARCHITECTURE.md "Protocol decisions": HCS modules talk Modbus RTU at 19200 8E1 by default,
    // with the RTU line timing on.
    static SerialSettings hcsDefault(const QString &portName);
    // ARCHITECTURE.md "HART": 1200 baud 8O1 through a HART modem.
    static SerialSettings hart(const QString &portName);

    // "8E1", "8N2", "7O1".
    QString formatText() const;
    // Parses formatText()'s form (case-insensitive); leaves the settings untouched on failure.
    bool setFormatText(QStringView text);
    // Start bit + data bits + parity bit + stop bits: 11 for 8E1, 10 for 8N1.
    int bitsPerCharacter() const;
    // Why these settings cannot be applied, or nothing if they can.
    std::optional<QString> problem() const;

    friend bool operator==(const SerialSettings &, const SerialSettings &) = default;
};

QChar parityLetter(Parity parity);

} // namespace vt::link
