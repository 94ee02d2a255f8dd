// The workbench's signals (model/tuning/test_signal.h): levels, edges, measuring windows and the
// specs that cannot make a signal.
#include "model/tuning/test_signal.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace vt::model {
namespace {

SignalSpec step(double from, double to, double hold, int repeats, StepDirection direction)
{
    SignalSpec s;
    s.kind = SignalKind::Step;
    s.from = from;
    s.to = to;
    s.hold = hold;
    s.repeats = repeats;
    s.direction = direction;
    return s;
}

TEST(TestSignal, AnUpStepSettlesAtFromThenHoldsTo)
{
    const auto signal = TestSignal::make(step(3, 5, 2, 1, StepDirection::Up));
    ASSERT_TRUE(signal);
    EXPECT_DOUBLE_EQ(signal->duration(), 4);
    EXPECT_DOUBLE_EQ(signal->valueAt(0), 3);
    EXPECT_DOUBLE_EQ(signal->valueAt(1.999), 3);
    EXPECT_DOUBLE_EQ(signal->valueAt(2), 5);
    EXPECT_DOUBLE_EQ(signal->valueAt(10), 5);
    ASSERT_EQ(signal->edges().size(), 1u);
    EXPECT_DOUBLE_EQ(signal->edges()[0].time, 2);
    EXPECT_DOUBLE_EQ(signal->edges()[0].from, 3);
    EXPECT_DOUBLE_EQ(signal->edges()[0].to, 5);
    EXPECT_DOUBLE_EQ(signal->edges()[0].end, 4);
    EXPECT_DOUBLE_EQ(signal->minimum(), 3);
    EXPECT_DOUBLE_EQ(signal->maximum(), 5);
}

TEST(TestSignal, RepeatedUpStepsGoBackWithoutMeasuringTheWayBack)
{
    const auto signal = TestSignal::make(step(3, 5, 1, 3, StepDirection::Up));
    ASSERT_TRUE(signal);
    // 3 | 5 | 3 | 5 | 3 | 5
    EXPECT_DOUBLE_EQ(signal->duration(), 6);
    EXPECT_DOUBLE_EQ(signal->valueAt(2.5), 3);
    ASSERT_EQ(signal->edges().size(), 3u);
    for (const SignalEdge &e : signal->edges()) {
        EXPECT_DOUBLE_EQ(e.from, 3);
        EXPECT_DOUBLE_EQ(e.to, 5);
    }
    EXPECT_DOUBLE_EQ(signal->edges()[2].time, 5);
}

TEST(TestSignal, DownStepsRunFromToBackToFrom)
{
    const auto signal = TestSignal::make(step(3, 5, 1, 2, StepDirection::Down));
    ASSERT_TRUE(signal);
    EXPECT_DOUBLE_EQ(signal->initialValue(), 5);
    ASSERT_EQ(signal->edges().size(), 2u);
    EXPECT_DOUBLE_EQ(signal->edges()[0].from, 5);
    EXPECT_DOUBLE_EQ(signal->edges()[0].to, 3);
}

TEST(TestSignal, BothDirectionsMeasureEveryEdge)
{
    const auto signal = TestSignal::make(step(3, 5, 1, 2, StepDirection::Both));
    ASSERT_TRUE(signal);
    // 3 | 5 | 3 | 5 | 3
    EXPECT_DOUBLE_EQ(signal->duration(), 5);
    ASSERT_EQ(signal->edges().size(), 4u);
    EXPECT_DOUBLE_EQ(signal->edges()[1].from, 5);
    EXPECT_DOUBLE_EQ(signal->edges()[1].to, 3);
    EXPECT_DOUBLE_EQ(signal->valueAt(4.5), 3);
}

TEST(TestSignal, SineStartsAtTheOffsetAndMeasuresAfterSettling)
{
    SignalSpec s;
    s.kind = SignalKind::Sine;
    s.amplitude = 1;
    s.offset = 4;
    s.frequencyHz = 2;
    s.cycles = 3;
    s.settlingCycles = 1;
    const auto signal = TestSignal::make(s);
    ASSERT_TRUE(signal);
    EXPECT_DOUBLE_EQ(signal->duration(), 2);
    EXPECT_NEAR(signal->valueAt(0), 4, 1e-12);
    EXPECT_NEAR(signal->valueAt(0.125), 5, 1e-12); // a quarter period
    EXPECT_NEAR(signal->valueAt(0.375), 3, 1e-12);
    ASSERT_EQ(signal->points().size(), 1u);
    EXPECT_DOUBLE_EQ(signal->points()[0].measureStart, 0.5);
    EXPECT_EQ(signal->points()[0].cycles, 3);
    EXPECT_DOUBLE_EQ(signal->minimum(), 3);
    EXPECT_DOUBLE_EQ(signal->maximum(), 5);
}

TEST(TestSignal, TriangleAndSquareHaveTheirShapes)
{
    SignalSpec s;
    s.kind = SignalKind::Triangle;
    s.amplitude = 2;
    s.offset = 0;
    s.frequencyHz = 1;
    s.cycles = 1;
    s.settlingCycles = 0;
    auto tri = TestSignal::make(s);
    ASSERT_TRUE(tri);
    EXPECT_NEAR(tri->valueAt(0.125), 1, 1e-12);
    EXPECT_NEAR(tri->valueAt(0.25), 2, 1e-12);
    EXPECT_NEAR(tri->valueAt(0.75), -2, 1e-12);
    s.kind = SignalKind::Square;
    auto square = TestSignal::make(s);
    ASSERT_TRUE(square);
    EXPECT_DOUBLE_EQ(square->valueAt(0.1), 2);
    EXPECT_DOUBLE_EQ(square->valueAt(0.6), -2);
    ASSERT_EQ(square->edges().size(), 1u);
    EXPECT_DOUBLE_EQ(square->edges()[0].time, 0.5);
}

TEST(TestSignal, SweepStepsThroughLogSpacedFrequenciesInWholeCycles)
{
    const auto f = sweepFrequencies(1, 100, 2);
    ASSERT_EQ(f.size(), 5u);
    EXPECT_NEAR(f[1], std::sqrt(10.0), 1e-9);
    EXPECT_DOUBLE_EQ(f.back(), 100);

    SignalSpec s;
    s.kind = SignalKind::Sweep;
    s.amplitude = 1;
    s.offset = 2;
    s.fromHz = 1;
    s.toHz = 10;
    s.pointsPerDecade = 1;
    s.cycles = 2;
    s.settlingCycles = 1;
    const auto signal = TestSignal::make(s);
    ASSERT_TRUE(signal);
    ASSERT_EQ(signal->points().size(), 2u);
    EXPECT_DOUBLE_EQ(signal->duration(), 3.0 + 0.3);
    EXPECT_DOUBLE_EQ(signal->points()[1].start, 3);
    EXPECT_DOUBLE_EQ(signal->points()[1].measureStart, 3.1);
    // Each frequency starts at phase 0: a quarter period of 10 Hz after its start is the peak.
    EXPECT_NEAR(signal->valueAt(3.025), 3, 1e-9);
}

TEST(TestSignal, SpecsThatMakeNoSignalAreRefusedWithAReason)
{
    std::string why;
    EXPECT_FALSE(TestSignal::make(step(3, 3, 1, 1, StepDirection::Up), &why));
    EXPECT_NE(why.find("different"), std::string::npos);
    EXPECT_FALSE(TestSignal::make(step(3, 5, 0, 1, StepDirection::Up), &why));
    EXPECT_FALSE(TestSignal::make(step(3, 5, NAN, 1, StepDirection::Up), &why));
    EXPECT_FALSE(TestSignal::make(step(3, 5, 3000, 2, StepDirection::Up), &why));
    EXPECT_NE(why.find("hour"), std::string::npos);
    SignalSpec s;
    s.kind = SignalKind::Sweep;
    s.amplitude = 1;
    s.fromHz = 10;
    s.toHz = 1;
    EXPECT_FALSE(TestSignal::make(s, &why));
    s.kind = SignalKind::Sine;
    s.amplitude = 0;
    EXPECT_FALSE(TestSignal::make(s, &why));
}

TEST(TestSignal, KindsAndDirectionsHaveKeys)
{
    EXPECT_EQ(dev::fromKey<SignalKind>("sweep"), SignalKind::Sweep);
    EXPECT_STREQ(key(SignalKind::Triangle), "triangle");
    EXPECT_EQ(dev::fromKey<StepDirection>("both"), StepDirection::Both);
    EXPECT_FALSE(dev::fromKey<StepDirection>("sideways"));
}

} // namespace
} // namespace vt::model
