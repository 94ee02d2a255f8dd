// OPAT manual (Rev R2.1) worked examples, byte-exact in both directions (§2.3–§3.4.2).
#include "hcs/cmd15.h"
#include "hcs/telegram.h"
#include "worked_examples.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hcs;
using namespace vt::test::hcs_examples;

namespace {
const DecodeOptions kOpat{Family::Opat, false};
}

TEST(HcsOpat, Sec2_3_ReadErrorModule3NotInstalled)
{
    const ExceptionResponse e{0x23, 0x03, kCmdRead, 5};
    EXPECT_EQ(encode(e), kOpat23ReadError);
    auto any = decodeResponse(kOpat23ReadError, kOpat);
    ASSERT_TRUE(any.ok());
    EXPECT_EQ(std::get<ExceptionResponse>(*any), e);
    EXPECT_EQ(e.err(), 0x83);
    // The typed CMD 3 decoder reports it as a device exception with the EXCE code.
    auto typed = decodeReadResponse(kOpat23ReadError, kOpat);
    ASSERT_FALSE(typed.ok());
    EXPECT_EQ(typed.error().code, DecodeErrc::DeviceException);
    EXPECT_EQ(typed.error().deviceCode, 5);
    EXPECT_EQ(typed.error().offset, 3u);
}

TEST(HcsOpat, Sec2_6_WriteErrorModule3NotInstalled)
{
    const ExceptionResponse e{0x23, 0x03, kCmdWrite, 5};
    EXPECT_EQ(encode(e), kOpat26WriteError);
    auto typed = decodeWriteResponse(kOpat26WriteError, kOpat);
    ASSERT_FALSE(typed.ok());
    EXPECT_EQ(typed.error().code, DecodeErrc::DeviceException);
    EXPECT_EQ(typed.error().deviceCode, 5);
}

TEST(HcsOpat, Sec2_7_WriteC107OneVolt)
{
    // "Master wants to write parameter C1.07 with value 1.000 V: ID = 0x0030, DATA = 0x3E8".
    const WriteRequest q{0x23, 0x00, 0x0030, 1000};
    EXPECT_EQ(encode(q), kOpat27Write);
    auto d = decodeWriteRequest(kOpat27Write, kOpat);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, q);
}

TEST(HcsOpat, Sec2_7_WriteResponseEchoes)
{
    // The OCR prints the last byte as "O0xE8"; it is 0xE8 as in the request.
    const WriteResponse a{0x23, 0x00, 0x0030, 1000};
    EXPECT_EQ(encode(a), kOpat27Write);
    auto d = decodeWriteResponse(kOpat27Write, kOpat);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, a);
}

TEST(HcsOpat, Sec2_7_ReadD107)
{
    const ReadRequest q{0x24, 0x00, 0x0007, 1};
    EXPECT_EQ(encode(q), kOpat27ReadRequest);
    auto d = decodeReadRequest(kOpat27ReadRequest, kOpat);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, q);
}

TEST(HcsOpat, Sec2_7_ReadResponseCntRepairedFromOcr)
{
    // The OCR prints CNT = 0x00 although the text says "CNT = 2 (2 Bytes)"; DMA §3.7 prints 0x02.
    const ReadResponse a{0x24, 0x00, {0x0133}};
    auto bytes = encode(a);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(*bytes, kOpat27ReadResponse);
    auto d = decodeReadResponse(kOpat27ReadResponse, kOpat);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, a);
    EXPECT_EQ(d->values[0], 307); // "DATA = 0x0133"
    // The damaged version is a CNT 0 response followed by two stray bytes: TooLong at 4.
    const Bytes ocr{0x24, 0x00, 0x03, 0x00, 0x01, 0x33};
    auto bad = decodeReadResponse(ocr, kOpat);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, DecodeErrc::TooLong);
    EXPECT_EQ(bad.error().offset, 4u);
}

TEST(HcsOpat, Sec2_8_SetValuesViaBus)
{
    struct Case
    {
        const Bytes &bytes;
        std::int16_t value;
    };
    // 0.000 V, 5.000 V = 0x1388, 9.999 V = 0x270F, -9.999 V = 0xD8F1.
    for (const Case &c : {Case{kOpat28Zero, 0}, Case{kOpat28Five, 5000}, Case{kOpat28Max, 9999},
                          Case{kOpat28Min, -9999}}) {
        const WriteRequest q{0x12, 0x00, 0x0027, asRaw(c.value)};
        EXPECT_EQ(encode(q), c.bytes);
        auto d = decodeWriteRequest(c.bytes, kOpat);
        ASSERT_TRUE(d.ok());
        EXPECT_EQ(asSigned(d->value), c.value);
        EXPECT_EQ(d->id, 0x0027);
    }
}

TEST(HcsOpat, Sec3_3_CyclicErrorTimeoutSlave)
{
    const ExceptionResponse e{0x23, 0x03, kCmdCyclic, 8};
    EXPECT_EQ(encode(e), kOpat33CyclicError);
    auto typed = decodeCyclicResponse(kOpat33CyclicError, kOpat);
    ASSERT_FALSE(typed.ok());
    EXPECT_EQ(typed.error().code, DecodeErrc::DeviceException);
    EXPECT_EQ(typed.error().deviceCode, 8);
    auto any = decodeResponse(kOpat33CyclicError, kOpat);
    ASSERT_TRUE(any.ok());
    EXPECT_EQ(std::get<ExceptionResponse>(*any), e);
}

TEST(HcsOpat, Sec3_4_1_MasterOnlyRequest)
{
    // SNUM 0 = only the OPAT master; the OCR's "O0xOF" is CMD 0x0F.
    const CyclicRequest q{0x23, {{0x00, 1000, 0}}};
    auto bytes = encode(q, Family::Opat);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(*bytes, kOpat341Request);
    auto d = decodeCyclicRequest(kOpat341Request, kOpat);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, q);
}

TEST(HcsOpat, Sec3_4_1_MasterResponse)
{
    const CyclicResponse a{0x23, 0x00, 0x4000, 1000, 0};
    EXPECT_EQ(encode(a), kOpat341Response);
    auto d = decodeCyclicResponse(kOpat341Response, kOpat);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, a);
}

TEST(HcsOpat, Sec3_4_2_MasterAndTwoSlavesRequest)
{
    const CyclicRequest q{0x23, {{0x00, 1000, 0}, {0x00, 2000, 0}, {0x00, -3000, 0}}};
    auto bytes = encode(q, Family::Opat);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(*bytes, kOpat342Request);
    EXPECT_EQ(bytes->size(), 18u); // "3 header + 5·module bytes", 3 modules
    auto d = decodeCyclicRequest(kOpat342Request, kOpat);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, q);
}

TEST(HcsOpat, Sec3_4_2_MultiplexedResponses)
{
    // The node answers master, slave 1, slave 2, master again as TADR changes 0x23..0x26.
    const CyclicResponse expected[] = {{0x23, 0, 0x4000, 1000, 0},
                                       {0x24, 1, 0x4000, 2000, 0},
                                       {0x25, 2, 0x4000, -3000, 0},
                                       {0x26, 0, 0x4000, 1000, 0}};
    const Bytes *frames[] = {&kOpat342ResponseMaster, &kOpat342ResponseSlave1,
                             &kOpat342ResponseSlave2, &kOpat342ResponseMasterAgain};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(encode(expected[i]), *frames[i]);
        auto d = decodeCyclicResponse(*frames[i], kOpat);
        ASSERT_TRUE(d.ok());
        EXPECT_EQ(*d, expected[i]);
    }
}
