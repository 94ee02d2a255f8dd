// Closed loop plant ("a set-value step on A1.01 in closed loop gives a
// d1.11 response whose overshoot grows with C1.13 and whose steady-state error vanishes with
// C1.17 > 0, deterministically in simulated time"). Families with the C block's controller:
// OPAT (modes 3/4/6/8), DMA PROFINET V51, DMA PROFIBUS V31/V32.
#include "plant_test_support.h"

#include <algorithm>
#include <cmath>

using namespace vt::dev::sim;
using namespace vt::dev::sim::test;

namespace {

class PlantClosedLoop : public ::testing::TestWithParam<std::string>
{
protected:
    // A position loop (mode 3) with a 0 … 10 V sensor over the stroke, P-PT1-I-DT1 selected.
    static std::unique_ptr<ClosedRig> positionLoop(std::int32_t kp1, std::int32_t ki)
    {
        auto rig = std::make_unique<ClosedRig>(GetParam());
        rig->set("C1.00", 1); // P-PT1-I-DT1 (the DMA default is 0 = off)
        rig->set("C1.09", 4); // 0 … 10 V
        rig->set("C1.13", kp1);
        rig->set("C1.17", ki);
        return rig;
    }
};

struct StepResponse
{
    double before = 0, peak = 0, final = 0; // d1.11, mV
    std::int32_t finalLagError = 0;         // d1.12, mV
    std::int32_t finalOutput = 0;           // d1.13, mV
    double overshoot() const { return (peak - final) / (final - before); }
};

// Settles at 3.000 V, then steps A1.01 to 5.000 V and records d1.11 for `seconds`.
StepResponse stepResponse(ClosedRig &rig, double seconds)
{
    rig.set("A1.01", 3000);
    rig.run(4.0);
    StepResponse r;
    r.before = rig.get("d1.11");
    rig.set("A1.01", 5000);
    const auto x = rig.record("d1.11", seconds);
    r.peak = *std::max_element(x.begin(), x.end());
    r.final = x.back();
    r.finalLagError = rig.get("d1.12");
    r.finalOutput = rig.get("d1.13");
    return r;
}

} // namespace

// C1.13 (KP1, "100 == factor 1.00"): the stiffer the P-portion against the valve's and the oil
// column's lag, the larger the overshoot. Measured: 200 -> 0.3 %, 300 -> 18 %, 400 -> 42 %.
TEST_P(PlantClosedLoop, OvershootGrowsWithC1_13)
{
    std::vector<double> overshoot;
    for (std::int32_t kp : {100, 200, 300, 400}) {
        auto rig = positionLoop(kp, 0);
        const StepResponse r = stepResponse(*rig, 4.0);
        overshoot.push_back(r.overshoot());
        EXPECT_GT(r.final - r.before, 1900) << "C1.13 = " << kp << ": the axis followed the step";
    }
    EXPECT_LT(overshoot[0], 0.005); // factor 1.00: well damped
    EXPECT_LT(overshoot[1], 0.02);
    for (std::size_t i = 1; i < overshoot.size(); ++i)
        EXPECT_GT(overshoot[i], overshoot[i - 1]) << "C1.13 step " << i;
    EXPECT_GT(overshoot[2], 0.10);
    EXPECT_GT(overshoot[3], 0.30);
}

// C1.17 (I-portion, V/s): the valve's null shift is a steady disturbance; a P-only loop holds the
// lag error that makes the output cancel it (1 % of nominal flow = 0.100 V of output, so
// 100 mV of lag error at C1.13 = 1.00 and 50 mV at 2.00); the I-portion takes it to zero and
// carries the 0.100 V itself.
TEST_P(PlantClosedLoop, SteadyStateErrorVanishesWithC1_17)
{
    for (std::int32_t kp : {100, 200}) {
        auto pOnly = positionLoop(kp, 0);
        const StepResponse p = stepResponse(*pOnly, 8.0);
        const int expected = -100 * 100 / kp;
        EXPECT_NEAR(p.finalLagError, expected, 2) << "C1.13 = " << kp << ", C1.17 = 0";
        EXPECT_NEAR(p.final, 5000 - expected, 2);

        auto pi = positionLoop(kp, 2000); // 2.000 V/s per V
        const StepResponse i = stepResponse(*pi, 8.0);
        EXPECT_LE(std::abs(i.finalLagError), 1) << "C1.13 = " << kp << ", C1.17 = 2000";
        EXPECT_NEAR(i.final, 5000, 1);
        EXPECT_NEAR(i.finalOutput, -100, 2) << "the I-portion holds the valve's null shift";
        EXPECT_NEAR(p.finalOutput, -100, 2);
    }
}

