// DSP-408 PZD and telegram types against the ED1/SD1 PROFIBUS-DP manual §4.5 and §4.8.2/§4.8.3.
#include "dsp408/pzd.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::dsp408;

namespace {

Options options(Direction direction, WordOrder order = WordOrder::HighWordFirst)
{
    Options o;
    o.direction = direction;
    o.pzdWordOrder = order;
    return o;
}

} // namespace

// §4.5.1 telegram type 2: control word + dpc_SetpointVal (2 words, high word first as the
// §4.6.1 examples order bytes, not §1.4's "little endian").
TEST(Dsp408Pzd, Section451TelegramType2)
{
    const RequestTelegram t{std::nullopt, {0x0007, 100000}};
    const Bytes wire{0x00, 0x07, 0x00, 0x01, 0x86, 0xA0};
    auto e = encodeTelegram(t);
    ASSERT_TRUE(e.ok());
    EXPECT_EQ(*e, wire);
    auto d = decodeRequestTelegram(wire);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, t);
    EXPECT_FALSE(d->pkw.has_value());
}

// §4.5.1 telegram type 1: PKW (§4.6.1 example 2 response) + status word + dpc_ActualVal.
TEST(Dsp408Pzd, Section451TelegramType1Response)
{
    const ResponseTelegram t{valueResponse(3, 98, ParamLength::Byte, 100), {0x000F, -2}};
    const Bytes wire{0xB0, 0x62, 0x03, 0x00, 0x00, 0x00, 0x00,
                     0x64, 0x00, 0x0F, 0xFF, 0xFF, 0xFF, 0xFE};
    const Options response = options(Direction::Response);
    EXPECT_EQ(*encodeTelegram(t, response), wire);
    auto d = decodeResponseTelegram(wire, response);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, t);

    const Description desc = describeTelegram(wire, response);
    ASSERT_TRUE(desc.ok()) << desc.summary.en;
    EXPECT_EQ(desc.field("telegram.type")->value, "1");
    EXPECT_EQ(desc.field("pkw.value")->value, "100");
    const FieldSpan *actual = desc.field("pzd.actual_value");
    ASSERT_NE(actual, nullptr);
    EXPECT_EQ(actual->offset, 10u);
    EXPECT_EQ(actual->value, "-2");
    const FieldSpan *ready = desc.field("pzd.status.bit3");
    ASSERT_NE(ready, nullptr);
    EXPECT_EQ(ready->value, "1");
    EXPECT_EQ(ready->offset, 9u); // low byte of the big-endian status word
    EXPECT_EQ(ready->text.de, "Bereit (R)");
    for (const FieldSpan &f : desc.fields)
        EXPECT_TRUE(f.text.complete()) << f.key;
}

TEST(Dsp408Pzd, WordOrderOption)
{
    const Options lowFirst = options(Direction::Request, WordOrder::LowWordFirst);
    const PzdSetpoint p{control::kDisable | control::kHoldEnable, 0x00012345};
    const Bytes wire{0x00, 0x03, 0x23, 0x45, 0x00, 0x01};
    EXPECT_EQ(encodePzd(p, lowFirst), wire);
    auto d = decodePzdSetpoint(wire, lowFirst);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, p);
    EXPECT_EQ(decodePzdSetpoint(wire)->setpoint, 0x23450001);
}

TEST(Dsp408Pzd, Section482ControlWordBitsDescribed)
{
    const Bytes wire{0x40, 0x0F, 0x00, 0x00, 0x00, 0x00};
    const Description d = describeTelegram(wire);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d.field("pzd.control_word")->value, "0x400F");
    EXPECT_EQ(d.field("pzd.control.bit14")->offset, 0u);
    EXPECT_EQ(d.field("pzd.control.bit3")->text.de, "Fehler quittieren (R)");
    EXPECT_EQ(d.field("pzd.control.bit5"), nullptr); // reserved and clear: not shown
    EXPECT_EQ(d.summary.en, "control word 0x400F, set value 0");
}

TEST(Dsp408Pzd, LengthsAndTypes)
{
    EXPECT_EQ(decodePzdActual(Bytes{0, 1, 2}).error().code, DecodeErrc::Truncated);
    EXPECT_EQ(decodePzdActual(Bytes(7, 0)).error().code, DecodeErrc::TooLong);
    EXPECT_EQ(decodeRequestTelegram(Bytes(9, 0)).error().code, DecodeErrc::BadLength);
    Options type1;
    type1.telegramType = TelegramType::PkwAndPzd;
    EXPECT_EQ(decodeRequestTelegram(Bytes(6, 0), type1).error().code, DecodeErrc::Truncated);
    EXPECT_EQ(decodeRequestTelegram(Bytes(12, 0), type1).error().code, DecodeErrc::Truncated);
    EXPECT_EQ(decodeRequestTelegram(Bytes(12, 0), type1).error().offset, 12u);
    EXPECT_FALSE(describeTelegram(Bytes(5, 0)).ok());
    EXPECT_FALSE(describeTelegram(Bytes{}).ok());
    // A reserved AK in a type-1 telegram is reported with the PKW layout.
    Bytes bad(14, 0);
    bad[0] = 0x40;
    const Description d = describeTelegram(bad);
    EXPECT_FALSE(d.ok());
    EXPECT_NE(d.field("pkw.ak"), nullptr);
}
