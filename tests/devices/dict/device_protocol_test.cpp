// DeviceProtocol keys: the dictionaries' "protocol" field round-trips; an unknown one is refused.
#include "dict/device_protocol.h"

#include <gtest/gtest.h>

using namespace vt::dev;

TEST(DeviceProtocol, KeysRoundTrip)
{
    for (DeviceProtocol p : kDeviceProtocols)
        EXPECT_EQ(fromKey<DeviceProtocol>(key(p)), p) << key(p);
    EXPECT_STREQ(key(DeviceProtocol::Hcs), "hcs");
    EXPECT_STREQ(key(DeviceProtocol::Dsp408), "dsp408");
    EXPECT_STREQ(key(DeviceProtocol::Hart), "hart");
}

TEST(DeviceProtocol, UnknownKeyIsRefused)
{
    EXPECT_FALSE(fromKey<DeviceProtocol>(""));
    EXPECT_FALSE(fromKey<DeviceProtocol>("modbus-rtu")); // a link, not a device protocol
    EXPECT_FALSE(fromKey<DeviceProtocol>("HCS"));
}
