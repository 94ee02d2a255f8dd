// DSP-408 PKW against the ED1/SD1 PROFIBUS-DP manual §4.6 and the worked examples of §4.6.1.
#include "dsp408/pkw.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::dsp408;

namespace {

Options options(Direction direction, IndPosition ind = IndPosition::Byte2)
{
    Options o;
    o.direction = direction;
    o.indPosition = ind;
    return o;
}

const Options kRequest = options(Direction::Request);
const Options kResponse = options(Direction::Response);

} // namespace

// §4.6.1 example 1: write dop_drivePos_AsideVal (IND 3, PNU 73, uint16) = 450.
TEST(Dsp408Pkw, Section461Example1WriteWordRequest)
{
    const Bytes wire{0x20, 0x49, 0x03, 0x00, 0x00, 0x00, 0x01, 0xC2};
    const Pkw request = writeRequest(3, 73, paramLength(DataType::UInt16), 450);
    EXPECT_EQ(request.ak, static_cast<std::uint8_t>(RequestId::WriteWord));
    auto encoded = encodePkw(request);
    ASSERT_TRUE(encoded.ok());
    EXPECT_EQ(*encoded, wire);
    auto decoded = decodePkw(wire, kRequest);
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(*decoded, request);
    EXPECT_EQ(requestLength(decoded->ak), ParamLength::Word);
    EXPECT_EQ(pweValue(decoded->pwe, ParamLength::Word), 450u);
}

TEST(Dsp408Pkw, Section461Example1PositiveResponse)
{
    const Bytes wire{0x10, 0x49, 0x03, 0x00, 0x00, 0x00, 0x01, 0xC2};
    const Pkw response = valueResponse(3, 73, ParamLength::Word, 450);
    auto encoded = encodePkw(response, kResponse);
    ASSERT_TRUE(encoded.ok());
    EXPECT_EQ(*encoded, wire);
    auto decoded = decodePkw(wire, kResponse);
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(decoded->ak, static_cast<std::uint8_t>(ResponseId::Word));
    EXPECT_TRUE(answers(*decoded, writeRequest(3, 73, ParamLength::Word, 450)));
    EXPECT_FALSE(errorCode(*decoded).has_value());
}

// §4.6.1 example 2: read dop_dither_AmplVal (IND 3, PNU 98, uint8) → AK Bh, value 100 in byte 7.
TEST(Dsp408Pkw, Section461Example2ReadByte)
{
    const Bytes request{0x10, 0x62, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00};
    const Bytes response{0xB0, 0x62, 0x03, 0x00, 0x00, 0x00, 0x00, 0x64};
    EXPECT_EQ(*encodePkw(readRequest(3, 98)), request);
    EXPECT_EQ(*encodePkw(valueResponse(3, 98, paramLength(DataType::UInt8), 100), kResponse),
              response);

    auto r = decodePkw(response, kResponse);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->ak, 11);
    EXPECT_EQ(responseLength(r->ak), ParamLength::Byte);
    EXPECT_EQ(pweValue(r->pwe, ParamLength::Byte), 100u);
    EXPECT_TRUE(answers(*r, readRequest(3, 98)));
    EXPECT_FALSE(answers(*r, readRequest(3, 97)));

    const Description d = describePkw(response, kResponse);
    ASSERT_TRUE(d.ok());
    const FieldSpan *value = d.field("pkw.value");
    ASSERT_NE(value, nullptr);
    EXPECT_EQ(value->offset, 7u);
    EXPECT_EQ(value->length, 1u);
    EXPECT_EQ(value->value, "100");
    EXPECT_EQ(d.summary.en, "parameter value (byte) IND 3 PNU 98 = 100");
    EXPECT_EQ(d.summary.de, "Parameterwert (Byte) IND 3 PNU 98 = 100");
}

