// Streaming de-framers: frames split over many reads, several frames per read, garbage between
// frames (RTU resynchronises by CRC), and the bounded MBAP length for TCP.
#include "modbus/deframer.h"
#include "modbus/rtu.h"
#include "modbus_vectors.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::modbus;
using namespace vt::test::modbus_vectors;

namespace {

Bytes concat(std::initializer_list<Bytes> parts)
{
    Bytes out;
    for (const Bytes &p : parts)
        out.insert(out.end(), p.begin(), p.end());
    return out;
}

} // namespace

TEST(ModbusRtuDeframer, FrameSplitByteByByte)
{
    RtuDeframer d(Direction::Response);
    std::vector<Bytes> got;
    for (std::uint8_t b : kRtuReadD107Response) {
        EXPECT_TRUE(got.empty());
        for (Bytes &f : d.feed(std::span<const std::uint8_t>(&b, 1)))
            got.push_back(std::move(f));
    }
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0], kRtuReadD107Response);
    EXPECT_EQ(d.buffered(), 0u);
    EXPECT_EQ(d.discarded(), 0u);
}

TEST(ModbusRtuDeframer, ThreeFramesInOneRead)
{
    RtuDeframer d(Direction::Response);
    const auto frames = d.feed(concat({kRtuReadD107Response, kRtuWriteC107, kRtuReadWrongId}));
    ASSERT_EQ(frames.size(), 3u);
    EXPECT_EQ(frames[0], kRtuReadD107Response);
    EXPECT_EQ(frames[1], kRtuWriteC107);
    EXPECT_EQ(frames[2], kRtuReadWrongId);
    EXPECT_EQ(d.discarded(), 0u);
}

TEST(ModbusRtuDeframer, GarbageBeforeAFrame)
{
    RtuDeframer d(Direction::Request);
    const Bytes garbage{0xFF, 0x00, 0x42, 0x13};
    const auto frames = d.feed(concat({garbage, kRtuReadD107}));
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0], kRtuReadD107);
    EXPECT_EQ(d.discarded(), garbage.size());
}

TEST(ModbusRtuDeframer, GarbageThatLooksLikeALongFrameHeader)
{
    // "01 03 FA" announces a 255-byte FC 3 response; the real answer behind it must not wait for
    // that.
    RtuDeframer d(Direction::Response);
    const Bytes garbage{0x01, 0x03, 0xFA};
    auto frames = d.feed(garbage);
    EXPECT_TRUE(frames.empty());
    frames = d.feed(std::span<const std::uint8_t>(kRtuReadD107Response).first(4));
    EXPECT_TRUE(frames.empty());
    frames = d.feed(std::span<const std::uint8_t>(kRtuReadD107Response).subspan(4));
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0], kRtuReadD107Response);
    EXPECT_EQ(d.discarded(), 3u);
}

TEST(ModbusRtuDeframer, CorruptCrcThenAGoodFrame)
{
    RtuDeframer d(Direction::Request);
    Bytes corrupt = kRtuWriteC107;
    corrupt.back() ^= 0x5A;
    const auto frames = d.feed(concat({corrupt, kRtuReadD107}));
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0], kRtuReadD107);
    EXPECT_EQ(d.discarded(), corrupt.size());
    EXPECT_EQ(d.buffered(), 0u);
}

TEST(ModbusRtuDeframer, CorruptFrameAndGoodFrameArrivingInPieces)
{
    RtuDeframer d(Direction::Response);
    Bytes corrupt = kRtuReadD107Response;
    corrupt[3] ^= 0x01;
    const Bytes stream = concat({corrupt, kRtuWriteC107, {0x00, 0x00}, kRtuReadWrongId});
    std::vector<Bytes> got;
    for (std::size_t i = 0; i < stream.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, stream.size() - i);
        for (Bytes &f : d.feed(std::span<const std::uint8_t>(stream).subspan(i, n)))
            got.push_back(std::move(f));
    }
    ASSERT_EQ(got.size(), 2u);
    EXPECT_EQ(got[0], kRtuWriteC107);
    EXPECT_EQ(got[1], kRtuReadWrongId);
}

TEST(ModbusRtuDeframer, SilenceDropsAPartialFrame)
{
    RtuDeframer d(Direction::Request);
    EXPECT_TRUE(d.feed(std::span<const std::uint8_t>(kRtuReadD107).first(5)).empty());
    EXPECT_EQ(d.buffered(), 5u);
    d.silence();
    EXPECT_EQ(d.buffered(), 0u);
    EXPECT_EQ(d.discarded(), 5u);
    const auto frames = d.feed(kRtuReadD107);
    ASSERT_EQ(frames.size(), 1u);
}

TEST(ModbusRtuDeframer, DirectionDecidesTheLayout)
{
    // A request-direction de-framer does not frame exceptions; a response one does not frame
    // an FC 3 request as a response (its "byte count" is the start address high byte).
    RtuDeframer requests(Direction::Request);
    EXPECT_TRUE(requests.feed(kRtuReadWrongId).empty());
    RtuDeframer responses(Direction::Response);
    EXPECT_TRUE(responses.feed(kRtuReadD107).empty());
}

TEST(ModbusRtuDeframer, LongestResponseByteByByte)
{
    const Bytes big =
        encodeRtu(RtuResponse{1, ReadResponse{std::vector<std::uint16_t>(125, 0x0103)}}).value();
    RtuDeframer d(Direction::Response);
    std::vector<Bytes> got;
    for (std::uint8_t b : big)
        for (Bytes &f : d.feed(std::span<const std::uint8_t>(&b, 1)))
            got.push_back(std::move(f));
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0], big);
}

TEST(ModbusTcpDeframer, SplitAndMultipleFrames)
{
    TcpDeframer d;
    const Bytes stream = concat({kTcpReadD107Response, kTcpWriteC107, kTcpReadWrongId});
    std::vector<Bytes> got;
    for (std::uint8_t b : stream)
        for (Bytes &f : d.feed(std::span<const std::uint8_t>(&b, 1)))
            got.push_back(std::move(f));
    ASSERT_EQ(got.size(), 3u);
    EXPECT_EQ(got[0], kTcpReadD107Response);
    EXPECT_EQ(got[2], kTcpReadWrongId);
    const auto all = d.feed(stream);
    ASSERT_EQ(all.size(), 3u);
    EXPECT_FALSE(d.error());
}

TEST(ModbusTcpDeframer, OversizedLengthLatchesUntilReset)
{
    TcpDeframer d;
    const Bytes huge{0x00, 0x01, 0x00, 0x00,
                     0x01, 0x05, 0x01}; // length 261: ADU would be 267 bytes
    EXPECT_TRUE(d.feed(concat({kTcpReadD107, huge})).size() == 1u);
    ASSERT_TRUE(d.error());
    EXPECT_EQ(d.error()->code, DecodeErrc::BadLength);
    EXPECT_EQ(d.error()->offset, 4u);
    EXPECT_TRUE(d.feed(kTcpReadD107).empty()); // out of step: nothing more until reset
    d.reset();
    EXPECT_EQ(d.feed(kTcpReadD107).size(), 1u);
    const Bytes notModbus{0x00, 0x01, 0x00, 0x07, 0x00, 0x06, 0x01};
    EXPECT_TRUE(d.feed(notModbus).empty());
    EXPECT_EQ(d.error()->code, DecodeErrc::BadValue);
}
