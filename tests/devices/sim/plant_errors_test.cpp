// Errors the plant detects and the numbers the modules report for them: DMA Profinet manual
// §4.5.1.1 (DMA Profibus Anleitung §4.5.1.1 "Fehlernummern"), OPAT manual §7 ERR: "error
// detection (cable fracture when enabled)".
#include "plant_test_support.h"

#include <algorithm>

using namespace vt::dev::sim;
using namespace vt::dev::sim::test;

TEST(PlantErrorNumbers, FollowTheManualsTables)
{
    // DMA: 2/4 wire break S1.06/S1.05 (< 2 mA), 5/6 over current (> 25 mA), 3 short circuit
    // (peak > 8 A), 8 current deviation (> 250 mA for ~100 ms).
    EXPECT_EQ(errorNumber(PlantError::SetValueWireBreak, ErrorTable::Dma), 2);
    EXPECT_EQ(errorNumber(PlantError::SetValueWireBreak2, ErrorTable::Dma), 4);
    EXPECT_EQ(errorNumber(PlantError::SetValueOverCurrent, ErrorTable::Dma), 5);
    EXPECT_EQ(errorNumber(PlantError::SetValueOverCurrent2, ErrorTable::Dma), 6);
    EXPECT_EQ(errorNumber(PlantError::OutputShortCircuit, ErrorTable::Dma), 3);
    EXPECT_EQ(errorNumber(PlantError::OutputCurrentDeviation, ErrorTable::Dma), 8);
    // OPAT ERR: 2/4 wire break sensor 1/2, 5/6 overload > 22 mA sensor 1/2, 8 output stages,
    // 9 wire break on set value; no set value over current entry.
    EXPECT_EQ(errorNumber(PlantError::FeedbackCableFracture, ErrorTable::Opat, 1), 2);
    EXPECT_EQ(errorNumber(PlantError::FeedbackCableFracture, ErrorTable::Opat, 2), 4);
    EXPECT_EQ(errorNumber(PlantError::FeedbackOverload, ErrorTable::Opat, 1), 5);
    EXPECT_EQ(errorNumber(PlantError::FeedbackOverload, ErrorTable::Opat, 2), 6);
    EXPECT_EQ(errorNumber(PlantError::SetValueWireBreak, ErrorTable::Opat), 9);
    EXPECT_EQ(errorNumber(PlantError::OutputCurrentDeviation, ErrorTable::Opat), 8);
    EXPECT_EQ(errorNumber(PlantError::SetValueOverCurrent, ErrorTable::Opat), std::nullopt);

    PlantErrors several;
    several.set(PlantError::OutputCurrentDeviation);
    several.set(PlantError::OutputShortCircuit);
    EXPECT_EQ(several.reportedNumber(ErrorTable::Dma), 3);
    EXPECT_EQ(several.text(), "output-short-circuit, output-current-deviation");
}

TEST(PlantErrorNumbers, TableFollowsTheFamily)
{
    EXPECT_EQ(errorTableFor(family("opat")), ErrorTable::Opat);
    EXPECT_EQ(errorTableFor(family("dma-pn-v51")), ErrorTable::Dma);
    EXPECT_EQ(errorTableFor(family("dma-pb-v15")), ErrorTable::Dma);
}

namespace {

class PlantFeedbackFracture : public ::testing::TestWithParam<std::string>
{
};

std::unique_ptr<ClosedRig> fractureRig(const std::string &name, std::int32_t c126)
{
    auto rig = std::make_unique<ClosedRig>(name);
    rig->set("C1.00", 1);
    rig->set("C1.09", 2); // 4 … 20 mA: a live zero, so a broken cable is visible
    rig->set("C1.26", c126);
    rig->set("A1.01", 5000);
    rig->run(2.0);
    return rig;
}

} // namespace

