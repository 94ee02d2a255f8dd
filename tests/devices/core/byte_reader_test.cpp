#include "core/byte_reader.h"

#include <array>
#include <gtest/gtest.h>

using vt::dev::ByteReader;

TEST(ByteReader, ReadsBigEndian)
{
    const std::array<std::uint8_t, 7> data{0x12, 0x34, 0xF4, 0x48, 0x00, 0x00, 0x03};
    ByteReader r(data);
    EXPECT_EQ(r.u16be(), 0x1234);
    EXPECT_EQ(r.i16be(), -3000);
    EXPECT_EQ(r.u16be(), 0x0000);
    EXPECT_EQ(r.u8(), 0x03);
    EXPECT_TRUE(r.atEnd());
    EXPECT_FALSE(r.failed());
}

TEST(ByteReader, FailureLatchesAndNeverReadsPastTheEnd)
{
    const std::array<std::uint8_t, 3> data{0x01, 0x02, 0x03};
    ByteReader r(data);
    EXPECT_EQ(r.u16be(), 0x0102);
    EXPECT_EQ(r.u16be(), 0u);
    EXPECT_TRUE(r.failed());
    EXPECT_EQ(r.failOffset(), 3u);
    EXPECT_EQ(r.u8(), 0u); // the byte is there, but the reader has failed
    EXPECT_TRUE(r.bytes(1).empty());
    EXPECT_EQ(r.remaining(), 0u);
}

TEST(ByteReader, ThirtyTwoBitAndSpans)
{
    const std::array<std::uint8_t, 6> data{0xFF, 0xFF, 0xFF, 0xFE, 0xAA, 0xBB};
    ByteReader r(data);
    EXPECT_EQ(r.i32be(), -2);
    auto s = r.bytes(2);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[1], 0xBB);
    EXPECT_TRUE(r.atEnd());
}
