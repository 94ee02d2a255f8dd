// Modbus RTU line timing (Modbus over Serial Line V1.02 §2.5.1.1): the character time, the
// silent interval t3.5 that separates frames, and RtuLineClock, which keeps track of the last
// byte seen on a half-duplex line to say when a master may send again and when a received frame
// has ended. Times are plain microseconds from any monotonic clock the caller owns, so the rules
// are tested without a wall clock. A plain value; not thread-safe (one link worker drives it).
#pragma once

#include <cstddef>
#include <cstdint>

namespace vt::dev::modbus {

// §2.5.1.1: above 19200 baud the silent interval is a fixed 1.75 ms (the 3.5 characters would
// load the receiver's CPU with an interrupt per few microseconds).
inline constexpr std::int64_t kFastLineSilenceUs = 1750;

// One character on the wire: start + data + parity + stop bits at `baud`, in microseconds
// (rounded up). `bitsPerCharacter` 11 for 8E1, 10 for 8N1.
std::int64_t characterTimeUs(int baud, int bitsPerCharacter);
// Time on the wire of `bytes` characters, rounded up.
std::int64_t wireTimeUs(std::size_t bytes, int baud, int bitsPerCharacter);
// t3.5: 3.5 characters, rounded up; 1750 µs above 19200 baud (§2.5.1.1).
std::int64_t silentIntervalUs(int baud, int bitsPerCharacter);

// The line as one station sees it: when the last byte in either direction left the wire.
class RtuLineClock
{
public:
    RtuLineClock(int baud, int bitsPerCharacter);

    // Bytes read from the line at `nowUs`: their last stop bit ended no later than that.
    void received(std::int64_t nowUs);
    // `bytes` handed to the transmitter at `nowUs`: they leave one character after the other,
    // after whatever is still being transmitted.
    void sent(std::size_t bytes, std::int64_t nowUs);

    // The earliest time a request may start: t3.5 after the last byte on the line.
    std::int64_t sendAllowedAtUs() const { return m_lineBusyUntilUs + m_silenceUs; }
    // When a frame whose last byte was received at the last received() call ends, unless more
    // bytes follow before then (§2.5.1.1: t3.5 of silence marks the end of a frame).
    std::int64_t frameEndsAtUs() const { return m_lastReceivedUs + m_silenceUs; }

    std::int64_t silenceUs() const { return m_silenceUs; }
    std::int64_t characterUs() const { return m_characterUs; }

private:
    std::int64_t m_characterUs;
    std::int64_t m_silenceUs;
    std::int64_t m_lineBusyUntilUs;
    std::int64_t m_lastReceivedUs;
};

} // namespace vt::dev::modbus
