// CAN frames: the Linux SocketCAN struct can_frame layout (16 bytes, can_id in host byte order)
// and the candump text notation.
#include "canopen/can_frame.h"
#include "core/byte_writer.h"

#include <bit>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::canopen;

TEST(CanopenCanFrame, SocketCanLayout)
{
    const CanFrame f = makeCanFrame(0x605, Bytes{0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0});
    const auto wire = toSocketCan(f);
    if constexpr (std::endian::native == std::endian::little) {
        EXPECT_EQ(Bytes(wire.begin(), wire.begin() + 4), (Bytes{0x05, 0x06, 0x00, 0x00}));
    }
    EXPECT_EQ(wire[4], 8);
    EXPECT_EQ(wire[8], 0x40);
    auto back = fromSocketCan(wire);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back, f);
}

TEST(CanopenCanFrame, SocketCanFlagsAndErrors)
{
    CanFrame ext = makeCanFrame(0x18FF0001, Bytes{1, 2});
    EXPECT_TRUE(ext.extended);
    ext.rtr = true;
    auto back = fromSocketCan(toSocketCan(ext));
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back, ext);
    auto wire = toSocketCan(makeCanFrame(0x123, Bytes{}));
    wire[4] = 9;
    EXPECT_EQ(fromSocketCan(wire).error().code, DecodeErrc::BadLength);
    EXPECT_EQ(fromSocketCan(Bytes(15, 0)).error().code, DecodeErrc::Truncated);
    EXPECT_EQ(fromSocketCan(Bytes(17, 0)).error().code, DecodeErrc::TooLong);
}

TEST(CanopenCanFrame, CandumpText)
{
    auto f = parseCandump("605#2B4060000F000000");
    ASSERT_TRUE(f.ok());
    EXPECT_EQ(f->id, 0x605u);
    EXPECT_EQ(f->dlc, 8);
    EXPECT_EQ(f->data[4], 0x0F);
    EXPECT_EQ(formatCandump(*f), "605#2B4060000F000000");
    auto e = parseCandump(" 18FF0001#0102 ");
    ASSERT_TRUE(e.ok());
    EXPECT_TRUE(e->extended);
    EXPECT_EQ(formatCandump(*e), "18FF0001#0102");
    auto r = parseCandump("123#R");
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r->rtr);
    EXPECT_FALSE(parseCandump("605").ok());
    EXPECT_FALSE(parseCandump("805#00").ok());
    EXPECT_FALSE(parseCandump("605#0").ok());
    EXPECT_FALSE(parseCandump("605#000102030405060708").ok());
    EXPECT_FALSE(parseCandump("6G5#00").ok());
}
