// CANopen SDO against CiA 301 §7.2.4.3 (SDO protocols) and the COB-IDs of the pre-defined
// connection set, with the CiA 408 objects the Wandfluh devices use (ARCHITECTURE.md "CAN").
#include "canopen/sdo.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::canopen;

namespace {

} // namespace

TEST(CanopenSdo, Cia301CobIdRule)
{
    EXPECT_EQ(sdoRequestId(5), 0x605);
    EXPECT_EQ(sdoResponseId(5), 0x585);
    EXPECT_EQ(sdoChannel(0x605), (SdoChannel{5, Direction::Request}));
    EXPECT_EQ(sdoChannel(0x5FF), (SdoChannel{127, Direction::Response}));
    EXPECT_FALSE(sdoChannel(0x600).has_value()); // node 0 does not exist
    EXPECT_FALSE(sdoChannel(0x580).has_value());
    EXPECT_FALSE(sdoChannel(0x680).has_value());
    EXPECT_FALSE(sdoChannel(0x181).has_value());
}

// Expedited download: write CiA 408 control word 0x6040 = 0x000F (D, H, M, R) to node 5.
TEST(CanopenSdo, Cia301ExpeditedDownload)
{
    const Bytes wire{0x2B, 0x40, 0x60, 0x00, 0x0F, 0x00, 0x00, 0x00};
    const Sdo w = expeditedDownload(0x6040, 0, 0x000F, 2);
    EXPECT_EQ(*encodeSdo(w), wire);
    auto d = decodeSdo(wire, Direction::Request);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, w);
    EXPECT_EQ(expeditedValue(*d), 0x000Fu);

    const Bytes ack{0x60, 0x40, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00};
    EXPECT_EQ(*encodeSdo(downloadResponse(0x6040, 0)), ack);
    EXPECT_EQ(decodeSdo(ack, Direction::Response)->command, SdoCommand::InitiateDownloadResponse);

    // All four sizes: n = 4 − size in bits 3..2.
    EXPECT_EQ(encodeSdo(expeditedDownload(0x2000, 1, 7, 1))->front(), 0x2F);
    EXPECT_EQ(encodeSdo(expeditedDownload(0x2000, 1, 7, 3))->front(), 0x27);
    EXPECT_EQ(encodeSdo(expeditedDownload(0x2000, 1, 7, 4))->front(), 0x23);
}

// Expedited upload: read status word 0x6041 of node 5 → 0x0237.
TEST(CanopenSdo, Cia301ExpeditedUpload)
{
    const Bytes request{0x40, 0x41, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00};
    const Bytes response{0x4B, 0x41, 0x60, 0x00, 0x37, 0x02, 0x00, 0x00};
    EXPECT_EQ(*encodeSdo(uploadRequest(0x6041, 0)), request);
    EXPECT_EQ(*encodeSdo(expeditedUploadResponse(0x6041, 0, 0x0237, 2)), response);
    auto r = decodeSdo(response, Direction::Response);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->command, SdoCommand::InitiateUploadResponse);
    EXPECT_TRUE(r->expedited);
    EXPECT_EQ(r->data, (Bytes{0x37, 0x02}));
    EXPECT_EQ(expeditedValue(*r), 0x0237u);
    // e = 1, s = 0: four bytes, size unspecified.
    auto unsized = decodeSdo(Bytes{0x42, 0x41, 0x60, 0x00, 1, 2, 3, 4}, Direction::Response);
    ASSERT_TRUE(unsized.ok());
    EXPECT_EQ(unsized->data.size(), 4u);
}

TEST(CanopenSdo, Cia301SegmentedInitiateAndSegments)
{
    // Segmented upload initiate response: 0x41, size 20 in bytes 4..7.
    const Bytes init{0x41, 0x08, 0x10, 0x00, 0x14, 0x00, 0x00, 0x00};
    auto s = decodeSdo(init, Direction::Response);
    ASSERT_TRUE(s.ok());
    EXPECT_FALSE(s->expedited);
    EXPECT_TRUE(s->sizeIndicated);
    EXPECT_EQ(s->size, 20u);
    EXPECT_EQ(*encodeSdo(*s), init);
    // Upload segment request with toggle, segment with 3 bytes and c = 1.
    EXPECT_EQ(decodeSdo(Bytes{0x70, 0, 0, 0, 0, 0, 0, 0}, Direction::Request)->toggle, true);
    const Bytes seg{0x19, 'a', 'b', 'c', 0, 0, 0, 0}; // 000 1 100 1
    auto g = decodeSdo(seg, Direction::Response);
    ASSERT_TRUE(g.ok());
    EXPECT_EQ(g->command, SdoCommand::UploadSegmentResponse);
    EXPECT_TRUE(g->toggle);
    EXPECT_TRUE(g->last);
    EXPECT_EQ(g->data, (Bytes{'a', 'b', 'c'}));
    EXPECT_EQ(*encodeSdo(*g), seg);
    // Block transfer is recognised and kept as sent.
    const Bytes block{0xC6, 0x00, 0x10, 0x00, 0x7F, 0, 0, 0};
    auto b = decodeSdo(block, Direction::Response);
    ASSERT_TRUE(b.ok());
    EXPECT_EQ(b->command, SdoCommand::BlockUploadResponse);
    EXPECT_EQ(*encodeSdo(*b), block);
}

