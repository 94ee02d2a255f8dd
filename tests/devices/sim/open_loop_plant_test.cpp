// Open loop plant ("open loop: currents follow E03/E1.03 solenoid
// selection and C1.07 dead band"; ramps r1.01..r1.04 "1 == 10 ms", E08). Families: mode 1 DMA
// PROFINET V13, DMA PROFIBUS V15, and the OPAT's open loop path.
#include "plant_test_support.h"

#include <algorithm>
#include <cmath>
#include <map>

using namespace vt::dev::sim;
using namespace vt::dev::sim::test;

namespace {

struct OpenFamily
{
    std::string family;
    std::string solenoidA;                // the family's name of "Solenoid selection A"
    std::map<int, double> ratedA, ratedB; // from the manuals' tables, amperes
};

std::ostream &operator<<(std::ostream &os, const OpenFamily &f)
{
    return os << f.family;
}

const std::map<int, double> kDma{{1, 0.8}, {2, 1.1}, {3, 1.3}, {4, 1.6},
                                 {5, 2.4}, {6, 2.7}, {7, 3.5}};

class PlantOpenLoop : public ::testing::TestWithParam<OpenFamily>
{
};

// mA as d1.07/d1.08 show them (1000 == 1.000 A).
int mA(double amps)
{
    return static_cast<int>(std::lround(amps * 1000.0));
}

} // namespace

// DMA Profinet manual §6 ID 0x62 / OPAT manual §7 ID 0x62: the selection sets the rated current;
// the set value scales it (9.999 V = max. current).
TEST_P(PlantOpenLoop, CurrentsFollowSolenoidSelection)
{
    const OpenFamily &f = GetParam();
    for (const auto &[selection, amps] : f.ratedA) {
        OpenRig rig(f.family);
        rig.set(f.solenoidA, selection);
        rig.set("A1.01", 5000); // 5.000 V = half of full scale
        rig.run(0.1);           // 33 current time constants
        EXPECT_NEAR(rig.get("d1.07"), mA(amps / 2.0), 1) << f.family << " selection " << selection;
        EXPECT_EQ(rig.get("d1.08"), 0);
        EXPECT_EQ(rig.get("d1.09"), rig.get("d1.07"));
    }
    for (const auto &[selection, amps] : f.ratedB) {
        OpenRig rig(f.family);
        rig.set("E2.03", selection);
        rig.set("A1.01", -2500);
        rig.run(0.1);
        EXPECT_NEAR(rig.get("d1.08"), mA(amps / 4.0), 1)
            << f.family << " B selection " << selection;
        EXPECT_EQ(rig.get("d1.07"), 0);
        EXPECT_EQ(rig.get("d1.05"), 0);
        EXPECT_EQ(rig.get("d1.06"), 2500);
    }
}

// C1.07/C1.08: "9.999 V = max. current depending on solenoid selection": the current jumps to
// the compensation as soon as the set value leaves zero; full scale stays full scale.
TEST_P(PlantOpenLoop, DeadBandShiftsCurrentOnset)
{
    const OpenFamily &f = GetParam();
    const double rated = f.ratedA.at(6);
    auto currentAt = [&](std::int32_t setValue, std::int32_t deadBand, const char *deadBandName,
                         const char *current) {
        OpenRig rig(f.family);
        rig.set(deadBandName, deadBand);
        rig.set("A1.01", setValue);
        rig.run(0.1);
        return rig.get(current);
    };
    // At rest nothing flows, with or without compensation.
    EXPECT_EQ(currentAt(0, 0, "C1.07", "d1.07"), 0);
    EXPECT_EQ(currentAt(0, 2000, "C1.07", "d1.07"), 0);
    // 0.100 V: 1 % of the rated current without, 20.8 % with 2.000 V compensation.
    EXPECT_NEAR(currentAt(100, 0, "C1.07", "d1.07"), mA(rated * 0.010), 1);
    EXPECT_NEAR(currentAt(100, 2000, "C1.07", "d1.07"), mA(rated * 0.208), 1);
    // The onset moved, the end did not.
    EXPECT_NEAR(currentAt(9999, 2000, "C1.07", "d1.07"), currentAt(9999, 0, "C1.07", "d1.07"), 1);
    // C1.08 does the same for solenoid B and leaves A alone.
    const double ratedB = f.ratedB.at(6);
    EXPECT_NEAR(currentAt(-100, 3000, "C1.08", "d1.08"), mA(ratedB * 0.307), 1);
    EXPECT_EQ(currentAt(100, 3000, "C1.08", "d1.08"), 0);
    EXPECT_NEAR(currentAt(100, 3000, "C1.08", "d1.07"), mA(rated * 0.010), 1);
}