// C1.26 = 1: a broken feedback cable (0 mA on a 4 … 20 mA sensor) trips the module, the outputs
// switch off (DMA Profinet manual §4.5.1.1: "the outputs will be disabled"), and only an
// acknowledge after the repair clears it.
TEST_P(PlantFeedbackFracture, DetectedWhenC1_26IsOn)
{
    auto rig = fractureRig(GetParam(), 1);
    ASSERT_FALSE(rig->plant->errors().tripped());
    ASSERT_NEAR(rig->get("d1.11"), 5100, 3); // P only: the null shift holds 0.1 V
    rig->plant->setSensorFault(SensorFault::WireBreak);
    rig->run(0.001);
    const ErrorLatch &errors = rig->plant->errors();
    EXPECT_TRUE(errors.latched().test(PlantError::FeedbackCableFracture));
    const int expected =
        GetParam() == "opat" ? 2 : 1; // OPAT ERR 2; DMA: no entry, "Error of operation"
    EXPECT_EQ(errors.latched().reportedNumber(rig->plant->errorTable()), expected);
    rig->run(0.1);
    EXPECT_EQ(rig->get("d1.07") + rig->get("d1.08"), 0) << "outputs off";
    EXPECT_EQ(rig->get("d1.13"), 0);

    EXPECT_FALSE(rig->plant->acknowledgeErrors()) << "the cable is still broken";
    rig->plant->setSensorFault(SensorFault::None);
    rig->run(0.001);
    EXPECT_TRUE(rig->plant->acknowledgeErrors());
    rig->run(3.0);
    EXPECT_FALSE(rig->plant->errors().tripped());
    EXPECT_NEAR(rig->get("d1.11"), 5100, 3) << "back in control";
}

// C1.26 = 0: nothing is detected; the card reads 0 mA as −2.5 V and the loop drives the axis
// into its end stop, as a real axis with a broken cable would.
TEST_P(PlantFeedbackFracture, NotDetectedWhenC1_26IsOff)
{
    auto rig = fractureRig(GetParam(), 0);
    rig->plant->setSensorFault(SensorFault::WireBreak);
    rig->run(1.0);
    EXPECT_FALSE(rig->plant->errors().tripped());
    EXPECT_EQ(rig->get("d1.11"), -2500);
    EXPECT_DOUBLE_EQ(rig->plant->axis().measured(), 1.0);
}

// A 0 … 10 V sensor has no live zero: 0 V is a valid position, so C1.26 cannot see the break.
TEST_P(PlantFeedbackFracture, NeedsALiveZero)
{
    auto rig = std::make_unique<ClosedRig>(GetParam());
    rig->set("C1.00", 1);
    rig->set("C1.09", 4);
    rig->set("C1.26", 1);
    rig->plant->setSensorFault(SensorFault::WireBreak);
    rig->run(0.1);
    EXPECT_FALSE(rig->plant->errors().tripped());
}

