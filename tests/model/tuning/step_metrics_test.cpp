// Step metrics against synthetic responses with known answers, sampled at polled (uneven) times:
// first order (rise τ·ln 9, settling τ·ln 50 and τ·ln 20, no overshoot), second order (overshoot
// exp(−πζ/√(1−ζ²)), peak time π/ω_d), a transport delay, a down step, fixed noise, and the
// steps of a staircase set value found by findStepEdges.
#include "model/tuning/step_metrics.h"
#include "synthetic.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace {

using namespace vt::model;
using namespace vt::model::test;

constexpr double kTau = 0.1;           // s
constexpr double kRate = 200;          // Hz, the monitor's nominal rate
constexpr double kJitter = 0.8;        // ±40 % of a sample interval
constexpr double kExactTime = 0.5e-3;  // s, noise-free first order (linear interpolation only)
constexpr double kSecondTime = 1.0e-3; // s, noise-free second order (curvier near its crossings)

StepMetrics metricsOf(const Samples &actual, const StepEdge &edge)
{
    const auto result = stepMetrics(actual, edge);
    if (!result.ok()) {
        ADD_FAILURE() << "refused: " << stepProblemKey(result.error());
        return {};
    }
    return *result;
}

// First time t ≥ 0 with s(t) ≥ level, by bisection after a fine scan (the reference, from the
// formula, not from samples).
double firstReach(const std::function<double(double)> &s, double level)
{
    double lo = 0, hi = 0;
    while (s(hi) < level)
        hi += 1e-4;
    lo = hi - 1e-4;
    for (int i = 0; i < 60; ++i)
        (s(0.5 * (lo + hi)) < level ? lo : hi) = 0.5 * (lo + hi);
    return hi;
}

