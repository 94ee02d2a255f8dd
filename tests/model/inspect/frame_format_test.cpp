// FrameFormat keys (the inspector's and `valvetune-cli decode --protocol` vocabulary) and the
// format each link protocol carries.
#include "inspect/describe_any.h"

#include <gtest/gtest.h>
#include <set>
#include <string>

using namespace vt::dev;

TEST(FrameFormat, KeysRoundTrip)
{
    std::set<std::string> keys;
    for (FrameFormat f : kFrameFormats) {
        EXPECT_EQ(fromKey<FrameFormat>(key(f)), f) << key(f);
        keys.insert(key(f));
    }
    EXPECT_EQ(keys.size(), kFrameFormats.size());
    EXPECT_STREQ(key(FrameFormat::Gateway), "gateway");
    EXPECT_STREQ(key(FrameFormat::Pkw), "pkw");
}

TEST(FrameFormat, UnknownKeyIsRefused)
{
    EXPECT_FALSE(fromKey<FrameFormat>(""));
    EXPECT_FALSE(fromKey<FrameFormat>("node-image")); // a link; it carries gateway telegrams
    EXPECT_FALSE(fromKey<FrameFormat>("PKW"));
}

TEST(FrameFormat, OfEachLink)
{
    // DMA Profinet manual §4.5.4: the node image is the gateway telegram plus padding.
    EXPECT_EQ(frameFormatOf(LinkProtocol::NodeImage), FrameFormat::Gateway);
    EXPECT_EQ(frameFormatOf(LinkProtocol::ModbusRtu), FrameFormat::ModbusRtu);
    EXPECT_EQ(frameFormatOf(LinkProtocol::ModbusTcp), FrameFormat::ModbusTcp);
    EXPECT_EQ(frameFormatOf(LinkProtocol::Hart), FrameFormat::Hart);
    EXPECT_EQ(frameFormatOf(LinkProtocol::Canopen), FrameFormat::Canopen);
}
