// OPAT manual §5.6: PROFIdrive telegram 1 and CMD 15 in one process image, byte-exact both ways.
#include "hcs/status_bits.h"
#include "profidrive/describe.h"
#include "profidrive/mixed.h"
#include "profidrive/stw1_zsw1.h"
#include "worked_examples.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::profidrive;
using namespace vt::test::profidrive_examples;

namespace {

bool contains(const std::string &text, const std::string &part)
{
    return text.find(part) != std::string::npos;
}

DescribeOptions opts(Direction direction)
{
    DescribeOptions o;
    o.direction = direction;
    return o;
}

} // namespace

TEST(ProfidriveMixed, Sec5_6_SendTelegram)
{
    const MixedRequest q{{0x047F, 0x0700}, {0x12, {{0x00, 0x1800, 0}, {0x00, 0x1800, 0}}}};
    auto bytes = encode(q);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(*bytes, kSec56Request);
    auto back = decodeMixedRequest(kSec56Request);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back, q);
}

TEST(ProfidriveMixed, Sec5_6_ResponsesFromMasterAndSlave)
{
    const MixedResponse master{{0x4237, static_cast<std::int16_t>(0xF39A)},
                               hcs::CyclicResponse{0x12, 0, 0x0400, -998, 3750}};
    EXPECT_EQ(encode(master), kSec56ResponseMaster);
    EXPECT_EQ(decodeMixedResponse(kSec56ResponseMaster).value(), master);
    const MixedResponse slave{{0x4237, static_cast<std::int16_t>(0xF99A)},
                              hcs::CyclicResponse{0x13, 1, 0x0404, 557, 0x1800}};
    EXPECT_EQ(encode(slave), kSec56ResponseSlave);
    EXPECT_EQ(decodeMixedResponse(kSec56ResponseSlave).value(), slave);
    // The slave's VALUE2 (d1.10, internal set value) is the 0x1800 the PLC sent it.
    EXPECT_EQ(std::get<hcs::CyclicResponse>(slave.node).value2, 0x1800);
}

TEST(ProfidriveMixed, Sec5_6_CableFractureAtFeedback1)
{
    auto r = decodeMixedResponse(kSec56ResponseCableFracture);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->drive.zsw1, 0x403F);
    EXPECT_TRUE(r->drive.zsw1 & zsw1::kFault);
    EXPECT_EQ(r->drive.nistA, 2); // "Error number 2 = cable fracture at FB1"
    const auto &c = std::get<hcs::CyclicResponse>(r->node);
    const hcs::ModuleStatus s = hcs::decodeStatus(c.status);
    EXPECT_TRUE(s.error);
    EXPECT_TRUE(s.hwEnable);
    EXPECT_EQ(s.errorNumber, 2);
}

TEST(ProfidriveMixed, ErrorsPointIntoTheWholeImage)
{
    const Bytes cut(kSec56Request.begin(), kSec56Request.begin() + 10);
    auto r = decodeMixedRequest(cut);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, DecodeErrc::Truncated);
    EXPECT_EQ(r.error().offset, 10u);
    const Bytes wrongCmd{0x04, 0x7F, 0x07, 0x00, 0x12, 0x01, 0x03, 0x00, 0x07, 0x00, 0x01};
    auto w = decodeMixedRequest(wrongCmd);
    ASSERT_FALSE(w.ok());
    EXPECT_EQ(w.error().code, DecodeErrc::UnexpectedCommand);
    EXPECT_EQ(w.error().offset, 6u);
    const Bytes error{0x42, 0x37, 0x00, 0x00, 0x12, 0x01, 0x8F, 0x07};
    auto e = decodeMixedResponse(error);
    ASSERT_TRUE(e.ok());
    EXPECT_EQ(std::get<hcs::ExceptionResponse>(e->node).code, 7);
    const Bytes cmd3{0x42, 0x37, 0x00, 0x00, 0x12, 0x01, 0x03, 0x02, 0x01, 0x33};
    EXPECT_EQ(decodeMixedResponse(cmd3).error().code, DecodeErrc::UnexpectedCommand);
    EXPECT_EQ(decodeMixedResponse(cmd3).error().offset, 6u);
    EXPECT_FALSE(encode(MixedRequest{{}, {1, {}}}).ok());
}