// §4.6: AK 7 carries the error code in PWE bytes 6..7.
TEST(Dsp408Pkw, Section46ErrorResponse)
{
    const Pkw e = errorResponse(3, 73, static_cast<std::uint16_t>(PkwError::NotChangeable));
    const Bytes wire{0x70, 0x49, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01};
    EXPECT_EQ(*encodePkw(e, kResponse), wire);
    auto r = decodePkw(wire, kResponse);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(errorCode(*r), 1);
    EXPECT_TRUE(answers(*r, writeRequest(3, 73, ParamLength::Word, 5)));
    const Description d = describePkw(wire, kResponse);
    ASSERT_TRUE(d.ok());
    const FieldSpan *err = d.field("pkw.error");
    ASSERT_NE(err, nullptr);
    EXPECT_EQ(err->offset, 6u);
    EXPECT_EQ(err->text.de, "Parameterwert nicht änderbar");
}

TEST(Dsp408Pkw, Section46DoubleWordAndPnuBits)
{
    // db_StoreParameter (IND 0, PNU 51, int32) = 's' 'a' 'v' 'e' (§4.8.8).
    const Pkw w = writeRequest(0, 51, ParamLength::DoubleWord, 0x73617665);
    EXPECT_EQ(*encodePkw(w), (Bytes{0x30, 0x33, 0x00, 0x00, 0x73, 0x61, 0x76, 0x65}));
    // PNU uses 11 bits; bit 11 is reserved and kept.
    const Bytes wide{0x1F, 0xFF, 0x00, 0x00, 0, 0, 0, 0};
    auto r = decodePkw(wide);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->pnu, 0x7FF);
    EXPECT_TRUE(r->pkeSpare);
    EXPECT_EQ(*encodePkw(*r), wide);
    EXPECT_EQ(encodePkw(readRequest(0, 0x800)).error().code, DecodeErrc::BadValue);
}

TEST(Dsp408Pkw, IndPositionOption)
{
    const Options swapped = options(Direction::Request, IndPosition::Byte3);
    const Bytes wire{0x20, 0x49, 0x00, 0x03, 0x00, 0x00, 0x01, 0xC2};
    EXPECT_EQ(*encodePkw(writeRequest(3, 73, ParamLength::Word, 450), swapped), wire);
    auto r = decodePkw(wire, swapped);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->ind, 3);
    const Description d = describePkw(wire, swapped);
    EXPECT_EQ(d.field("pkw.ind")->offset, 3u);
}

TEST(Dsp408Pkw, RejectsWrongLengthAndReservedIds)
{
    const Bytes shortPkw{0x10, 0x62, 0x03};
    EXPECT_EQ(decodePkw(shortPkw).error().code, DecodeErrc::Truncated);
    EXPECT_EQ(decodePkw(shortPkw).error().offset, 3u);
    const Bytes longPkw{0x10, 0x62, 0x03, 0, 0, 0, 0, 0, 0};
    EXPECT_EQ(decodePkw(longPkw).error().code, DecodeErrc::TooLong);
    const Bytes reserved{0x50, 0x62, 0x03, 0, 0, 0, 0, 0}; // AK 5: reserved request id
    EXPECT_EQ(decodePkw(reserved).error().code, DecodeErrc::UnexpectedCommand);
    const Description d = describePkw(reserved);
    EXPECT_FALSE(d.ok());
    EXPECT_NE(d.field("pkw.pnu"), nullptr); // the layout is still shown
    // AK 10 is a request id only, AK 7 a response id only.
    const Bytes ak10{0xA0, 0x62, 0x03, 0, 0, 0, 0, 0};
    EXPECT_TRUE(decodePkw(ak10, kRequest).ok());
    EXPECT_FALSE(decodePkw(ak10, kResponse).ok());
    EXPECT_FALSE(describePkw(Bytes{}).ok());
}

TEST(Dsp408Pkw, TextsInBothLanguages)
{
    for (std::uint8_t ak = 0; ak < 16; ++ak) {
        EXPECT_TRUE(requestIdText(ak).complete());
        EXPECT_TRUE(responseIdText(ak).complete());
    }
    for (int c : {0, 1, 2, 5, 18, 99}) {
        const auto code = static_cast<std::uint16_t>(c);
        EXPECT_TRUE(pkwErrorText(code).complete());
        EXPECT_NE(pkwErrorText(code).en, pkwErrorText(code).de);
    }
    const Description d = describePkw(Bytes{0x20, 0x49, 0x03, 0x00, 0x00, 0x00, 0x01, 0xC2});
    for (const FieldSpan &f : d.fields)
        EXPECT_TRUE(f.text.complete()) << f.key;
}
