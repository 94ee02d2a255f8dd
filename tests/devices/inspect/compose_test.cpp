// The composer: every kind's bytes equal the manuals'
// worked examples, writes are flagged for confirmation, and each frame names its link.
#include "hcs/worked_examples.h"
#include "inspect/compose.h"
#include "inspect/logged_frame.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::inspect;
using namespace vt::test::hcs_examples;

namespace {

ComposedFrame built(const ComposeSpec &s)
{
    const auto r = compose(s);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().reason);
    return r.ok() ? *r : ComposedFrame{};
}

} // namespace

TEST(Compose, GatewayCmd3AndCmd6EqualOpatSec2_7)
{
    ComposeSpec s;
    s.kind = ComposeKind::GatewayRead;
    s.tadr = 0x24;
    s.sadr = 0;
    s.id = 0x0007;
    s.count = 1;
    ComposedFrame f = built(s);
    EXPECT_EQ(f.bytes, kOpat27ReadRequest);
    EXPECT_FALSE(f.writes);
    EXPECT_EQ(f.link, LinkProtocol::NodeImage);

    s.kind = ComposeKind::GatewayWrite;
    s.tadr = 0x23;
    s.id = 0x0030;
    s.value = 1000;
    f = built(s);
    EXPECT_EQ(f.bytes, kOpat27Write);
    EXPECT_TRUE(f.writes);
    s.value = -9999; // §2.8: -9.999 V
    s.tadr = 0x12;
    s.id = 0x0027;
    EXPECT_EQ(built(s).bytes, kOpat28Min);

    s.kind = ComposeKind::GatewayRead;
    s.count = 9; // OPAT manual §2.1: at most 8 parameters
    EXPECT_FALSE(compose(s).ok());
}

TEST(Compose, Cmd15EqualsOpatSec3_4_2AndDmaSec4_4_2)
{
    ComposeSpec s;
    s.kind = ComposeKind::GatewayCyclic;
    s.tadr = 0x23;
    s.modules = {{0, 1000, 0}, {0, 2000, 0}, {0, -3000, 0}};
    s.family = hcs::Family::Opat;
    EXPECT_EQ(built(s).bytes, kOpat342Request);
    s.family = hcs::Family::Dma;
    EXPECT_EQ(built(s).bytes, kDma442Request);
    s.modules.assign(6, {}); // DMA Profinet manual §4.1: at most 5 slaves
    EXPECT_FALSE(compose(s).ok());
}

TEST(Compose, ModbusRtuAndTcp)
{
    ComposeSpec s;
    s.kind = ComposeKind::ModbusRead;
    s.unit = 1;
    s.id = 7;
    s.count = 1;
    ComposedFrame f = built(s);
    EXPECT_EQ(f.bytes, (Bytes{0x01, 0x03, 0x00, 0x07, 0x00, 0x01, 0x35, 0xCB}));
    EXPECT_EQ(f.link, LinkProtocol::ModbusRtu);
    s.modbusTcp = true;
    s.transaction = 1;
    f = built(s);
    EXPECT_EQ(f.bytes,
              (Bytes{0x00, 0x01, 0x00, 0x00, 0x00, 0x06, 0x01, 0x03, 0x00, 0x07, 0x00, 0x01}));
    EXPECT_EQ(f.link, LinkProtocol::ModbusTcp);
    s.kind = ComposeKind::ModbusWrite;
    s.modbusTcp = false;
    s.id = 0x30;
    s.value = 1000;
    f = built(s);
    EXPECT_TRUE(f.writes);
    EXPECT_EQ(Bytes(f.bytes.begin(), f.bytes.end() - 2),
              (Bytes{0x01, 0x06, 0x00, 0x30, 0x03, 0xE8}));
}

TEST(Compose, PkwEqualsEd1Sec4_6_1)
{
    ComposeSpec s;
    s.kind = ComposeKind::PkwWrite; // example 1: IND 3, PNU 73, uint16 = 450
    s.ind = 3;
    s.pnu = 73;
    s.width = 2;
    s.value = 450;
    ComposedFrame f = built(s);
    EXPECT_EQ(f.bytes, (Bytes{0x20, 0x49, 0x03, 0x00, 0x00, 0x00, 0x01, 0xC2}));
    EXPECT_TRUE(f.writes);
    EXPECT_FALSE(f.link);          // PROFIBUS DP: no ValveTune link carries it
    s.kind = ComposeKind::PkwRead; // example 2: IND 3, PNU 98
    s.pnu = 98;
    EXPECT_EQ(built(s).bytes, (Bytes{0x10, 0x62, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00}));
}

TEST(Compose, HartParameterWriteEqualsSec4_4_1)
{
    ComposeSpec s;
    s.kind = ComposeKind::HartParamWrite; // IND 250, PNU 6, instance 0 = 450 to an SD733
    s.hartDeviceType = 0xE3F0;
    s.hartDeviceId = 0x123456;
    s.ind = 250;
    s.pnu = 6;
    s.width = 2;
    s.value = 450;
    const ComposedFrame f = built(s);
    EXPECT_EQ(f.bytes, (Bytes{0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x82, 0xA3, 0xF0, 0x12, 0x34, 0x56,
                              0x83, 0x05, 0xFA, 0x06, 0x00, 0x01, 0xC2, 0x18}));
    EXPECT_TRUE(f.writes);
    EXPECT_EQ(f.link, LinkProtocol::Hart);
    ComposeSpec zero;
    zero.kind = ComposeKind::HartCommand; // command 0 in a short frame (§2.3)
    zero.pollAddress = 0;
    zero.hartCommand = 0;
    const ComposedFrame z = built(zero);
    EXPECT_FALSE(z.writes);
    EXPECT_EQ(Bytes(z.bytes.end() - 5, z.bytes.end()), (Bytes{0x02, 0x80, 0x00, 0x00, 0x82}));
}

TEST(Compose, SdoFramesAndTheirSocketCanImage)
{
    ComposeSpec s;
    s.kind = ComposeKind::SdoDownload; // CiA 301 §7.2.4.3.3: 0x6040/0 = 0x000F, 2 bytes
    s.node = 5;
    s.index = 0x6040;
    s.subindex = 0;
    s.width = 2;
    s.value = 0x0F;
    const ComposedFrame f = built(s);
    EXPECT_EQ(f.bytes, (Bytes{0x2B, 0x40, 0x60, 0x00, 0x0F, 0x00, 0x00, 0x00}));
    ASSERT_TRUE(f.cobId.has_value());
    EXPECT_EQ(*f.cobId, 0x605u);
    EXPECT_TRUE(f.writes);
    const Bytes image = wireBytes(f);
    ASSERT_EQ(image.size(), 16u);
    EXPECT_EQ(Bytes(image.begin() + 8, image.end()), f.bytes);
    s.kind = ComposeKind::SdoUpload;
    s.index = 0x6041;
    EXPECT_EQ(built(s).bytes, (Bytes{0x40, 0x41, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}));
    s.node = 0;
    EXPECT_FALSE(compose(s).ok());
}

TEST(Compose, NodeImageWirePadsTheTelegram)
{
    ComposeSpec s;
    s.kind = ComposeKind::GatewayWrite;
    s.tadr = 0x23;
    s.sadr = 1;
    s.id = 0x30;
    s.value = 1000;
    const ComposedFrame f = built(s);
    const Bytes wire = wireBytes(f, 42);
    ASSERT_EQ(wire.size(), 42u);
    EXPECT_EQ(Bytes(wire.begin(), wire.begin() + 7), kDma37Write);
}
