// DSP-408 scaling against the ED1/SD1 PROFIBUS-DP manual §4.7.
#include "dsp408/scaling.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

using namespace vt::dev::dsp408;

// §4.7 example: 60 mA / 1.78 = 33.7 → 33; 33 × 1.78 = 58.74 → 58 mA.
TEST(Dsp408Scaling, Section47SolenoidCurrentExample)
{
    EXPECT_EQ(scaleToRaw(60.0, kFactSolCurrent), 33);
    EXPECT_EQ(scaleFromRaw(33, kFactSolCurrent), 58);
}

// §4.7.1 example: 4..20 mA transducer over 0..500 mm → 0.09765625 (97 µm steps).
TEST(Dsp408Scaling, Section471FactReferenceExample)
{
    EXPECT_DOUBLE_EQ(factReference(500.0, 16.0, 20.0), 0.09765625);
    EXPECT_EQ(factReference(500.0, 16.0, 0.0), 0.0);
}

TEST(Dsp408Scaling, TruncatesTowardZeroWithoutBinaryRoundingLosses)
{
    EXPECT_EQ(scaleToRaw(89.0, kFactSolCurrent), 50); // 89 / 1.78 is exactly 50
    EXPECT_EQ(scaleToRaw(-60.0, kFactSolCurrent), -33);
    EXPECT_EQ(scaleFromRaw(-33, kFactSolCurrent), -58);
    EXPECT_EQ(scaleToRaw(50.0, kFactPercentage), 0);
    EXPECT_EQ(scaleFromRaw(1024, kFactInterface), 10); // 1024 × 0.009765625 = 10 V
}

TEST(Dsp408Scaling, TotalOnBadInput)
{
    EXPECT_EQ(scaleToRaw(60.0, 0.0), 0);
    EXPECT_EQ(scaleToRaw(60.0, -1.0), 0);
    EXPECT_EQ(scaleToRaw(std::nan(""), 1.0), 0);
    EXPECT_EQ(scaleToRaw(1e300, 1.0), std::numeric_limits<std::int32_t>::max());
    EXPECT_EQ(scaleToRaw(-1e300, 1.0), std::numeric_limits<std::int32_t>::min());
    EXPECT_EQ(scaleFromRaw(1000, std::numeric_limits<double>::infinity()), 0);
}