// r1.03 = 100 (1 == 10 ms: 1.00 s). E08 = 1 "rise constant": 1 s per 10 V, so 0 -> 5 V in 0.5 s.
// E08 = 0 "time constant": every change takes the whole 1 s.
TEST_P(PlantOpenLoop, RampsTakeTheDocumentedTime)
{
    const OpenFamily &f = GetParam();
    for (int e08 : {1, 0}) {
        OpenRig rig(f.family);
        rig.set("E08", e08);
        rig.set("r1.03", 100);
        rig.set("r1.04", 50);
        rig.set("A1.01", 5000);
        const double upTime = e08 == 1 ? 0.5 : 1.0;
        rig.run(upTime / 2);
        EXPECT_NEAR(rig.get("d1.02"), 2500, 2) << "E08 = " << e08;
        EXPECT_EQ(rig.get("d1.01"), 5000); // the sum is ahead of the ramp
        rig.run(upTime / 2 - 0.001);
        EXPECT_LT(rig.get("d1.02"), 5000);
        rig.run(0.001);
        EXPECT_EQ(rig.get("d1.02"), 5000);
        // Down with r1.04 = 0.50 s: rise constant 10 V per 0.5 s -> 0.25 s; time constant 0.5 s.
        rig.set("A1.01", 0);
        const double downTime = e08 == 1 ? 0.25 : 0.5;
        rig.run(downTime / 2);
        EXPECT_NEAR(rig.get("d1.02"), 2500, 2) << "E08 = " << e08;
        rig.run(downTime / 2);
        EXPECT_EQ(rig.get("d1.02"), 0);
    }
}

// A change across zero uses +⇒0 (r1.04), then 0⇒− (r1.01); 0 == ramp function off.
TEST_P(PlantOpenLoop, RampAcrossZeroUsesBothQuadrants)
{
    OpenRig rig(GetParam().family);
    rig.set("E08", 1);
    rig.set("A1.01", 4000);
    rig.run(0.01); // no ramp times yet: passes at once
    EXPECT_EQ(rig.get("d1.02"), 4000);
    rig.set("r1.04", 200); // 2 s per 10 V: 4 V -> 0 in 0.8 s
    rig.set("r1.01", 100); // 1 s per 10 V: 0 -> -4 V in 0.4 s
    rig.set("A1.01", -4000);
    rig.run(0.4);
    EXPECT_NEAR(rig.get("d1.02"), 2000, 2);
    rig.run(0.4);
    EXPECT_NEAR(rig.get("d1.02"), 0, 2);
    rig.run(0.2);
    EXPECT_NEAR(rig.get("d1.02"), -2000, 2);
    rig.run(0.2);
    EXPECT_EQ(rig.get("d1.02"), -4000);
    EXPECT_GT(rig.get("d1.08"), 0);
    EXPECT_EQ(rig.get("d1.07"), 0);
}