TEST(CanopenSdo, Cia301AbortWithCodeTexts)
{
    const Bytes wire{0x80, 0x41, 0x60, 0x00, 0x00, 0x00, 0x02, 0x06};
    const Sdo a = abortTransfer(0x6041, 0, 0x06020000);
    EXPECT_EQ(*encodeSdo(a), wire);
    auto d = decodeSdo(wire, Direction::Response);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->abortCode, 0x06020000u);
    EXPECT_EQ(abortCodeText(0x06020000).en, "Object does not exist in the object dictionary");
    EXPECT_EQ(abortCodeText(0x06020000).de, "Objekt existiert nicht im Objektverzeichnis");
    EXPECT_TRUE(isKnownAbortCode(0x08000022));
    EXPECT_EQ(abortCodeText(0x12345678).en, "unknown abort code 0x12345678");
    const std::uint32_t all[] = {
        0x05030000, 0x05040000, 0x05040001, 0x05040002, 0x05040003, 0x05040004, 0x05040005,
        0x06010000, 0x06010001, 0x06010002, 0x06020000, 0x06040041, 0x06040042, 0x06040043,
        0x06040047, 0x06060000, 0x06070010, 0x06070012, 0x06070013, 0x06090011, 0x06090030,
        0x06090031, 0x06090032, 0x06090036, 0x060A0023, 0x08000000, 0x08000020, 0x08000021,
        0x08000022, 0x08000023, 0x08000024};
    for (std::uint32_t code : all) {
        EXPECT_TRUE(isKnownAbortCode(code)) << std::hex << code;
        EXPECT_TRUE(abortCodeText(code).complete());
        EXPECT_NE(abortCodeText(code).en, abortCodeText(code).de);
    }
}

TEST(CanopenSdo, CanFramesOfTheSdoChannel)
{
    auto f = toCanFrame(expeditedDownload(0x6040, 0, 0x000F, 2), 5);
    ASSERT_TRUE(f.ok());
    EXPECT_EQ(f->id, 0x605u);
    EXPECT_EQ(f->dlc, 8);
    auto m = fromCanFrame(*f);
    ASSERT_TRUE(m.ok());
    EXPECT_EQ(m->channel.node, 5);
    EXPECT_EQ(expeditedValue(m->sdo), 0x000Fu);
    EXPECT_EQ(toCanFrame(abortTransfer(0x6040, 0, 0x08000000), 5, Direction::Response)->id, 0x585u);
    EXPECT_FALSE(toCanFrame(uploadRequest(0x6041, 0), 0).ok());
    EXPECT_FALSE(toCanFrame(uploadRequest(0x6041, 0), 128).ok());
    CanFrame nmt = makeCanFrame(0x000, Bytes{0x01, 0x05});
    EXPECT_EQ(fromCanFrame(nmt).error().code, DecodeErrc::UnexpectedCommand);
}

TEST(CanopenSdo, EncodeAndDecodeErrors)
{
    EXPECT_EQ(encodeSdo(expeditedDownload(0x6040, 0, Bytes{})).error().code, DecodeErrc::BadValue);
    EXPECT_EQ(encodeSdo(expeditedDownload(0x6040, 0, Bytes(5, 0))).error().code,
              DecodeErrc::BadValue);
    EXPECT_EQ(decodeSdo(Bytes{0x40, 0x41}, Direction::Request).error().code, DecodeErrc::Truncated);
    EXPECT_EQ(decodeSdo(Bytes(9, 0), Direction::Request).error().code, DecodeErrc::TooLong);
    EXPECT_EQ(decodeSdo(Bytes{0xE0, 0, 0, 0, 0, 0, 0, 0}, Direction::Request).error().code,
              DecodeErrc::UnexpectedCommand);
}

TEST(CanopenSdo, DescribeUsesTheCobId)
{
    const CanFrame f = makeCanFrame(0x585, Bytes{0x4B, 0x41, 0x60, 0x00, 0x37, 0x02, 0x00, 0x00});
    const Description d = describeSdo(f);
    ASSERT_TRUE(d.ok()) << d.summary.en;
    EXPECT_EQ(d.field("can.id")->text.de, "COB-ID: SDO-Antwort von Knoten 5 (0x580 + Knoten)");
    EXPECT_EQ(d.field("sdo.index")->value, "0x6041");
    EXPECT_EQ(d.field("sdo.data")->value, "37 02 (567)");
    EXPECT_EQ(d.field("sdo.data")->length, 2u);
    EXPECT_EQ(d.summary.en, "node 5: upload response (value read) 0x6041/0 = 567 (2 bytes)");
    EXPECT_EQ(d.summary.de, "Knoten 5: Upload-Antwort (gelesener Wert) 0x6041/0 = 567 (2 Byte)");
    for (const FieldSpan &fs : d.fields)
        EXPECT_TRUE(fs.text.complete()) << fs.key;

    const Description a =
        describeSdo(makeCanFrame(0x605, Bytes{0x80, 0x40, 0x60, 0x00, 0x22, 0x00, 0x00, 0x08}));
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(a.field("sdo.abort_code")->value, "0x08000022");
    // Without a COB-ID the direction option decides; a non-SDO id is an error.
    DescribeOptions response;
    response.direction = Direction::Response;
    EXPECT_EQ(describeSdo(Bytes{0x60, 0x40, 0x60, 0, 0, 0, 0, 0}, response).fields[0].text.en,
              "download confirmed (write done)");
    EXPECT_FALSE(describeSdo(makeCanFrame(0x181, Bytes(8, 0))).ok());
    EXPECT_FALSE(describeSdo(Bytes{0x40}).ok());
}
