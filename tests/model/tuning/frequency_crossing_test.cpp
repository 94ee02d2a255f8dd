// The −3 dB and −90° frequencies of a sweep: a second-order system's points (ω_n, ζ known) give
// its bandwidth ω_n·√(1 − 2ζ² + √(4ζ⁴ − 4ζ² + 2)) and ω_n itself; phases wrapped per point are
// unwrapped across the sweep; points that are not valid are left out.
#include "model/tuning/frequency_response.h"

#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <numbers>

namespace {

using namespace vt::model;

constexpr double kFn = 3.0; // Hz
constexpr double kZeta = 0.5;

// Points of H(s) = ω_n² / (s² + 2ζω_n s + ω_n²) · e^{−s·delay}, `perDecade` per decade from
// 0.1 Hz to 100 Hz, as frequencyPoint reports them (phase wrapped into (−360°, 0°]).
std::vector<FrequencyPoint> secondOrderPoints(double delay, int perDecade)
{
    std::vector<FrequencyPoint> points;
    for (int i = 0; i <= 3 * perDecade; ++i) {
        const double f = 0.1 * std::pow(10.0, static_cast<double>(i) / perDecade);
        const std::complex<double> s(0, 2 * std::numbers::pi * f);
        const double wn = 2 * std::numbers::pi * kFn;
        const std::complex<double> h =
            wn * wn / (s * s + 2 * kZeta * wn * s + wn * wn) * std::exp(-s * delay);
        double phase = std::arg(h) * 180 / std::numbers::pi;
        if (phase > 0)
            phase -= 360;
        points.push_back(
            {f, 20 * std::log10(std::abs(h)), phase, 1.0, true, FrequencyProblem::None});
    }
    return points;
}

TEST(FrequencyCrossing, SecondOrderBandwidthAndNaturalFrequency)
{
    const std::vector<FrequencyPoint> points = secondOrderPoints(0, 10);
    const double z2 = kZeta * kZeta;
    const double bandwidth = kFn * std::sqrt(1 - 2 * z2 + std::sqrt(4 * z2 * z2 - 4 * z2 + 2));
    const std::optional<double> f3 = gainCrossing(points);
    const std::optional<double> f90 = phaseCrossing(points);
    ASSERT_TRUE(f3 && f90);
    EXPECT_NEAR(*f3, bandwidth, 0.02 * bandwidth);
    EXPECT_NEAR(*f90, kFn, 0.02 * kFn);
    EXPECT_FALSE(gainCrossing(points, -200.0));
}

TEST(FrequencyCrossing, PointsThatAreNotValidAreLeftOut)
{
    std::vector<FrequencyPoint> points = secondOrderPoints(0, 10);
    const std::optional<double> clean = gainCrossing(points);
    // A point below the bandwidth that would fall through −3 dB and −90° if it counted.
    points.push_back({1.05, -20.0, -170.0, 0.2, false, FrequencyProblem::AboveValidBand});
    EXPECT_EQ(gainCrossing(points), clean);
    EXPECT_NEAR(*phaseCrossing(points), kFn, 0.02 * kFn);
}

// A 50 ms delay turns the phase past −360° (wrapped per point back to near 0°); unwrapped across
// the sweep it crosses −450° where the second order's and the delay's lags add up to it.
TEST(FrequencyCrossing, PhaseIsUnwrappedAcrossTheSweep)
{
    constexpr double kDelay = 0.05;
    const std::vector<FrequencyPoint> points = secondOrderPoints(kDelay, 40);
    const auto lagDeg = [&](double f) {
        const double r = f / kFn;
        const double second = std::atan2(2 * kZeta * r, 1 - r * r) * 180 / std::numbers::pi;
        return -second - 360 * f * kDelay;
    };
    const std::vector<double> unwrapped = unwrappedPhaseDeg(points);
    ASSERT_EQ(unwrapped.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        EXPECT_NEAR(unwrapped[i], lagDeg(points[i].frequencyHz), 1e-9) << points[i].frequencyHz;

    double lo = kFn, hi = 100; // the reference: bisection on the formula
    for (int i = 0; i < 60; ++i)
        (lagDeg(0.5 * (lo + hi)) > -450 ? lo : hi) = 0.5 * (lo + hi);
    const std::optional<double> f450 = phaseCrossing(points, -450.0);
    ASSERT_TRUE(f450);
    EXPECT_NEAR(*f450, lo, 0.02 * lo);
}

TEST(FrequencyCrossing, NoValidPointsNoCrossing)
{
    EXPECT_FALSE(gainCrossing({}));
    EXPECT_FALSE(phaseCrossing({}));
    std::vector<FrequencyPoint> points = secondOrderPoints(0, 10);
    for (FrequencyPoint &p : points)
        p.valid = false;
    EXPECT_FALSE(gainCrossing(points));
    EXPECT_TRUE(std::isnan(unwrappedPhaseDeg(points).front()));
}

} // namespace