TEST(ProfidriveDescribe, Sec5_6_SendTelegramFields)
{
    const Description d = describe(kSec56Request, opts(Direction::Request));
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d.protocol, "profidrive");
    EXPECT_EQ(d.field("STW1")->value, "0x047F");
    EXPECT_TRUE(contains(d.field("STW1.ON/OFF1")->text.en, "enable OPAT"));
    EXPECT_EQ(d.field("STW1.ON/OFF1")->offset, 1u); // bit 0 lives in the second (low) byte
    EXPECT_EQ(d.field("STW1.CONTROL_BY_PLC")->offset, 0u);
    EXPECT_EQ(d.field("STW1.FAULT_ACK"), nullptr); // 0 and no meaning of its own when clear
    EXPECT_EQ(d.field("note"), nullptr);
    const FieldSpan *n = d.field("NSOLL_A");
    ASSERT_NE(n, nullptr);
    EXPECT_EQ(n->value, "1792");
    EXPECT_TRUE(contains(n->text.en, "0x0700 = 10.94 % = 1.094 V"));
    EXPECT_TRUE(contains(n->text.de, "10,94 % = 1,094 V"));
    // The CMD 15 part keeps its keys, offsets in the whole image, one level deeper.
    const FieldSpan *tadr = d.field("TADR");
    ASSERT_NE(tadr, nullptr);
    EXPECT_EQ(tadr->offset, 4u);
    EXPECT_EQ(tadr->depth, 1);
    EXPECT_EQ(d.field("SNUM")->value, "1");
    const FieldSpan *slave = d.field("DAT1.2");
    ASSERT_NE(slave, nullptr);
    EXPECT_EQ(slave->offset, 13u);
    EXPECT_TRUE(contains(slave->text.en, "6.144 V"));
}

TEST(ProfidriveDescribe, Sec5_6_CableFractureNamesTheErrorTwice)
{
    const Description d = describe(kSec56ResponseCableFracture, opts(Direction::Response));
    ASSERT_TRUE(d.ok());
    EXPECT_TRUE(contains(d.field("ZSW1.FAULT")->text.en, "fault present"));
    const FieldSpan *nist = d.field("NIST_A");
    EXPECT_TRUE(contains(nist->text.en, "error number 2"));
    EXPECT_TRUE(contains(nist->text.en, "wire break sensor 1"));
    EXPECT_TRUE(contains(nist->text.de, "Drahtbruch Sensor 1"));
    const FieldSpan *e = d.field("DAT.1L.error");
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->offset, 8u);
    EXPECT_TRUE(contains(e->text.en, "wire break sensor 1"));
}

TEST(ProfidriveDescribe, Telegram1AloneAndLayouts)
{
    const Bytes t1{0x04, 0x7E, 0x07, 0x00}; // bit 0 clear: OFF1
    DescribeOptions o = opts(Direction::Request);
    Description d = describe(t1, o);
    ASSERT_TRUE(d.ok());
    EXPECT_TRUE(contains(d.field("STW1.ON/OFF1")->text.en, "OFF1"));
    EXPECT_EQ(d.field("STW1.ON/OFF1")->value, "0");
    ASSERT_NE(d.field("note"), nullptr); // not 0x047F: the OPAT ignores the set value
    o.layout = Layout::MixedCmd15;
    d = describe(t1, o);
    EXPECT_FALSE(d.ok());
    EXPECT_EQ(d.error->offset, 4u);
    o.layout = Layout::Telegram1;
    d = describe(kSec56Request, o);
    EXPECT_FALSE(d.ok());
    EXPECT_EQ(d.error->code, DecodeErrc::TooLong);
    EXPECT_NE(d.field("extra"), nullptr);
}

TEST(ProfidriveDescribe, EveryExampleCompleteInBothLanguages)
{
    for (const Bytes *b : {&kSec56Request, &kSec56ResponseMaster, &kSec56ResponseSlave,
                           &kSec56ResponseCableFracture}) {
        const Direction dir = b == &kSec56Request ? Direction::Request : Direction::Response;
        const Description d = describe(*b, opts(dir));
        EXPECT_TRUE(d.ok());
        EXPECT_TRUE(d.summary.complete());
        for (const FieldSpan &f : d.fields) {
            EXPECT_TRUE(f.text.complete()) << f.key;
            EXPECT_LE(f.offset + f.length, b->size()) << f.key;
        }
    }
}
