// Issue "Tuning workbench", tests: the Bode points the workbench measures over the bus on the
// built-in simulator match the plant's own response, computed from the plant model directly (the
// same commissioned DMA-2 module driven on its own SimClock, no bus, the set value written into
// the module every 0.5 ms step) within 1 dB and 10° inside the valid band.
#include "dict/dictionary_loader.h"
#include "model/tuning/run_analysis.h"
#include "model/tuning/test_run.h"
#include "sim/hcs_node.h"
#include "sim/sim_clock.h"
#include "sim/sim_device.h"
#include "sim_rig.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace vt::model {
namespace {

constexpr double kAmplitude = 0.5; // V around
constexpr double kOffset = 4.0;    // V
constexpr int kCycles = 2;
constexpr int kSettling = 2; // the bus test starts from wherever the axis is
const double kFrequencies[] = {2.0, 4.0};

// The plant alone: A1.01 follows the sine at every 0.5 ms step of the module's own clock, d1.11
// is sampled at the same steps; gain and phase by the analysis' own DFT.
FrequencyPoint plantResponse(double frequencyHz)
{
    dev::sim::SimClock clock;
    dev::sim::SimDeviceSpec spec;
    spec.family = "dma-pn-v51";
    spec.mode = 3;
    auto device = dev::sim::SimDevice::build(clock, *dev::builtinDictionaries(), spec);
    EXPECT_TRUE(device.ok());
    dev::sim::HcsModule &module = (*device)->node()->module(0);
    const dev::ParamMeta *setRow = module.storage().find("A1.01");
    const auto id = static_cast<std::uint16_t>(*setRow->id);
    const auto write = [&](double volts) {
        EXPECT_TRUE(module.write(id, static_cast<std::uint16_t>(std::lround(volts * 1000))).ok());
    };
    write(kOffset); // settle at the offset first, as the bus test starts from it
    clock.advance(3'000'000);
    Samples set, actual;
    const double duration = (kCycles + kSettling) / frequencyHz;
    constexpr std::int64_t kStepUs = 500;
    for (std::int64_t us = 0; us <= static_cast<std::int64_t>(duration * 1e6); us += kStepUs) {
        const double t = static_cast<double>(us) * 1e-6;
        const double v = kOffset + kAmplitude * std::sin(2 * std::numbers::pi * frequencyHz * t);
        write(v);
        set.t.push_back(t);
        set.y.push_back(std::round(v * 1000) / 1000.0);
        clock.advance(kStepUs);
        actual.t.push_back(t + kStepUs * 1e-6);
        actual.y.push_back(module.storage().get("d1.11") / 1000.0);
    }
    return frequencyPoint(set, actual, frequencyHz, kSettling / frequencyHz, kCycles, {2000, 2000});
}

TEST(WorkbenchOnTheSimulator, TheMeasuredBodeMatchesThePlantsOwnResponse)
{
    auto rig = test::connectSim({"dma-pn-v51", 1, {}, {}, {}});
    ASSERT_TRUE(rig);
    // The sine starts from its offset: the axis is sent there first; the settling cycles take
    // up the rest of the way.
    {
        std::optional<Outcome> done;
        rig->access().write(rig->module().address, rig->row("A1.01"), dev::RawValue{kOffset * 1000},
                            Priority::User, std::nullopt, [&](const Outcome &o) { done = o; });
        ASSERT_TRUE(test::waitFor(done));
    }
    SignalSpec s;
    s.kind = SignalKind::Sweep;
    s.amplitude = kAmplitude;
    s.offset = kOffset;
    s.fromHz = kFrequencies[0];
    s.toHz = kFrequencies[1];
    s.pointsPerDecade = 1; // 2 and 4 Hz
    s.cycles = kCycles;
    s.settlingCycles = kSettling;
    const auto signal = TestSignal::make(s);
    ASSERT_TRUE(signal);
    TestRunSetup setup = TestRun::setupFor(rig->module(), rig->row("A1.01"), *signal);
    TestRun run(rig->access(), setup);
    std::optional<TestOutcome> outcome;
    QObject::connect(&run, &TestRun::finished, &run, [&](const TestOutcome &o) { outcome = o; });
    run.start();
    ASSERT_TRUE(test::waitFor(outcome, 30'000));
    ASSERT_EQ(outcome->end, TestEnd::Finished) << outcome->reason.toStdString();
    const RunAnalysis measured =
        analyseRun(*signal, run.recording(), setup.actualRow, setup.setValueRow);
    ASSERT_FALSE(measured.points.empty());
    int compared = 0;
    for (const FrequencyPoint &m : measured.points) {
        if (!m.valid)
            continue;
        const FrequencyPoint plant = plantResponse(m.frequencyHz);
        ASSERT_TRUE(plant.valid) << m.frequencyHz << " Hz";
        EXPECT_NEAR(m.gainDb, plant.gainDb, 1.0) << m.frequencyHz << " Hz";
        double dPhase = m.phaseDeg - plant.phaseDeg;
        dPhase -= 360.0 * std::round(dPhase / 360.0);
        EXPECT_LE(std::abs(dPhase), 10.0)
            << m.frequencyHz << " Hz: bus " << m.phaseDeg << "°, plant " << plant.phaseDeg << "°";
        ++compared;
    }
    EXPECT_GE(compared, 2);
}

} // namespace
} // namespace vt::model
