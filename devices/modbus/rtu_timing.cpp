#include "rtu_timing.h"

#include <algorithm>
#include <limits>

namespace vt::dev::modbus {

namespace {

// Far enough in the past that the first request goes out at once.
constexpr std::int64_t kLongAgo = std::numeric_limits<std::int64_t>::min() / 4;

std::int64_t ceilDiv(std::int64_t a, std::int64_t b)
{
    return (a + b - 1) / b;
}

} // namespace

std::int64_t characterTimeUs(int baud, int bitsPerCharacter)
{
    return baud <= 0 ? 0 : ceilDiv(std::int64_t{bitsPerCharacter} * 1'000'000, baud);
}

std::int64_t wireTimeUs(std::size_t bytes, int baud, int bitsPerCharacter)
{
    if (baud <= 0)
        return 0;
    return ceilDiv(static_cast<std::int64_t>(bytes) * bitsPerCharacter * 1'000'000, baud);
}

std::int64_t silentIntervalUs(int baud, int bitsPerCharacter)
{
    if (baud <= 0)
        return 0;
    if (baud > 19200)
        return kFastLineSilenceUs;
    // 3.5 characters = 7 half characters.
    return ceilDiv(std::int64_t{bitsPerCharacter} * 7 * 1'000'000, std::int64_t{baud} * 2);
}

RtuLineClock::RtuLineClock(int baud, int bitsPerCharacter)
    : m_characterUs(characterTimeUs(baud, bitsPerCharacter)),
      m_silenceUs(silentIntervalUs(baud, bitsPerCharacter)), m_lineBusyUntilUs(kLongAgo),
      m_lastReceivedUs(kLongAgo)
{
}

void RtuLineClock::received(std::int64_t nowUs)
{
    m_lastReceivedUs = std::max(m_lastReceivedUs, nowUs);
    m_lineBusyUntilUs = std::max(m_lineBusyUntilUs, nowUs);
}

void RtuLineClock::sent(std::size_t bytes, std::int64_t nowUs)
{
    const std::int64_t start = std::max(m_lineBusyUntilUs, nowUs);
    m_lineBusyUntilUs = start + static_cast<std::int64_t>(bytes) * m_characterUs;
}

} // namespace vt::dev::modbus
