#include "serial_settings.h"

#include <QCoreApplication>

namespace vt::link {

SerialSettings SerialSettings::hcsDefault(const QString &portName)
{
    SerialSettings s;
    s.portName = portName;
    s.baudRate = 19200;
    s.dataBits = 8;
    s.parity = Parity::Even;
    s.stopBits = StopBits::One;
    s.silentInterval = true;
    s.frameEndBySilence = true;
    return s;
}

SerialSettings SerialSettings::hart(const QString &portName)
{
    SerialSettings s;
    s.portName = portName;
    s.baudRate = 1200;
    s.dataBits = 8;
    s.parity = Parity::Odd;
    s.stopBits = StopBits::One;
    return s;
}

QChar parityLetter(Parity parity)
{
    switch (parity) {
    case Parity::None: return QLatin1Char('N');
    case Parity::Even: return QLatin1Char('E');
    case Parity::Odd: return QLatin1Char('O');
    }
    return QLatin1Char('?');
}

QString SerialSettings::formatText() const
{
    return QString::number(dataBits) + parityLetter(parity) +
           QString::number(static_cast<int>(stopBits));
}

bool SerialSettings::setFormatText(QStringView text)
{
    const QString t = text.trimmed().toString().toUpper();
    if (t.size() != 3)
        return false;
    const char16_t bits = t[0].unicode();
    const char16_t par = t[1].unicode();
    const char16_t stop = t[2].unicode();
    if (bits < u'5' || bits > u'8')
        return false;
    Parity parsedParity = Parity::None;
    switch (par) {
    case u'N': parsedParity = Parity::None; break;
    case u'E': parsedParity = Parity::Even; break;
    case u'O': parsedParity = Parity::Odd; break;
    default: return false;
    }
    if (stop != u'1' && stop != u'2')
        return false;
    dataBits = bits - u'0';
    parity = parsedParity;
    stopBits = stop == u'1' ? StopBits::One : StopBits::Two;
    return true;
}

int SerialSettings::bitsPerCharacter() const
{
    return 1 + dataBits + (parity == Parity::None ? 0 : 1) + static_cast<int>(stopBits);
}

std::optional<QString> SerialSettings::problem() const
{
    const char *ctx = "vt::link::SerialSettings";
    if (portName.isEmpty())
        return QCoreApplication::translate(ctx, "No serial port selected");
    if (baudRate <= 0)
        return QCoreApplication::translate(ctx, "Invalid baud rate %1").arg(baudRate);
    if (dataBits < 5 || dataBits > 8)
        return QCoreApplication::translate(ctx, "Invalid number of data bits %1").arg(dataBits);
    return std::nullopt;
}

} // namespace vt::link