// Every d-value along the chain: d1.01 sum, d1.02 after the ramps, d1.03 after the (identity)
// linearisation, d1.04 after C1.05 sign/gain, C1.06 offset and gain A/B, d1.05/d1.06 signals.
TEST_P(PlantOpenLoop, ChainValuesAreConsistent)
{
    OpenRig rig(GetParam().family);
    rig.set("A1.01", 3000);
    rig.set("C1.05", -200); // sign and gain: inverts and doubles
    rig.set("C1.06", 500);  // +0.5 V
    rig.set("C1.04", 50);   // gain B 0.50
    rig.run(0.1);
    EXPECT_EQ(rig.get("d1.01"), 3000);
    EXPECT_EQ(rig.get("d1.02"), 3000);
    EXPECT_EQ(rig.get("d1.03"), 3000);
    EXPECT_EQ(rig.get("d1.04"), -2750); // (-2 × 3 V + 0.5 V) × 0.5
    EXPECT_EQ(rig.get("d1.05"), 0);
    EXPECT_EQ(rig.get("d1.06"), 2750);
    EXPECT_EQ(rig.get("d1.07"), 0);
    EXPECT_NEAR(rig.get("d1.08"), mA(GetParam().ratedB.at(6) * 0.275), 1);
}

// The analogue input S1.06 adds to the bus set value unless E17 = 2 ("only digital").
TEST_P(PlantOpenLoop, AnalogueInputCountsUnlessE17SaysDigitalOnly)
{
    OpenRig rig(GetParam().family);
    rig.set("A1.01", 1000);
    rig.set("E15", 3); // 4 … 20 mA without cable fracture detection
    rig.plant->setAnalogueInput(AnalogueInput::S1_06, 12.0); // 12 mA = 5.000 V
    rig.run(0.01);
    EXPECT_EQ(rig.get("d1.01"), 6000);
    rig.set("E17", 2);
    rig.run(0.01);
    EXPECT_EQ(rig.get("d1.01"), 1000);
}

// Display values are zero while the enable signal is not applied (OPAT manual §7, d block).
TEST_P(PlantOpenLoop, DisabledOutputsCarryNoCurrent)
{
    OpenRig rig(GetParam().family);
    rig.set("A1.01", 5000);
    rig.run(0.1);
    ASSERT_GT(rig.get("d1.07"), 0);
    rig.plant->setEnabled(false);
    rig.run(0.1);
    EXPECT_EQ(rig.get("d1.07"), 0);
    EXPECT_EQ(rig.get("d1.02"), 0);
    EXPECT_EQ(rig.get("d1.01"), 5000);
}

// E1.13/E13 dither amplitude ("3.000 V = 30 % of max. rated current") at E1.14/E14 Hz rides on
// the current; the mean stays where the set value puts it.
TEST_P(PlantOpenLoop, DitherRidesOnTheCurrent)
{
    const OpenFamily &f = GetParam();
    OpenRig rig(f.family);
    const bool opat = f.solenoidA == "E03";
    rig.set(opat ? "E13" : "E1.13", 1000); // 10 % of rated
    rig.set(opat ? "E14" : "E1.14", 50);   // 50 Hz: 20 ms period
    rig.set("A1.01", 5000);
    rig.run(0.1);
    const double rated = f.ratedA.at(6);
    int low = 1 << 30, high = 0;
    double sum = 0;
    for (int i = 0; i < 40; ++i) { // two periods at 0.5 ms
        rig.clock.advance(500);
        const int value = rig.get("d1.07");
        low = std::min(low, value);
        high = std::max(high, value);
        sum += value;
    }
    EXPECT_NEAR(high - low, mA(rated * 0.2), mA(rated * 0.01));
    EXPECT_NEAR(sum / 40.0, mA(rated * 0.5), 2);
}

INSTANTIATE_TEST_SUITE_P(
    PlantFamilies, PlantOpenLoop,
    ::testing::Values(
        OpenFamily{"dma-pn-v13", "E1.03", kDma, kDma},
        OpenFamily{"dma-pb-v15", "E1.03", kDma, kDma},
        OpenFamily{
            "opat",
            "E03",
            {{1, 0.150}, {2, 0.150}, {3, 0.150}, {4, 0.240}, {5, 0.500}, {6, 0.630}, {7, 0.800}},
            {{1, 0.315}, {2, 0.315}, {3, 0.350}, {4, 0.400}, {5, 0.500}, {6, 0.630}, {7, 0.800}}}),
    [](const ::testing::TestParamInfo<OpenFamily> &p) {
        std::string name = p.param.family;
        std::replace(name.begin(), name.end(), '-', '_');
        return name;
    });
