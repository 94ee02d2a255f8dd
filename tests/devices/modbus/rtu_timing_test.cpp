// Modbus over Serial Line V1.02 §2.5.1.1 on an injected clock: the character time, t3.5 (and its
// fixed 1.75 ms above 19200 baud), when a master may send again after bytes in either direction,
// and when a received frame has ended.
#include "modbus/rtu_timing.h"

#include <gtest/gtest.h>

namespace vt::dev::modbus {
namespace {

TEST(ModbusRtuTiming, CharacterTimeCountsStartDataParityAndStopBits)
{
    EXPECT_EQ(characterTimeUs(19200, 11), 573); // 8E1: 11 bits, 572.9 µs rounded up
    EXPECT_EQ(characterTimeUs(9600, 10), 1042); // 8N1
    EXPECT_EQ(wireTimeUs(8, 19200, 11), 4584);  // an FC 3 request: 8 × 11 bits
    EXPECT_EQ(wireTimeUs(0, 19200, 11), 0);
}

TEST(ModbusRtuTiming, SilentIntervalIsThreeAndAHalfCharactersUpTo19200Baud)
{
    EXPECT_EQ(silentIntervalUs(19200, 11), 2006); // 38.5 bits at 19200 = 2005.2 µs
    EXPECT_EQ(silentIntervalUs(9600, 11), 4011);
    EXPECT_EQ(silentIntervalUs(9600, 10), 3646);
    EXPECT_EQ(silentIntervalUs(1200, 11), 32084);
}

TEST(ModbusRtuTiming, SilentIntervalIsFixedAbove19200Baud)
{
    EXPECT_EQ(silentIntervalUs(38400, 11), kFastLineSilenceUs);
    EXPECT_EQ(silentIntervalUs(115200, 10), kFastLineSilenceUs);
    EXPECT_EQ(silentIntervalUs(0, 11), 0); // no serial wire, no interval
}

TEST(ModbusRtuTiming, FirstRequestGoesOutAtOnce)
{
    const RtuLineClock line(19200, 11);
    EXPECT_LE(line.sendAllowedAtUs(), 0);
}

TEST(ModbusRtuTiming, NextRequestWaitsForSilenceAfterTheLastByteReceived)
{
    RtuLineClock line(19200, 11);
    line.sent(8, 1'000);
    line.received(20'000); // the answer's first bytes
    line.received(25'000); // its last byte
    EXPECT_EQ(line.sendAllowedAtUs(), 25'000 + 2006);
    EXPECT_EQ(line.frameEndsAtUs(), 25'000 + 2006);
}

TEST(ModbusRtuTiming, WithoutAnAnswerTheOwnRequestsLastByteCounts)
{
    // A request that timed out: the line was last busy with our own bytes, which leave the
    // transmitter one character after the other.
    RtuLineClock line(115200, 11);
    line.sent(8, 10'000);
    const std::int64_t lastStopBit = 10'000 + 8 * characterTimeUs(115200, 11);
    EXPECT_EQ(line.sendAllowedAtUs(), lastStopBit + kFastLineSilenceUs);
    // Bytes handed over while the first are still being sent queue behind them.
    line.sent(8, 10'100);
    EXPECT_EQ(line.sendAllowedAtUs(),
              lastStopBit + 8 * characterTimeUs(115200, 11) + kFastLineSilenceUs);
}

TEST(ModbusRtuTiming, ALateByteMovesTheFrameEnd)
{
    RtuLineClock line(19200, 11);
    line.received(1'000);
    const std::int64_t firstEnd = line.frameEndsAtUs();
    line.received(1'500); // within t3.5: the same frame goes on
    EXPECT_EQ(line.frameEndsAtUs(), firstEnd + 500);
    line.received(1'200); // a clock read out of order never moves it back
    EXPECT_EQ(line.frameEndsAtUs(), firstEnd + 500);
}

} // namespace
} // namespace vt::dev::modbus
