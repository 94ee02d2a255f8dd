#include "termios_line.h"

#include <cstring>

namespace vt::link {

namespace {

// The rates termios names; Linux adds the high ones (termios(3), "Line control").
struct Speed
{
    int rate;
    speed_t speed;
};

constexpr Speed kSpeeds[] = {
    {50, B50},           {75, B75},           {110, B110},         {134, B134},
    {150, B150},         {200, B200},         {300, B300},         {600, B600},
    {1200, B1200},       {1800, B1800},       {2400, B2400},       {4800, B4800},
    {9600, B9600},       {19200, B19200},     {38400, B38400},     {57600, B57600},
    {115200, B115200},   {230400, B230400},
#ifdef B4000000
    {460800, B460800},   {500000, B500000},   {576000, B576000},   {921600, B921600},
    {1000000, B1000000}, {1152000, B1152000}, {1500000, B1500000}, {2000000, B2000000},
    {2500000, B2500000}, {3000000, B3000000}, {3500000, B3500000}, {4000000, B4000000},
#endif
};

tcflag_t characterSize(int dataBits)
{
    switch (dataBits) {
    case 5: return CS5;
    case 6: return CS6;
    case 7: return CS7;
    default: return CS8;
    }
}

} // namespace

std::optional<speed_t> termiosSpeed(int baudRate)
{
    for (const Speed &s : kSpeeds)
        if (s.rate == baudRate)
            return s.speed;
    return std::nullopt;
}

int termiosBaud(speed_t speed)
{
    for (const Speed &s : kSpeeds)
        if (s.speed == speed)
            return s.rate;
    return 0;
}

bool applyLineSettings(termios &t, const SerialSettings &settings)
{
    const auto speed = termiosSpeed(settings.baudRate);
    if (!speed)
        return false;
    termios n = t;
    ::cfmakeraw(&n);
    // CLOCAL: a line without carrier detect (RS-485 adapters, ptys) still reads and writes.
    n.c_cflag |= CLOCAL | CREAD;
    n.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD | CSTOPB);
#ifdef CRTSCTS
    n.c_cflag &= ~static_cast<tcflag_t>(CRTSCTS);
#endif
    n.c_cflag |= characterSize(settings.dataBits);
    if (settings.parity != Parity::None)
        n.c_cflag |= PARENB;
    if (settings.parity == Parity::Odd)
        n.c_cflag |= PARODD;
    if (settings.stopBits == StopBits::Two)
        n.c_cflag |= CSTOPB;
    n.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY | INPCK | IGNPAR | PARMRK | ISTRIP);
    // With parity on, the driver checks it; without, nothing to check (libserialport's marks).
    n.c_iflag |= settings.parity == Parity::None ? IGNPAR : INPCK;
    n.c_cc[VMIN] = 1;
    n.c_cc[VTIME] = 0;
    ::cfsetispeed(&n, *speed);
    ::cfsetospeed(&n, *speed);
    t = n;
    return true;
}

bool differsOnlyInCharacterFormat(const termios &held, const termios &wanted)
{
    const tcflag_t format = CSIZE | PARENB;
    return held.c_iflag == wanted.c_iflag && held.c_oflag == wanted.c_oflag &&
           held.c_lflag == wanted.c_lflag &&
           (held.c_cflag & ~format) == (wanted.c_cflag & ~format) &&
           std::memcmp(held.c_cc, wanted.c_cc, sizeof held.c_cc) == 0 &&
           ::cfgetispeed(&held) == ::cfgetispeed(&wanted) &&
           ::cfgetospeed(&held) == ::cfgetospeed(&wanted);
}

} // namespace vt::link
