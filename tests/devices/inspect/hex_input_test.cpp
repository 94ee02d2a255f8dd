// The decode box's paste parser: the
// notations PLC programmers paste, candump frames, and bounds against untrusted input.
#include "inspect/hex_input.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::inspect;

TEST(HexInput, AcceptsSpacesPrefixesCommasAndNewlines)
{
    const Bytes expected{0x23, 0x00, 0x06, 0x00, 0x30, 0x03, 0xE8}; // OPAT manual §2.7
    for (const char *text : {"23 00 06 00 30 03 E8", "0x23,0x00,0x06,0x00,0x30,0x03,0xE8",
                             "2300060030 03e8", "  23 00 06\n00 30\r\n03 E8\n",
                             "23-00-06-00-30-03-E8", "0x23, 0x00, 0x06, 0x0030, 0x03E8"}) {
        const auto r = parseHexInput(text);
        ASSERT_TRUE(r.ok()) << text;
        EXPECT_EQ(r->bytes, expected) << text;
        EXPECT_FALSE(r->cobId.has_value());
    }
}

TEST(HexInput, CandumpGivesCobIdAndData)
{
    const auto r = parseHexInput(" 605#4041600000000000\n");
    ASSERT_TRUE(r.ok());
    ASSERT_TRUE(r->cobId.has_value());
    EXPECT_EQ(*r->cobId, 0x605u);
    EXPECT_EQ(r->bytes, (Bytes{0x40, 0x41, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}));
    EXPECT_FALSE(parseHexInput("605#40416").ok()); // odd digit count
}

TEST(HexInput, ReportsWhereTheTextIsNotHex)
{
    const auto r = parseHexInput("  23 0G");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().position, 6u); // the G
    EXPECT_FALSE(parseHexInput("0x").ok());
}

TEST(HexInput, BoundsLengthBeforeParsing)
{
    const std::string tooLong(kMaxInputChars + 1, ' ');
    EXPECT_FALSE(parseHexInput(tooLong).ok());
    std::string many;
    for (std::size_t i = 0; i <= kMaxFrameBytes; ++i)
        many += "00";
    ASSERT_LE(many.size(), kMaxInputChars);
    EXPECT_FALSE(parseHexInput(many).ok());
    EXPECT_TRUE(parseHexInput(many.substr(2)).ok());
    EXPECT_TRUE(parseHexInput("").ok()); // nothing pasted: no bytes, no error
}
