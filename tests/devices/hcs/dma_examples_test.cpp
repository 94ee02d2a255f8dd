// DMA Profinet manual (Rev R1.2) §3.3–§4.4.2 and DMA Profibus Anleitung (Rev R3.1) §3.3–§4.4.2
// worked examples: the two manuals print identical bytes, so each test covers both sections.
#include "hcs/cmd15.h"
#include "hcs/telegram.h"
#include "worked_examples.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hcs;
using namespace vt::test::hcs_examples;

namespace {
const DecodeOptions kDma{Family::Dma, false};
}

TEST(HcsDma, ProfinetSec3_3_ProfibusSec3_3_ReadError)
{
    const ExceptionResponse e{0x23, 0x03, kCmdRead, 5};
    EXPECT_EQ(encode(e), kDma33ReadError);
    auto any = decodeResponse(kDma33ReadError, kDma);
    ASSERT_TRUE(any.ok());
    EXPECT_EQ(std::get<ExceptionResponse>(*any), e);
}

TEST(HcsDma, ProfinetSec3_6_ProfibusSec3_6_WriteError)
{
    const ExceptionResponse e{0x23, 0x03, kCmdWrite, 5};
    EXPECT_EQ(encode(e), kDma36WriteError);
    auto any = decodeResponse(kDma36WriteError, kDma);
    ASSERT_TRUE(any.ok());
    EXPECT_EQ(std::get<ExceptionResponse>(*any), e);
}

TEST(HcsDma, ProfinetSec3_7_ProfibusSec3_7_WriteC107)
{
    const WriteRequest q{0x23, 0x01, 0x0030, 1000};
    EXPECT_EQ(encode(q), kDma37Write);
    auto dq = decodeWriteRequest(kDma37Write, kDma);
    ASSERT_TRUE(dq.ok());
    EXPECT_EQ(*dq, q);
    const WriteResponse a{0x23, 0x01, 0x0030, 1000};
    EXPECT_EQ(encode(a), kDma37Write);
    auto da = decodeWriteResponse(kDma37Write, kDma);
    ASSERT_TRUE(da.ok());
    EXPECT_EQ(*da, a);
}

TEST(HcsDma, ProfinetSec3_7_ProfibusSec3_7_ReadD107)
{
    const ReadRequest q{0x24, 0x01, 0x0007, 1};
    EXPECT_EQ(encode(q), kDma37ReadRequest);
    auto dq = decodeReadRequest(kDma37ReadRequest, kDma);
    ASSERT_TRUE(dq.ok());
    EXPECT_EQ(*dq, q);
    const ReadResponse a{0x24, 0x01, {0x0133}};
    auto bytes = encode(a);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(*bytes, kDma37ReadResponse);
    auto da = decodeReadResponse(kDma37ReadResponse, kDma);
    ASSERT_TRUE(da.ok());
    EXPECT_EQ(*da, a);
}

TEST(HcsDma, ProfinetSec3_8_ProfibusSec3_8_SetValues)
{
    struct Case
    {
        const Bytes &bytes;
        std::int16_t value;
    };
    for (const Case &c : {Case{kDma38Zero, 0}, Case{kDma38Five, 5000}, Case{kDma38Max, 9999},
                          Case{kDma38Min, -9999}}) {
        const WriteRequest q{0x12, 0x01, 0x0027, asRaw(c.value)};
        EXPECT_EQ(encode(q), c.bytes);
        auto d = decodeRequest(c.bytes, kDma);
        ASSERT_TRUE(d.ok());
        EXPECT_EQ(std::get<WriteRequest>(*d), q);
    }
}

TEST(HcsDma, ProfinetSec4_3_ProfibusSec4_3_CyclicError)
{
    const ExceptionResponse e{0x23, 0x03, kCmdCyclic, 8};
    EXPECT_EQ(encode(e), kDma43CyclicError);
    auto typed = decodeCyclicResponse(kDma43CyclicError, kDma);
    ASSERT_FALSE(typed.ok());
    EXPECT_EQ(typed.error().code, DecodeErrc::DeviceException);
    EXPECT_EQ(typed.error().deviceCode, 8);
}

TEST(HcsDma, ProfinetSec4_4_1_ProfibusSec4_4_1_SingleSlave)
{
    // SNUM 1 = one module (DMA counts modules, the OPAT counts slaves besides the master).
    const CyclicRequest q{0x23, {{0x00, 1000, 0}}};
    auto bytes = encode(q, Family::Dma);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(*bytes, kDma441Request);
    auto dq = decodeCyclicRequest(kDma441Request, kDma);
    ASSERT_TRUE(dq.ok());
    EXPECT_EQ(*dq, q);
    // Response: status 0x40 00, current A 0.000 A, current B 0.270 A.
    const CyclicResponse a{0x23, 0x01, 0x4000, 0, 270};
    EXPECT_EQ(encode(a), kDma441Response);
    auto da = decodeCyclicResponse(kDma441Response, kDma);
    ASSERT_TRUE(da.ok());
    EXPECT_EQ(*da, a);
}

TEST(HcsDma, ProfinetSec4_4_2_ProfibusSec4_4_2_ThreeModules)
{
    const CyclicRequest q{0x23, {{0x00, 1000, 0}, {0x00, 2000, 0}, {0x00, -3000, 0}}};
    auto bytes = encode(q, Family::Dma);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(*bytes, kDma442Request);
    auto dq = decodeCyclicRequest(kDma442Request, kDma);
    ASSERT_TRUE(dq.ok());
    EXPECT_EQ(*dq, q);
    // The tables number the response bytes 0,1,2,3,3,4,5,6,7 (byte 3 twice); the telegram has 9
    // bytes.
    const CyclicResponse expected[] = {{0x23, 1, 0x4000, 0, 270},
                                       {0x24, 2, 0x4000, 0, 540},
                                       {0x25, 3, 0x4000, 810, 0},
                                       {0x26, 1, 0x4000, 0, 270}};
    const Bytes *frames[] = {&kDma442Response1, &kDma442Response2, &kDma442Response3,
                             &kDma442Response1Again};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(encode(expected[i]), *frames[i]);
        auto d = decodeCyclicResponse(*frames[i], kDma);
        ASSERT_TRUE(d.ok());
        EXPECT_EQ(*d, expected[i]);
    }
}

TEST(HcsDma, SameBytesDifferentFamiliesDifferentModuleCounts)
{
    // OPAT §3.4.2 and DMA §4.4.2 send the same 18 bytes except SNUM: 2 (slaves besides the
    // master) vs 3 (modules). Decoding with the wrong family must not silently succeed.
    auto asDma = decodeCyclicRequest(kOpat342Request, kDma);
    ASSERT_FALSE(asDma.ok());
    EXPECT_EQ(asDma.error().code, DecodeErrc::TooLong);
    EXPECT_EQ(asDma.error().offset, 13u);
    auto asOpat = decodeCyclicRequest(kDma442Request, DecodeOptions{Family::Opat, false});
    ASSERT_FALSE(asOpat.ok());
    EXPECT_EQ(asOpat.error().code, DecodeErrc::Truncated);
    EXPECT_EQ(asOpat.error().offset, 18u);
}
