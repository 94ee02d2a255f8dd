#include "core/hex.h"

#include <gtest/gtest.h>

using vt::dev::Bytes;
using vt::dev::parseHex;
using vt::dev::toHex;

TEST(Hex, AcceptsThePlcNotations)
{
    const Bytes expected{0x23, 0x00, 0x03};
    for (const char *text : {"23 00 03", "0x23,0x00,0x03", "230003", "23-00-03", "  23:00;03 "}) {
        auto r = parseHex(text);
        ASSERT_TRUE(r.ok()) << text;
        EXPECT_EQ(*r, expected) << text;
    }
}

TEST(Hex, RejectsGarbageWithPosition)
{
    auto r = parseHex("23 0g 03");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().position, 4u);
    EXPECT_FALSE(parseHex("123").ok());
    EXPECT_FALSE(parseHex("0x").ok());
}

TEST(Hex, SingleNibbleIsOneByte)
{
    auto r = parseHex("3 F");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(*r, (Bytes{0x03, 0x0F}));
}

TEST(Hex, FormatsUppercaseWithSeparator)
{
    const Bytes b{0x0F, 0xA0, 0x00};
    EXPECT_EQ(toHex(b), "0F A0 00");
    EXPECT_EQ(toHex(b, '\0'), "0FA000");
    EXPECT_EQ(vt::dev::hexWord(0x03E8), "0x03E8");
    EXPECT_EQ(vt::dev::hexByte(0x8F), "0x8F");
}
