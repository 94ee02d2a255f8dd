// LinkProtocol keys (STYLE.md rule 18): every protocol survives key() → fromKey(), keys are
// distinct, and a key no link has is refused rather than guessed.
#include "core/link_protocol.h"

#include <gtest/gtest.h>
#include <set>
#include <string>

using namespace vt::dev;

TEST(LinkProtocol, KeysRoundTrip)
{
    std::set<std::string> keys;
    for (LinkProtocol p : kLinkProtocols) {
        EXPECT_EQ(fromKey<LinkProtocol>(key(p)), p) << key(p);
        keys.insert(key(p));
    }
    EXPECT_EQ(keys.size(), kLinkProtocols.size());
}

TEST(LinkProtocol, KeysAreTheSavedOnes)
{
    // Settings, telegram log files and command lines hold these texts.
    EXPECT_STREQ(key(LinkProtocol::ModbusRtu), "modbus-rtu");
    EXPECT_STREQ(key(LinkProtocol::ModbusTcp), "modbus-tcp");
    EXPECT_STREQ(key(LinkProtocol::NodeImage), "node-image");
    EXPECT_STREQ(key(LinkProtocol::Hart), "hart");
    EXPECT_STREQ(key(LinkProtocol::Canopen), "canopen");
}

TEST(LinkProtocol, UnknownKeyIsRefused)
{
    EXPECT_FALSE(fromKey<LinkProtocol>(""));
    EXPECT_FALSE(fromKey<LinkProtocol>("modbus"));
    EXPECT_FALSE(fromKey<LinkProtocol>("Modbus-RTU"));
    EXPECT_FALSE(fromKey<LinkProtocol>("gateway")); // a frame format, not a link
    EXPECT_FALSE(fromKey<LinkProtocol>("modbus-rtu "));
}