// Last time before `until` with |s(t) − 1| > band, by a fine backward scan and bisection.
double lastOutside(const std::function<double(double)> &s, double band, double until)
{
    const auto outside = [&](double t) { return std::abs(s(t) - 1.0) > band; };
    double hi = until;
    while (!outside(hi - 1e-5))
        hi -= 1e-5;
    double lo = hi - 1e-5;
    for (int i = 0; i < 60; ++i)
        (outside(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
    return hi;
}

TEST(StepMetrics, FirstOrderUpStep)
{
    const Samples set{{0.0, 1.0}, {1.0, 4.0}};
    const Samples actual = sampled(polledTimes(0, 3.0, kRate, kJitter, 1),
                                   stepThrough(1.0, 4.0, 1.0, 0, firstOrder(kTau)));
    const std::vector<StepEdge> edges = findStepEdges(set, 0.01, 3.0);
    ASSERT_EQ(edges.size(), 1u);
    const StepMetrics m = metricsOf(actual, edges[0]);
    EXPECT_TRUE(m.up);
    EXPECT_NEAR(m.startValue, 1.0, 1e-9);
    EXPECT_NEAR(m.finalValue, 4.0, 1e-6);
    EXPECT_NEAR(m.steadyStateError, 0.0, 1e-6);
    EXPECT_NEAR(m.deadTime, kTau * std::log(1 / 0.98), kExactTime);
    EXPECT_NEAR(m.riseTime, kTau * std::log(9.0), kExactTime);
    EXPECT_NEAR(m.rise10Time, 1.0 + kTau * std::log(1 / 0.9), kExactTime);
    EXPECT_NEAR(m.rise90Time, 1.0 + kTau * std::log(10.0), kExactTime);
    EXPECT_NEAR(m.settlingTime2, kTau * std::log(50.0), kExactTime);
    EXPECT_NEAR(m.settlingTime5, kTau * std::log(20.0), kExactTime);
    EXPECT_NEAR(m.overshootPct, 0.0, 1e-4);
}

TEST(StepMetrics, FirstOrderDownStepWithDeadTime)
{
    constexpr double kDelay = 0.05;
    const Samples set{{0.0, 2.0}, {5.0, 2.0}};
    const Samples actual = sampled(polledTimes(0, 4.0, kRate, kJitter, 2),
                                   stepThrough(5.0, 2.0, 2.0, kDelay, firstOrder(kTau)));
    const std::vector<StepEdge> edges = findStepEdges(set, 0.01, 4.0);
    ASSERT_EQ(edges.size(), 1u);
    const StepMetrics m = metricsOf(actual, edges[0]);
    EXPECT_FALSE(m.up);
    EXPECT_NEAR(m.finalValue, 2.0, 1e-6);
    EXPECT_NEAR(m.deadTime, kDelay + kTau * std::log(1 / 0.98), kExactTime);
    EXPECT_NEAR(m.riseTime, kTau * std::log(9.0), kExactTime);
    EXPECT_NEAR(m.settlingTime2, kDelay + kTau * std::log(50.0), kExactTime);
    EXPECT_NEAR(m.settlingTime5, kDelay + kTau * std::log(20.0), kExactTime);
    EXPECT_NEAR(m.overshootPct, 0.0, 1e-4);
    EXPECT_LT(m.rise90Time, 2.0 + kDelay + kTau * std::log(10.0) + kExactTime);
}

TEST(StepMetrics, SecondOrderOvershootAndPeakTime)
{
    constexpr double kZeta = 0.35, kOmegaN = 20.0, kStep = 0.5, kEnd = 3.0;
    const auto s = secondOrder(kZeta, kOmegaN);
    const Samples set{{0.0, kStep}, {0.0, 2.0}};
    const Samples actual =
        sampled(polledTimes(0, kEnd, kRate, kJitter, 3), stepThrough(0.0, 2.0, kStep, 0, s));
    const std::vector<StepEdge> edges = findStepEdges(set, 0.01, kEnd);
    ASSERT_EQ(edges.size(), 1u);
    const StepMetrics m = metricsOf(actual, edges[0]);
    const double root = std::sqrt(1 - kZeta * kZeta);
    EXPECT_NEAR(m.overshootPct, 100.0 * std::exp(-std::numbers::pi * kZeta / root), 0.1);
    EXPECT_NEAR(m.peakTime, std::numbers::pi / (kOmegaN * root), 0.5 / kRate * (1 + kJitter));
    EXPECT_NEAR(m.peakValue, 2.0 * s(m.peakTime), 1e-9);
    EXPECT_NEAR(m.riseTime, firstReach(s, 0.9) - firstReach(s, 0.1), kSecondTime);
    EXPECT_NEAR(m.deadTime, firstReach(s, 0.02), kSecondTime);
    EXPECT_NEAR(m.settlingTime2, lastOutside(s, 0.02, kEnd - kStep), kSecondTime);
    EXPECT_NEAR(m.settlingTime5, lastOutside(s, 0.05, kEnd - kStep), kSecondTime);
    EXPECT_NEAR(m.steadyStateError, 0.0, 1e-6);
}

// Noise of ±0.3 % of the step (a fixed pseudo-random sequence plus a 47 Hz sine) moves a
// crossing by at most noise / slope: for the band b the settling time by up to
// τ·ln(b / (b − 0.003)) (16 ms at 2 %, 6 ms at 5 %); overshoot reads up to the noise.
TEST(StepMetrics, FirstOrderWithFixedNoise)
{
    constexpr double kStep = 3.0;
    FixedNoise noise(4);
    const auto clean = stepThrough(1.0, 1.0 + kStep, 1.0, 0, firstOrder(kTau));
    const auto noisy = [&](double t) {
        return clean(t) +
               kStep * (0.002 * noise.next() + 0.001 * std::sin(2 * std::numbers::pi * 47 * t));
    };
    const Samples actual = sampled(polledTimes(0, 3.0, kRate, kJitter, 5), noisy);
    const StepEdge edge{1.0, 1.0, 1.0 + kStep, 3.0, 1.0};
    const StepMetrics m = metricsOf(actual, edge);
    EXPECT_NEAR(m.startValue, 1.0, 0.001 * kStep);
    EXPECT_NEAR(m.steadyStateError, 0.0, 0.001 * kStep);
    EXPECT_NEAR(m.deadTime, kTau * std::log(1 / 0.98), 2e-3);
    EXPECT_NEAR(m.riseTime, kTau * std::log(9.0), 4e-3);
    EXPECT_NEAR(m.settlingTime2, kTau * std::log(50.0), 0.2 * kTau);
    EXPECT_NEAR(m.settlingTime5, kTau * std::log(20.0), 0.08 * kTau);
    EXPECT_LE(m.overshootPct, 0.35);
}

TEST(StepMetrics, SecondOrderWithFixedNoise)
{
    constexpr double kZeta = 0.35, kOmegaN = 20.0;
    FixedNoise noise(6);
    const auto clean = stepThrough(4.0, 1.0, 1.0, 0.02, secondOrder(kZeta, kOmegaN));
    const Samples actual = sampled(polledTimes(0, 4.0, kRate, kJitter, 7),
                                   [&](double t) { return clean(t) + 3.0 * 0.003 * noise.next(); });
    const StepMetrics m = metricsOf(actual, StepEdge{1.0, 4.0, 1.0, 4.0, 1.0});
    const double root = std::sqrt(1 - kZeta * kZeta);
    EXPECT_FALSE(m.up);
    EXPECT_NEAR(m.overshootPct, 100.0 * std::exp(-std::numbers::pi * kZeta / root), 0.5);
    EXPECT_NEAR(m.peakTime, 0.02 + std::numbers::pi / (kOmegaN * root), 0.015);
    EXPECT_NEAR(m.deadTime, 0.02 + firstReach(secondOrder(kZeta, kOmegaN), 0.02), 2e-3);
}

// A written staircase: three steps up and down, two changes below minJump that are no steps
// (after the first step has settled, and undone before its hold ends), each step's hold ending at
// the next; the metrics of every step, up or down, read the same lag.
TEST(StepMetrics, StaircaseStepsFoundAndMeasured)
{
    const Samples set{{0.0, 1.0, 1.5, 1.6, 3.0, 5.0}, {0.0, 2.0, 2.004, 2.0, 5.0, 1.0}};
    const std::vector<StepEdge> edges = findStepEdges(set, 0.01, 7.0);
    ASSERT_EQ(edges.size(), 3u);
    EXPECT_DOUBLE_EQ(edges[0].time, 1.0);
    EXPECT_DOUBLE_EQ(edges[0].from, 0.0);
    EXPECT_DOUBLE_EQ(edges[0].to, 2.0);
    EXPECT_DOUBLE_EQ(edges[0].end, 3.0);
    EXPECT_DOUBLE_EQ(edges[0].holdBefore, 1.0);
    EXPECT_DOUBLE_EQ(edges[1].time, 3.0);
    EXPECT_DOUBLE_EQ(edges[1].from, 2.0);
    EXPECT_DOUBLE_EQ(edges[1].to, 5.0);
    EXPECT_DOUBLE_EQ(edges[1].end, 5.0);
    EXPECT_DOUBLE_EQ(edges[1].holdBefore, 2.0);
    EXPECT_DOUBLE_EQ(edges[2].end, 7.0);

    const Samples actual = lagResponse(set, kTau, polledTimes(0, 7.0, kRate, kJitter, 8));
    for (const StepEdge &edge : edges) {
        const StepMetrics m = metricsOf(actual, edge);
        EXPECT_EQ(m.up, edge.to > edge.from);
        EXPECT_NEAR(m.riseTime, kTau * std::log(9.0), kExactTime);
        EXPECT_NEAR(m.settlingTime2, kTau * std::log(50.0), kExactTime);
        EXPECT_NEAR(m.steadyStateError, 0.0, 1e-6);
    }
}

TEST(StepMetrics, LastStepHoldsAtLeastUntilItsOwnTime)
{
    const std::vector<StepEdge> edges = findStepEdges(Samples{{0.0, 2.0}, {0.0, 1.0}}, 0.1, 1.0);
    ASSERT_EQ(edges.size(), 1u);
    EXPECT_DOUBLE_EQ(edges[0].end, 2.0);
    EXPECT_TRUE(findStepEdges(Samples{{0.0, 2.0}, {0.0, 0.05}}, 0.1, 3.0).empty());
    EXPECT_TRUE(findStepEdges(Samples{}, 0.1, 3.0).empty());
}

} // namespace