INSTANTIATE_TEST_SUITE_P(PlantFamilies, PlantFeedbackFracture,
                         ::testing::Values("opat", "dma-pn-v51", "dma-pb-v32"),
                         [](const ::testing::TestParamInfo<std::string> &p) {
                             std::string name = p.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

// OPAT C1.26 = 2: "cable fracture detection on, only in closed loop".
TEST(PlantFeedbackFractureOpat, OnlyInClosedLoopWithC1_26Two)
{
    auto rig = fractureRig("opat", 2);
    rig->set("C1.00", 0); // open loop
    rig->plant->setSensorFault(SensorFault::WireBreak);
    rig->run(0.1);
    EXPECT_FALSE(rig->plant->errors().tripped());
    rig->set("C1.00", 1);
    rig->run(0.001);
    EXPECT_TRUE(rig->plant->errors().latched().test(PlantError::FeedbackCableFracture));
}

// OPAT ERR 5: "Overload of current > 22 mA sensor 1".
TEST(PlantFeedbackFractureOpat, OverloadedCurrentSensor)
{
    auto rig = fractureRig("opat", 0);
    rig->plant->setSensorFault(SensorFault::Overload);
    rig->run(0.001);
    EXPECT_EQ(rig->plant->errors().latched().reportedNumber(ErrorTable::Opat), 5);
}

namespace {

class PlantSetValueErrors : public ::testing::TestWithParam<std::string>
{
};

} // namespace

// E15 = 4 "4 … 20 mA with cable fracture detection": below 2 mA is a wire break (DMA error 2,
// OPAT ERR 9); E15 = 3 is the same input without detection.
TEST_P(PlantSetValueErrors, CurrentSetValueWireBreak)
{
    for (std::int32_t e15 : {3, 4}) {
        OpenRig rig(GetParam());
        rig.set("E15", e15);
        rig.plant->setAnalogueInput(AnalogueInput::S1_06, 12.0);
        rig.run(0.1);
        EXPECT_EQ(rig.get("d1.01"), 5000);
        EXPECT_FALSE(rig.plant->errors().tripped());
        rig.plant->setAnalogueInput(AnalogueInput::S1_06, 1.9);
        rig.run(0.001);
        if (e15 == 3) {
            EXPECT_FALSE(rig.plant->errors().tripped());
            continue;
        }
        EXPECT_TRUE(rig.plant->errors().latched().test(PlantError::SetValueWireBreak));
        EXPECT_EQ(rig.plant->errors().latched().reportedNumber(rig.plant->errorTable()),
                  GetParam() == "opat" ? 9 : 2);
        rig.run(0.1);
        EXPECT_EQ(rig.get("d1.07"), 0);
    }
}

// DMA error 5: "Over current at set point S1.06 (current signal >25mA)".
TEST_P(PlantSetValueErrors, CurrentSetValueOverCurrent)
{
    OpenRig rig(GetParam());
    rig.set("E15", 6); // 12 mA ± 8 mA with cable fracture detection
    rig.plant->setAnalogueInput(AnalogueInput::S1_06, 26.0);
    rig.run(0.001);
    EXPECT_TRUE(rig.plant->errors().latched().test(PlantError::SetValueOverCurrent));
}

// E17 = 2 switches the analogue inputs off, and with them their monitoring.
TEST_P(PlantSetValueErrors, IgnoredWhenOnlyDigitalSetValuesAreActive)
{
    OpenRig rig(GetParam());
    rig.set("E15", 4);
    rig.set("E17", 2);
    rig.run(0.1);
    EXPECT_FALSE(rig.plant->errors().tripped());
}

// DMA error 8: "The difference between the desired current and the actual current is outside of
// the defined range. Conditions for error triggering: IError > 250 mA for tError approx. 100 ms."
TEST_P(PlantSetValueErrors, OpenSolenoidTripsAfter100ms)
{
    OpenRig rig(GetParam());
    rig.set("A1.01", 8000); // 80 % of the rated current, above 250 mA for every default solenoid
    rig.run(0.1);
    rig.plant->setSolenoidFault(false, SolenoidFault::OpenCircuit);
    rig.run(0.095);
    EXPECT_FALSE(rig.plant->errors().tripped()) << "not before ~100 ms";
    rig.run(0.010);
    EXPECT_TRUE(rig.plant->errors().latched().test(PlantError::OutputCurrentDeviation));
    EXPECT_EQ(rig.plant->errors().latched().reportedNumber(rig.plant->errorTable()), 8);
}

// DMA error 3: "Excess current or short circuit at the output stages (peak current >8A!)".
TEST_P(PlantSetValueErrors, ShortedSolenoid)
{
    OpenRig rig(GetParam());
    rig.set("A1.01", -3000);
    rig.run(0.05);
    rig.plant->setSolenoidFault(true, SolenoidFault::ShortCircuit);
    rig.run(0.005);
    EXPECT_TRUE(rig.plant->errors().latched().test(PlantError::OutputShortCircuit));
    EXPECT_EQ(rig.plant->errors().latched().reportedNumber(rig.plant->errorTable()),
              GetParam() == "opat" ? 8 : 3);
}

INSTANTIATE_TEST_SUITE_P(PlantFamilies, PlantSetValueErrors,
                         ::testing::Values("opat", "dma-pn-v13", "dma-pb-v15"),
                         [](const ::testing::TestParamInfo<std::string> &p) {
                             std::string name = p.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });
