// Step metrics refuse what they cannot measure, each with its own reason: no step, a recording
// that does not cover the step and its final-value window, too few samples, a response lost in
// the noise, a hold too short for the loop to settle.
#include "model/tuning/step_metrics.h"
#include "synthetic.h"

#include <gtest/gtest.h>

namespace {

using namespace vt::model;
using namespace vt::model::test;

constexpr double kTau = 0.1;

std::string_view problemOf(const Samples &actual, const StepEdge &edge)
{
    const auto result = stepMetrics(actual, edge);
    return result.ok() ? "accepted" : stepProblemKey(result.error());
}

Samples lag(double from, double to, double rateHz)
{
    return sampled(polledTimes(0, 3.0, rateHz, 0.8, 11),
                   stepThrough(from, to, 1.0, 0, firstOrder(kTau)));
}

TEST(StepRefusal, ZeroStep)
{
    EXPECT_EQ(problemOf(lag(1, 1, 200), StepEdge{1.0, 1.0, 1.0, 3.0, 1.0}), "zero-step");
}

TEST(StepRefusal, RecordingEndsBeforeTheFinalValueWindow)
{
    const Samples actual = lag(0, 2, 200);
    EXPECT_EQ(problemOf(actual, StepEdge{1.0, 0.0, 2.0, 3.0, 1.0}), "accepted");
    // The hold runs to 5 s, the recording to 3 s: its last 10 % (4.6..5 s) is not recorded.
    EXPECT_EQ(problemOf(actual, StepEdge{1.0, 0.0, 2.0, 5.0, 1.0}), "too-short");
    // A recording that starts after the step.
    EXPECT_EQ(problemOf(actual, StepEdge{-1.0, 0.0, 2.0, 3.0, 1.0}), "too-short");
    // A hold without length.
    EXPECT_EQ(problemOf(actual, StepEdge{1.0, 0.0, 2.0, 1.0, 1.0}), "too-short");
}

TEST(StepRefusal, TooFewSamples)
{
    // 2 s hold at 8 Hz: 16 samples, fewer than kMinHoldSamples.
    EXPECT_EQ(problemOf(lag(0, 2, 8), StepEdge{1.0, 0.0, 2.0, 3.0, 1.0}), "too-few-samples");
    EXPECT_EQ(problemOf(lag(0, 2, 25), StepEdge{1.0, 0.0, 2.0, 3.0, 1.0}), "accepted");
}

TEST(StepRefusal, ResponseLostInTheNoise)
{
    FixedNoise noise(12);
    const Samples flat = sampled(polledTimes(0, 3.0, 200, 0.8, 13),
                                 [&](double) { return 1.0 + 0.01 * noise.next(); });
    EXPECT_EQ(problemOf(flat, StepEdge{1.0, 1.0, 3.0, 3.0, 1.0}), "no-response");
}

TEST(StepRefusal, HoldTooShortToSettle)
{
    // Held 2 τ: across its last 10 % the lag still changes by 3.5 % of the step.
    EXPECT_EQ(problemOf(lag(0, 2, 200), StepEdge{1.0, 0.0, 2.0, 1.0 + 2 * kTau, 1.0}),
              "not-settled");
    EXPECT_EQ(problemOf(lag(0, 2, 200), StepEdge{1.0, 0.0, 2.0, 1.0 + 5 * kTau, 1.0}), "accepted");
}

TEST(StepRefusal, KeysAreStable)
{
    EXPECT_EQ(stepProblemKey(StepProblem::TooFewSamples), "too-few-samples");
    EXPECT_EQ(stepProblemKey(StepProblem::TooShort), "too-short");
    EXPECT_EQ(stepProblemKey(StepProblem::ZeroStep), "zero-step");
    EXPECT_EQ(stepProblemKey(StepProblem::NoResponse), "no-response");
    EXPECT_EQ(stepProblemKey(StepProblem::NotSettled), "not-settled");
}

} // namespace
