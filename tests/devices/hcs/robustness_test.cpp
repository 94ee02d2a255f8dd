// Truncated, padded and garbage telegrams give typed errors at the right offset; decoding,
// describing and re-encoding are total on arbitrary input and agree with each other.
#include "hcs/describe.h"
#include "hcs/telegram.h"
#include "worked_examples.h"

#include <gtest/gtest.h>
#include <random>

using namespace vt::dev;
using namespace vt::dev::hcs;
using namespace vt::test::hcs_examples;

namespace {

Result<std::monostate, DecodeError> decodeAny(std::span<const std::uint8_t> bytes, Family family,
                                              Direction direction, bool padding = false)
{
    const DecodeOptions o{family, padding};
    if (direction == Direction::Request) {
        auto r = decodeRequest(bytes, o);
        return r.ok() ? Result<std::monostate, DecodeError>(std::monostate{}) : r.error();
    }
    auto r = decodeResponse(bytes, o);
    return r.ok() ? Result<std::monostate, DecodeError>(std::monostate{}) : r.error();
}

} // namespace

TEST(HcsRobustness, EveryPrefixOfEveryExampleIsTruncatedAtItsEnd)
{
    for (const Example &ex : allExamples()) {
        for (std::size_t n = 0; n < ex.bytes.size(); ++n) {
            const std::span<const std::uint8_t> prefix(ex.bytes.data(), n);
            auto r = decodeAny(prefix, ex.family, ex.direction);
            ASSERT_FALSE(r.ok()) << ex.name << " prefix " << n;
            EXPECT_EQ(r.error().code, DecodeErrc::Truncated) << ex.name << " prefix " << n;
            EXPECT_EQ(r.error().offset, n) << ex.name << " prefix " << n; // the first missing byte
        }
    }
}

TEST(HcsRobustness, ExtraByteIsTooLongUnlessPaddingIsAllowed)
{
    for (const Example &ex : allExamples()) {
        Bytes longer = ex.bytes;
        longer.push_back(0xAA);
        auto r = decodeAny(longer, ex.family, ex.direction);
        ASSERT_FALSE(r.ok()) << ex.name;
        EXPECT_EQ(r.error().code, DecodeErrc::TooLong) << ex.name;
        EXPECT_EQ(r.error().offset, ex.bytes.size()) << ex.name;
        EXPECT_TRUE(decodeAny(longer, ex.family, ex.direction, true).ok()) << ex.name;
    }
}

TEST(HcsRobustness, UnknownCommandsAreUnexpectedAtOffset2)
{
    const Bytes q{0x01, 0x01, 0x04, 0x00, 0x00, 0x00, 0x00};
    auto r = decodeRequest(q);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, DecodeErrc::UnexpectedCommand);
    EXPECT_EQ(r.error().offset, 2u);
    // An error response to a command that does not exist.
    const Bytes e{0x01, 0x01, 0x84, 0x01};
    auto a = decodeResponse(e);
    ASSERT_FALSE(a.ok());
    EXPECT_EQ(a.error().code, DecodeErrc::UnexpectedCommand);
    EXPECT_EQ(a.error().offset, 2u);
    // A request never carries bit 7.
    auto b = decodeRequest(kDma33ReadError);
    ASSERT_FALSE(b.ok());
    EXPECT_EQ(b.error().code, DecodeErrc::UnexpectedCommand);
    // Typed decoders refuse the other commands.
    auto c = decodeReadRequest(kDma37Write);
    ASSERT_FALSE(c.ok());
    EXPECT_EQ(c.error().code, DecodeErrc::UnexpectedCommand);
    auto d = decodeWriteResponse(kDma33ReadError);
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error().code, DecodeErrc::UnexpectedCommand);
}

TEST(HcsRobustness, OddCntIsBadLengthAtOffset3)
{
    const Bytes a{0x24, 0x01, 0x03, 0x03, 0x01, 0x33, 0x00};
    auto r = decodeReadResponse(a);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, DecodeErrc::BadLength);
    EXPECT_EQ(r.error().offset, 3u);
}

TEST(HcsRobustness, LargeCntTruncatedWhereTheDataEnds)
{
    // CNT 0xFE announces 254 data bytes; only 2 follow.
    const Bytes a{0x24, 0x01, 0x03, 0xFE, 0x01, 0x33};
    auto r = decodeReadResponse(a);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, DecodeErrc::Truncated);
    EXPECT_EQ(r.error().offset, 6u);
}

TEST(HcsRobustness, ReadResponseEncodeRefusesMoreThan127Values)
{
    ReadResponse a{1, 1, std::vector<std::uint16_t>(128, 0)};
    auto r = encode(a);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, DecodeErrc::BadValue);
    a.values.resize(127);
    ASSERT_TRUE(encode(a).ok());
    EXPECT_EQ(encode(a)->size(), 4u + 254u);
}

TEST(HcsRobustness, RandomFramesNeverCrashAndAgreeWithDescribe)
{
    std::mt19937 rng(20240611);
    std::uniform_int_distribution<int> len(0, 50);
    std::uniform_int_distribution<int> byte(0, 255);
    const std::uint8_t cmds[] = {3, 6, 15, 0x83, 0x86, 0x8F};
    for (int i = 0; i < 20000; ++i) {
        Bytes frame(static_cast<std::size_t>(len(rng)));
        for (auto &b : frame)
            b = static_cast<std::uint8_t>(byte(rng));
        if (frame.size() > 2 && i % 2 == 0) // keep half of them plausible
            frame[2] = cmds[static_cast<std::size_t>(i / 2) % 6];
        const Family family = i % 3 == 0 ? Family::Opat : Family::Dma;
        const Direction direction = i % 4 < 2 ? Direction::Request : Direction::Response;
        const Description d = describe(frame, DescribeOptions{family, direction});
        auto r = decodeAny(frame, family, direction);
        ASSERT_EQ(d.ok(), r.ok());
        if (!r.ok()) {
            EXPECT_EQ(*d.error, r.error());
            EXPECT_LE(r.error().offset, frame.size());
            continue;
        }
        // A frame that decodes re-encodes to the same bytes.
        if (direction == Direction::Request) {
            auto q = decodeRequest(frame, {family, false});
            auto back = encode(*q, family);
            ASSERT_TRUE(back.ok());
            EXPECT_EQ(*back, frame);
        } else {
            auto a = decodeResponse(frame, {family, false});
            auto back = encode(*a);
            ASSERT_TRUE(back.ok());
            EXPECT_EQ(*back, frame);
        }
    }
}
