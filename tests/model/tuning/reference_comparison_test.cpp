// The reference fingerprint's comparison math (model/tuning/reference_comparison.h) on synthetic
// figures and recordings with known answers: each figure's change and its threshold, a slower lag
// reading as a rise-time drift, the settings that differ in display units, and the overlay of two
// responses on one axis.
#include "dict/cooking.h"
#include "dict/dictionary_loader.h"
#include "model/tuning/reference_comparison.h"
#include "synthetic.h"

#include <cmath>
#include <gtest/gtest.h>

namespace vt::model {
namespace {

const DriftThresholds kDefaults;

TEST(ReferenceComparison, RiseTimeCountsBothWaysInPercentOfTheReference)
{
    const MetricDrift slower = metricDrift(DriftMetric::RiseTime, 0.1, 0.125, kDefaults);
    EXPECT_NEAR(slower.deltaPercent, 25, 1e-9);
    EXPECT_DOUBLE_EQ(slower.thresholdPercent, 20);
    EXPECT_TRUE(slower.exceeded);
    const MetricDrift faster = metricDrift(DriftMetric::RiseTime, 0.1, 0.075, kDefaults);
    EXPECT_NEAR(faster.deltaPercent, -25, 1e-9);
    EXPECT_TRUE(faster.exceeded);
    const MetricDrift close = metricDrift(DriftMetric::RiseTime, 0.1, 0.115, kDefaults);
    EXPECT_NEAR(close.deltaPercent, 15, 1e-9);
    EXPECT_FALSE(close.exceeded);
}

TEST(ReferenceComparison, OvershootCountsOnlyARiseInPercentagePoints)
{
    const MetricDrift within = metricDrift(DriftMetric::Overshoot, 0.3, 5.0, kDefaults);
    EXPECT_NEAR(within.deltaPercent, 4.7, 1e-9);
    EXPECT_FALSE(within.exceeded);
    EXPECT_TRUE(metricDrift(DriftMetric::Overshoot, 0.3, 5.4, kDefaults).exceeded);
    const MetricDrift calmer = metricDrift(DriftMetric::Overshoot, 18, 0, kDefaults);
    EXPECT_NEAR(calmer.deltaPercent, -18, 1e-9);
    EXPECT_FALSE(calmer.exceeded);
}

TEST(ReferenceComparison, SteadyStateErrorCountsInPercentOfTheStep)
{
    // 0.06 − 0.01 of a 2 V step: 2.5 % of the step.
    const MetricDrift d = metricDrift(DriftMetric::SteadyStateError, 0.01, 0.06, kDefaults, 2.0);
    EXPECT_NEAR(d.deltaPercent, 2.5, 1e-9);
    EXPECT_TRUE(d.exceeded);
    EXPECT_FALSE(metricDrift(DriftMetric::SteadyStateError, 0.01, -0.02, kDefaults, 2.0).exceeded);
}

TEST(ReferenceComparison, AFigureGoneNowIsDriftOneThatAppearedIsNot)
{
    const MetricDrift gone = metricDrift(DriftMetric::SettlingTime, 0.3, NAN, kDefaults);
    EXPECT_TRUE(gone.exceeded);
    EXPECT_TRUE(std::isnan(gone.deltaPercent));
    EXPECT_FALSE(metricDrift(DriftMetric::SettlingTime, NAN, 0.3, kDefaults).exceeded);
    EXPECT_FALSE(metricDrift(DriftMetric::SettlingTime, NAN, NAN, kDefaults).exceeded);
}

TEST(ReferenceComparison, EditedThresholdsApply)
{
    DriftThresholds strict;
    strict.riseTimePct = 10;
    strict.overshootPoints = 1;
    EXPECT_TRUE(metricDrift(DriftMetric::RiseTime, 0.1, 0.115, strict).exceeded);
    EXPECT_TRUE(metricDrift(DriftMetric::Overshoot, 0.3, 1.5, strict).exceeded);
    EXPECT_DOUBLE_EQ(metricDrift(DriftMetric::Overshoot, 0.3, 1.5, strict).thresholdPercent, 1);
}

// A lag of τ polled at 200 Hz, 3 → 5 V at t = 1 s, held 2 s (over 13 τ: settled).
StepMetrics lagStep(double tau, std::uint32_t seed, Samples *out = nullptr)
{
    const auto s = test::firstOrder(tau);
    const Samples actual = test::sampled(test::polledTimes(0, 3, 200, 0.8, seed),
                                         [&](double t) { return 3 + 2 * s(t - 1); });
    const StepEdge edge{1, 3, 5, 3, 1};
    const auto m = stepMetrics(actual, edge);
    EXPECT_TRUE(m.ok());
    if (out)
        *out = actual;
    return m.ok() ? *m : StepMetrics{};
}

TEST(ReferenceComparison, ASlowerLagShowsAsARiseAndSettlingTimeDrift)
{
    // Rise τ·ln 9 and settling τ·ln 50 both scale with τ: 0.1 → 0.15 s is +50 %.
    const auto drift = stepDrift(lagStep(0.1, 1), lagStep(0.15, 2), kDefaults, "V");
    ASSERT_EQ(drift.size(), 4u);
    EXPECT_EQ(drift[0].metric, DriftMetric::RiseTime);
    EXPECT_NEAR(drift[0].reference, 0.1 * std::log(9), 1e-3);
    EXPECT_NEAR(drift[0].deltaPercent, 50, 1.5);
    EXPECT_TRUE(drift[0].exceeded);
    EXPECT_EQ(drift[0].unit, "s");
    EXPECT_EQ(drift[1].metric, DriftMetric::Overshoot);
    EXPECT_FALSE(drift[1].exceeded);
    EXPECT_EQ(drift[2].metric, DriftMetric::SettlingTime);
    EXPECT_NEAR(drift[2].deltaPercent, 50, 1.5);
    EXPECT_TRUE(drift[2].exceeded);
    EXPECT_EQ(drift[3].metric, DriftMetric::SteadyStateError);
    EXPECT_EQ(drift[3].unit, "V");
    EXPECT_FALSE(drift[3].exceeded);
}

TEST(ReferenceComparison, TheSameLagCompareswithinEveryThreshold)
{
    const auto drift = stepDrift(lagStep(0.1, 1), lagStep(0.1, 7), kDefaults, "V");
    for (const MetricDrift &d : drift)
        EXPECT_FALSE(d.exceeded) << d.label << " " << d.deltaPercent;
}

TEST(ReferenceComparison, AStepWithoutFiguresNowExceedsEveryFigureItHad)
{
    const auto drift = stepDrift(lagStep(0.1, 1), std::nullopt, kDefaults, "V");
    ASSERT_EQ(drift.size(), 4u);
    for (const MetricDrift &d : drift)
        EXPECT_TRUE(d.exceeded) << d.label;
}

TEST(ReferenceComparison, SweepFrequenciesCountInPercent)
{
    const auto drift = sweepDrift(8.0, 6.0, 5.0, 5.5, kDefaults);
    ASSERT_EQ(drift.size(), 2u);
    EXPECT_EQ(drift[0].metric, DriftMetric::Bandwidth);
    EXPECT_NEAR(drift[0].deltaPercent, -25, 1e-9);
    EXPECT_TRUE(drift[0].exceeded);
    EXPECT_EQ(drift[1].metric, DriftMetric::Phase90);
    EXPECT_NEAR(drift[1].deltaPercent, 10, 1e-9);
    EXPECT_FALSE(drift[1].exceeded);
    EXPECT_EQ(drift[1].unit, "Hz");
}

TEST(ReferenceComparison, SettingsThatDifferInDisplayUnitsInDictionaryOrder)
{
    const auto &set = dev::builtinDictionaries();
    ASSERT_TRUE(set.ok());
    const dev::Dictionary *dma = set->find("dma-pn-v51");
    ASSERT_TRUE(dma);
    // C1.13: 100 == factor 1.00 (DMA Profinet manual §4.4).
    const std::vector<RunSetting> before{{"C1.13", 200}, {"C1.17", 0}, {"C1.00", 1}, {"X", 1}};
    const std::vector<RunSetting> after{{"C1.00", 1}, {"C1.17", 0}, {"C1.13", 50}, {"C1.09", 4}};
    const auto drift = paramDrift(3, *dma, before, after, dev::Language::English);
    ASSERT_EQ(drift.size(), 3u);
    EXPECT_EQ(drift[0].row, "C1.09"); // dictionary order: C1.09 before C1.13
    EXPECT_FALSE(drift[0].reference);
    EXPECT_DOUBLE_EQ(*drift[0].now, dev::toDisplay(*dma->find("C1.09"), 4));
    EXPECT_EQ(drift[1].row, "C1.13");
    EXPECT_EQ(drift[1].module, 3);
    EXPECT_DOUBLE_EQ(*drift[1].reference, 2.0);
    EXPECT_DOUBLE_EQ(*drift[1].now, 0.5);
    EXPECT_DOUBLE_EQ(*drift[1].nowRaw, 50);
    EXPECT_EQ(drift[1].unit, dma->find("C1.13")->unit);
    EXPECT_EQ(drift[1].name, dma->find("C1.13")->label.in(dev::Language::English));
    EXPECT_EQ(drift[2].row, "X"); // not in the dictionary: last, raw
    EXPECT_DOUBLE_EQ(*drift[2].reference, 1);
    EXPECT_FALSE(drift[2].now);
}

TEST(ReferenceComparison, TheOverlayPutsBothResponsesOnTheTimeAfterTheirSteps)
{
    Samples slow;
    Samples fast;
    lagStep(0.15, 3, &slow);
    lagStep(0.1, 4, &fast);
    // The same responses recorded with the step 0.4 s later.
    Samples later = fast;
    for (double &t : later.t)
        t += 0.4;
    const DriftOverlay o =
        stepOverlay("step-up", slow, {1, 3, 5, 3, 1}, later, {1.4, 3, 5, 3.4, 1.4}, 111);
    ASSERT_EQ(o.x.size(), 111u);
    EXPECT_NEAR(o.x.front(), -0.2, 1e-12); // a tenth of the hold before the step
    EXPECT_NEAR(o.x.back(), 2.0, 1e-12);
    for (std::size_t i = 0; i < o.x.size(); ++i) {
        EXPECT_NEAR(o.reference[i], valueAt(slow, 1 + o.x[i]), 1e-12);
        EXPECT_NEAR(o.now[i], valueAt(fast, 1 + o.x[i]), 1e-12);
    }
}

} // namespace
} // namespace vt::model
