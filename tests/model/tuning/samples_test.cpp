// Reading a recorded channel between its samples: straight line, staircase, time-weighted mean
// over uneven spacing, and the achieved rate.
#include "model/tuning/samples.h"

#include <cmath>
#include <gtest/gtest.h>

namespace {

using vt::model::Samples;

const Samples kRamp{{0.0, 1.0, 1.5, 4.0}, {0.0, 2.0, 3.0, 8.0}}; // y = 2t, uneven spacing

TEST(TuningSamples, ValueAtReadsTheStraightLineAndHoldsTheEnds)
{
    EXPECT_DOUBLE_EQ(vt::model::valueAt(kRamp, 0.25), 0.5);
    EXPECT_DOUBLE_EQ(vt::model::valueAt(kRamp, 1.0), 2.0);
    EXPECT_DOUBLE_EQ(vt::model::valueAt(kRamp, 3.0), 6.0);
    EXPECT_DOUBLE_EQ(vt::model::valueAt(kRamp, -1.0), 0.0);
    EXPECT_DOUBLE_EQ(vt::model::valueAt(kRamp, 9.0), 8.0);
    EXPECT_TRUE(std::isnan(vt::model::valueAt(Samples{}, 1.0)));
}

TEST(TuningSamples, HeldValueAtReadsTheStaircase)
{
    EXPECT_DOUBLE_EQ(vt::model::heldValueAt(kRamp, 0.99), 0.0);
    EXPECT_DOUBLE_EQ(vt::model::heldValueAt(kRamp, 1.0), 2.0);
    EXPECT_DOUBLE_EQ(vt::model::heldValueAt(kRamp, 3.9), 3.0);
    EXPECT_DOUBLE_EQ(vt::model::heldValueAt(kRamp, 5.0), 8.0);
}

TEST(TuningSamples, MeanOverIsTimeWeightedAndClipped)
{
    // The mean of 2t over [0.5, 3.5] is 4, however unevenly the line is sampled.
    EXPECT_NEAR(vt::model::meanOver(kRamp, 0.5, 3.5), 4.0, 1e-12);
    // Clipped to the recording: [0, 4] → 4.
    EXPECT_NEAR(vt::model::meanOver(kRamp, -3.0, 7.0), 4.0, 1e-12);
    // Nothing left of the interval: the value at its clipped end.
    EXPECT_DOUBLE_EQ(vt::model::meanOver(kRamp, 5.0, 6.0), 8.0);
}

TEST(TuningSamples, AverageRate)
{
    EXPECT_DOUBLE_EQ(vt::model::averageRateHz(kRamp), 0.75);
    EXPECT_DOUBLE_EQ(vt::model::averageRateHz(Samples{{1.0}, {2.0}}), 0.0);
}

} // namespace