// C1.33 limits the I-portion's output (DMA V31 has no C1.33: the output range limits it).
TEST_P(PlantClosedLoop, IPortionLimitedByC1_33)
{
    auto rig = positionLoop(100, 4000);
    if (!findParam(rig->dict, "C1.33").valid())
        GTEST_SKIP() << GetParam() << " has no C1.33";
    rig->set("C1.33", 50); // 0.050 V, less than the 0.100 V the null shift needs
    const StepResponse r = stepResponse(*rig, 8.0);
    EXPECT_NEAR(rig->plant->controller().iPart(), -0.050, 1e-9);
    EXPECT_NEAR(r.finalLagError, -50, 2); // the P-portion supplies the rest
}

// d1.10 desired = d1.02 after the ramps, d1.12 = d1.10 − d1.11, d1.13 drives the valve chain
// (d1.03 = d1.13 with the linear curve).
TEST_P(PlantClosedLoop, DisplayValuesAreConsistent)
{
    auto rig = positionLoop(200, 1000);
    rig->set("A1.01", 4000);
    for (int i = 0; i < 300; ++i) {
        rig->run(0.005);
        EXPECT_EQ(rig->get("d1.10"), rig->get("d1.02"));
        EXPECT_NEAR(rig->get("d1.12"), rig->get("d1.10") - rig->get("d1.11"), 1);
        EXPECT_EQ(rig->get("d1.03"), rig->get("d1.13"));
    }
    EXPECT_NEAR(rig->get("d1.11"), 4000, 5);
}

// Remote loop controller (C1.00 = 2): d1.12 and d1.13 stay 0.000 V until Din_1 is set (DMA
// Profinet manual §4.5.1.3); meanwhile the set value drives the valve open loop.
TEST_P(PlantClosedLoop, RemoteControllerWaitsForDin)
{
    auto rig = positionLoop(200, 0);
    rig->set("C1.00", 2);
    rig->set("A1.01", 2000);
    rig->run(0.05);
    EXPECT_EQ(rig->get("d1.12"), 0);
    EXPECT_EQ(rig->get("d1.13"), 0);
    EXPECT_FALSE(rig->plant->loop().closed);
    EXPECT_GT(rig->get("d1.07"), 0); // open loop: 2 V to the valve
    rig->plant->setDin(true);
    rig->run(3.0);
    EXPECT_TRUE(rig->plant->loop().closed);
    EXPECT_NEAR(rig->get("d1.11"), 2050, 2);
}

// Mode 4: pressure in a volume with leakage is a first-order plant, so a P-only loop keeps
// e = w / (1 + Kp) (here (5 V − 0.1 V) / 3 with C1.13 = 2.00, the null shift helping); C1.17
// removes it (time constant (1 + Kp) / Ki = 0.75 s with C1.17 = 4.000).
TEST_P(PlantClosedLoop, PressureLoopNeedsTheIPortion)
{
    for (std::int32_t ki : {0, 4000}) {
        ClosedRig rig(GetParam(), std::make_unique<PressureAxis>());
        rig.set("C1.00", 1);
        rig.set("C1.09", 2); // 4 … 20 mA pressure transducer
        rig.set("C1.13", 200);
        rig.set("C1.17", ki);
        rig.set("A1.01", 5000);
        rig.run(8.0);
        if (ki == 0)
            EXPECT_NEAR(rig.get("d1.12"), (5000 - 100) / 3, 3);
        else
            EXPECT_LE(std::abs(rig.get("d1.12")), 1);
    }
}

INSTANTIATE_TEST_SUITE_P(PlantFamilies, PlantClosedLoop,
                         ::testing::Values("opat", "dma-pn-v51", "dma-pb-v32"),
                         [](const ::testing::TestParamInfo<std::string> &p) {
                             std::string name = p.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

// OPAT modes 6/8: branch 2 runs the same classes on the C2/d2/r2/A2 rows. The OPAT's C2.09 has
// only "0 = off (used for Profibus application)", so the PLC closes the loop: it writes the
// measured pressure to A2.02 every millisecond.
TEST(PlantClosedLoopBranch2, OpatSecondLoopUsesC2AndD2Rows)
{
    ClosedRig rig("opat", std::make_unique<PressureAxis>(), 2);
    rig.set("C2.13", 200);
    rig.set("C2.17", 4000);
    rig.set("A2.01", 6000);
    for (int ms = 0; ms < 8000; ++ms) {
        rig.set("A2.02",
                static_cast<std::int32_t>(std::lround(rig.plant->axis().measured() * 10000.0)));
        rig.clock.advance(1000);
    }
    EXPECT_EQ(rig.get("d2.10"), 6000);
    EXPECT_NEAR(rig.get("d2.11"), 6000, 2);
    EXPECT_LE(std::abs(rig.get("d2.12")), 2);
    EXPECT_EQ(rig.get("d1.10"), 0) << "branch 1 untouched";
    EXPECT_EQ(rig.get("d1.11"), 0);
}
