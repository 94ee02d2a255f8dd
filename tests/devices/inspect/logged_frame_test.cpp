// describeLogged: CANopen records are SocketCAN images and node-image
// records are padded gateway telegrams; both are explained with offsets into the logged bytes.
#include "canopen/can_frame.h"
#include "hcs/worked_examples.h"
#include "inspect/logged_frame.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::inspect;

TEST(LoggedFrame, CanopenImageIsUnwrappedWithImageOffsets)
{
    // CiA 301 §7.2.4.3.6: upload response from node 5, 0x6041/0 = 0x0237.
    const auto frame =
        canopen::makeCanFrame(0x585, Bytes{0x4B, 0x41, 0x60, 0x00, 0x37, 0x02, 0x00, 0x00});
    const auto image = canopen::toSocketCan(frame);
    const auto d = describeLogged(LinkProtocol::Canopen, image, {});
    ASSERT_TRUE(d.ok());
    ASSERT_TRUE(d->ok()) << d->summary.en;
    const FieldSpan *id = d->field("can.id");
    ASSERT_NE(id, nullptr);
    EXPECT_EQ(id->offset, 0u);
    EXPECT_EQ(id->length, 4u);
    EXPECT_EQ(id->value, "0x0585");
    const FieldSpan *index = d->field("sdo.index");
    ASSERT_NE(index, nullptr);
    EXPECT_EQ(index->offset, 9u); // data byte 1 sits at image byte 9
    EXPECT_EQ(index->value, "0x6041");
    for (const FieldSpan &f : d->fields)
        EXPECT_LE(f.offset + f.length, image.size()) << f.key;
}

TEST(LoggedFrame, BrokenCanopenImageShowsItsError)
{
    std::array<std::uint8_t, 16> image{};
    image[4] = 12; // CAN FD length
    const auto d = describeLogged(LinkProtocol::Canopen, image, {});
    ASSERT_TRUE(d.ok());
    EXPECT_FALSE(d->ok());
}

TEST(LoggedFrame, NodeImageIsAPaddedGatewayTelegram)
{
    using namespace vt::test::hcs_examples;
    Bytes image = kDma37Write; // DMA Profinet manual §3.7 in the 42-byte module of §4.5.4
    image.resize(42, 0);
    AnyOptions o;
    o.direction = Direction::Request;
    const auto d = describeLogged(LinkProtocol::NodeImage, image, o);
    ASSERT_TRUE(d.ok());
    EXPECT_TRUE(d->ok());
    ASSERT_NE(d->field("ID"), nullptr);
    EXPECT_EQ(d->field("ID")->offset, 3u);
    // The same bytes as a bare gateway telegram are too long.
    o.protocol = FrameFormat::Gateway;
    const auto bare = describeAny(image, o);
    ASSERT_TRUE(bare.ok());
    EXPECT_FALSE(bare->ok());
    EXPECT_FALSE(fromKey<LinkProtocol>("no-such-link"));
}
