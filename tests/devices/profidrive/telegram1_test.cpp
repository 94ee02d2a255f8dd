// PROFIdrive standard telegram 1 on the OPAT (OPAT manual §5): words, bits and N2 normalisation.
#include "profidrive/stw1_zsw1.h"
#include "profidrive/telegram1.h"
#include "worked_examples.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::profidrive;
using namespace vt::test::profidrive_examples;

TEST(ProfidriveTelegram1, Sec5_6_SetpointWordsRoundTrip)
{
    const Setpoint s{stw1::kOpatRun, 0x0700};
    const Bytes first4(kSec56Request.begin(), kSec56Request.begin() + 4);
    EXPECT_EQ(encode(s), first4);
    EXPECT_EQ(decodeSetpoint(first4).value(), s);
    // §5.2.1: "For using the set value Bit 0,1,2,3,4,5,6 and 10 must be set".
    EXPECT_EQ(stw1::kOpatRun, stw1::kOn | stw1::kNoCoastStop | stw1::kNoQuickStop |
                                  stw1::kEnableOperation | stw1::kEnableRampGenerator |
                                  stw1::kUnfreezeRampGenerator | stw1::kEnableSetpoint |
                                  stw1::kControlByPlc);
}

TEST(ProfidriveTelegram1, Sec5_6_ActualWords)
{
    const Bytes first4(kSec56ResponseMaster.begin(), kSec56ResponseMaster.begin() + 4);
    const Actual a{0x4237, static_cast<std::int16_t>(0xF39A)};
    EXPECT_EQ(encode(a), first4);
    EXPECT_EQ(decodeActual(first4).value(), a);
    EXPECT_TRUE(a.zsw1 & zsw1::kOperationEnabled);
    EXPECT_TRUE(a.zsw1 & zsw1::kClosedLoop);
    EXPECT_FALSE(a.zsw1 & zsw1::kFault);
}

TEST(ProfidriveTelegram1, Sec5_3_Sec5_6_N2ScalingIs0x4000For10Volt)
{
    // ARCHITECTURE.md "PROFIdrive N2": §5.6 "Set-value = 0x0700 == 1,093V" decides against §5.3's
    // "100% = 0x2000": 0x0700 / 0x4000 × 10 V = 1.09375 V (the manual truncates to 1,093), while
    // 0x2000 = 10 V would give 2.1875 V.
    EXPECT_DOUBLE_EQ(n2ToVolts(0x0700), 1.09375);
    EXPECT_DOUBLE_EQ(n2ToVolts(0x0700, 10.0 * 0x4000 / 0x2000), 2.1875); // the sentence's reading
    EXPECT_DOUBLE_EQ(n2ToPercent(0x4000), 100.0);
    EXPECT_DOUBLE_EQ(n2ToPercent(static_cast<std::int16_t>(0xC000)), -100.0);
    EXPECT_DOUBLE_EQ(n2ToVolts(0x4000), 10.0);
    EXPECT_EQ(voltsToN2(10.0), 0x4000);
    EXPECT_EQ(voltsToN2(-10.0), -0x4000);
    EXPECT_EQ(voltsToN2(1.09375), 0x0700);
    EXPECT_EQ(percentToN2(100.0), 0x4000);
    // N2 covers -200 % .. +200 % - 2^-14 %: saturate instead of wrapping.
    EXPECT_EQ(percentToN2(200.0), 32767);
    EXPECT_EQ(percentToN2(-200.0), -32768);
    EXPECT_EQ(voltsToN2(-1e9), -32768);
    EXPECT_EQ(voltsToN2(1.0, 0.0), 0);
    EXPECT_EQ(n2ToMillivolts(0x4000), 10000);
    EXPECT_EQ(n2ToMillivolts(0x0700), 1094);
    EXPECT_EQ(n2ToMillivolts(static_cast<std::int16_t>(0xF99A)), -1000); // slave answer in §5.6
}

TEST(ProfidriveTelegram1, TypedErrors)
{
    const Bytes three{0x04, 0x7F, 0x07};
    auto r = decodeSetpoint(three);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, DecodeErrc::Truncated);
    EXPECT_EQ(r.error().offset, 3u);
    const Bytes five{0x04, 0x7F, 0x07, 0x00, 0x12};
    EXPECT_EQ(decodeActual(five).error().code, DecodeErrc::TooLong);
    EXPECT_EQ(decodeActual(five).error().offset, 4u);
    EXPECT_TRUE(decodeActual(five, true).ok());
    EXPECT_EQ(decodeActual(Bytes{}).error().offset, 0u);
}

TEST(ProfidriveTelegram1, Sec5_2_Sec5_4_BitTablesComplete)
{
    ASSERT_EQ(stw1Bits().size(), 16u);
    ASSERT_EQ(zsw1Bits().size(), 16u);
    for (std::size_t i = 0; i < 16; ++i) {
        EXPECT_EQ(stw1Bits()[i].mask, 1u << i);
        EXPECT_EQ(zsw1Bits()[i].mask, 1u << i);
        EXPECT_TRUE(stw1Bits()[i].whenSet.complete());
        EXPECT_TRUE(zsw1Bits()[i].whenSet.complete());
    }
    EXPECT_EQ(stw1Bits()[12].name, "Din_1");
    EXPECT_EQ(zsw1Bits()[14].name, "Dout_1");
    EXPECT_TRUE(zsw1Bits()[3].whenSet.de.find("Fehlernummer") != std::string::npos);
}
