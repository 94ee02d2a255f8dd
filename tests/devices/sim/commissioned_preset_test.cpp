// The commissioned preset (docs/SIMULATOR.md "Commissioned preset"): every value it writes is
// valid for the row on every family, version and mode; a simulator built as valvetune and
// valvetune-sim build it answers a bus set-value step with a moving actual value — position and
// pressure loops follow A1.01, open-loop solenoids carry a current proportional to it — and
// `--factory` (SimDeviceSpec::factory) leaves the dictionary defaults, under which a position
// loop's d1.11 stays at 0.
#include "dict/cooking.h"
#include "dict/dictionary_loader.h"
#include "hcs_sim_support.h"
#include "sim/commissioned_preset.h"
#include "sim/hcs_node.h"
#include "sim/node_config.h"
#include "sim/param_io.h"
#include "sim/sim_clock.h"
#include "sim/sim_device.h"

#include <cmath>
#include <gtest/gtest.h>
#include <set>

using namespace vt::dev;
using namespace vt::dev::sim;
using namespace vt::dev::sim::test;

namespace {

constexpr std::int64_t kSecondUs = 1'000'000;

std::unique_ptr<SimDevice> simulator(SimClock &clock, const std::string &family, int mode,
                                     bool factory)
{
    SimDeviceSpec spec;
    spec.family = family;
    spec.mode = mode;
    spec.factory = factory;
    auto device = SimDevice::build(clock, *builtinDictionaries(), spec);
    if (!device.ok()) {
        ADD_FAILURE() << family << " mode " << mode << ": " << device.error().message;
        return nullptr;
    }
    return std::move(device).value();
}

// A bus write as CMD 6 / FC 6 carries it.
void busWrite(HcsModule &module, const std::string &name, std::int32_t raw)
{
    const ParamMeta *row = module.storage().find(name);
    ASSERT_NE(row, nullptr) << name;
    ASSERT_TRUE(
        module.write(static_cast<std::uint16_t>(*row->id), static_cast<std::uint16_t>(raw)).ok())
        << name << " = " << raw;
}

std::int32_t get(const HcsModule &module, int branch, std::string_view name)
{
    return module.storage().get(branchName(name, branch));
}

// Solenoid A's measured current of the branch, mA. Branch 1 shows it as d1.07; the dictionaries
// have no d2.07, so branch 2's is read from its plant.
double solenoidA(HcsModule &module, int branch)
{
    const ValveChainValues &valve = module.openLoop(branch) ? module.openLoop(branch)->valve()
                                                            : module.closedLoop(branch)->valve();
    if (branch == 1) {
        EXPECT_NEAR(module.storage().get("d1.07"), valve.currentA * 1000.0, 1.0);
    }
    return valve.currentA * 1000.0;
}

// Every simulated family with each of its modes, as the simulator builds them (newest version).
std::vector<std::pair<std::string, int>> simulatedModes()
{
    std::vector<std::pair<std::string, int>> out;
    for (const std::string &family : simulatedFamilies(*builtinDictionaries()))
        for (const std::string &mode : builtinDictionaries()->find(family)->modes)
            out.emplace_back(family, std::stoi(mode));
    return out;
}

std::string label(const std::string &family, int mode, int branch)
{
    return family + " mode " + std::to_string(mode) + " branch " + std::to_string(branch);
}

} // namespace

// Every preset value lies inside its row's range (the dictionary's own write check) on every
// family, version and mode; every loop branch gets its whole set of loop entries; no table entry
// is dead.
TEST(CommissionedPreset, EveryValueIsValidForEveryFamilyVersionAndMode)
{
    std::set<std::pair<PresetScope, std::string_view>> used;
    for (const Variant &v : allVariants()) {
        SimClock clock;
        HcsModule module(clock, configFor(v));
        const std::vector<PresetWrite> writes = commissionedValues(module);
        for (const PresetWrite &w : writes) {
            const ParamMeta *row = module.storage().find(w.name);
            ASSERT_NE(row, nullptr) << v.name() << " " << w.name;
            const auto problem = checkWrite(*row, w.raw);
            EXPECT_FALSE(problem.has_value()) << v.name() << ": " << w.name << " = " << w.raw;
        }
        const auto written = [&](const std::string &name) {
            return std::any_of(writes.begin(), writes.end(),
                               [&](const PresetWrite &w) { return w.name == name; });
        };
        for (const PresetEntry &entry : commissionedPreset()) {
            if (entry.scope == PresetScope::Module) {
                if (written(std::string(entry.name)))
                    used.emplace(entry.scope, entry.name);
                continue;
            }
            for (const auto &[branch, role] : branchRoles(module)) {
                const bool loop =
                    role == BranchRole::PositionLoop || role == BranchRole::PressureLoop;
                const bool wanted =
                    (entry.scope == PresetScope::Loop && loop) ||
                    (entry.scope == PresetScope::PositionLoop &&
                     role == BranchRole::PositionLoop) ||
                    (entry.scope == PresetScope::PressureLoop && role == BranchRole::PressureLoop);
                if (!wanted)
                    continue;
                EXPECT_TRUE(written(branchName(entry.name, branch)))
                    << v.name() << " branch " << branch << " lacks " << entry.name;
                used.emplace(entry.scope, entry.name);
            }
        }
    }
    for (const PresetEntry &entry : commissionedPreset())
        EXPECT_TRUE(used.count({entry.scope, entry.name})) << entry.name << " applies nowhere";
}

// The roles follow the plants: open loop in modes 1/2, position and pressure as the axis, and the
// OPAT's second loop, whose C2.09 offers only "off", closed by the PLC through A2.02.
TEST(CommissionedPreset, BranchRolesFollowTheMode)
{
    const auto roles = [](const std::string &family, int mode) {
        SimClock clock;
        const Variant v{family, family == "opat" ? "34" : dictionary(family).versions.back(), mode};
        HcsModule module(clock, configFor(v));
        std::vector<BranchRole> out;
        for (const auto &[branch, role] : branchRoles(module))
            out.push_back(role);
        return out;
    };
    using R = BranchRole;
    EXPECT_EQ(roles("dma-pn-v13", 1), (std::vector{R::OpenLoop}));
    EXPECT_EQ(roles("dma-pb-v22", 2), (std::vector{R::OpenLoop, R::OpenLoop}));
    EXPECT_EQ(roles("dma-pn-v51", 3), (std::vector{R::PositionLoop}));
    EXPECT_EQ(roles("dma-pn-v51", 4), (std::vector{R::PressureLoop}));
    EXPECT_EQ(roles("dma-pb-v32", 6), (std::vector{R::PositionLoop, R::PressureLoop}));
    EXPECT_EQ(roles("dma-pb-v32", 8), (std::vector{R::PressureLoop, R::PressureLoop}));
    EXPECT_EQ(roles("opat", 6), (std::vector{R::PositionLoop, R::BusFeedback}));
    EXPECT_EQ(roles("opat", 8), (std::vector{R::PressureLoop, R::BusFeedback}));
}

// A bus step of the set value on a commissioned simulator moves what the monitor shows, on every
// family and mode: the loops' d1.11 reaches the set value, the open-loop solenoid current is
// proportional to it, the OPAT's bus-fed second loop drives its pressure up.
TEST(CommissionedPreset, BusStepMovesTheActualValueOnEveryFamilyAndMode)
{
    for (const auto &[family, mode] : simulatedModes()) {
        SimClock clock;
        auto device = simulator(clock, family, mode, false);
        ASSERT_TRUE(device);
        HcsModule &module = device->node()->module(0);
        EXPECT_EQ(module.storage().get("E17"), 2) << family << ": bus set values only";
        for (const auto &[branch, role] : branchRoles(module)) {
            const std::string what = label(family, mode, branch);
            const std::string setValue = branchName("A1.01", branch);
            switch (role) {
            case BranchRole::PositionLoop:
            case BranchRole::PressureLoop: {
                clock.advance(kSecondUs);
                EXPECT_NEAR(get(module, branch, "d1.11"), 0, 60) << what << " at rest";
                busWrite(module, setValue, 5000); // 5.000 V
                clock.advance((role == BranchRole::PositionLoop ? 4 : 6) * kSecondUs);
                EXPECT_NEAR(get(module, branch, "d1.11"), 5000, 100) << what << " follows";
                EXPECT_FALSE(module.tripped()) << what;
                break;
            }
            case BranchRole::BusFeedback: {
                ClosedLoopPlant *plant = module.closedLoop(branch);
                busWrite(module, setValue, 5000);
                clock.advance(2 * kSecondUs);
                EXPECT_GT(solenoidA(module, branch), 0) << what << ": solenoid A energised";
                EXPECT_GT(plant->axis().measured(), 0.2) << what << ": the pressure rises";
                break;
            }
            case BranchRole::OpenLoop: {
                busWrite(module, setValue, 2500);
                clock.advance(kSecondUs / 5);
                const double half = solenoidA(module, branch);
                busWrite(module, setValue, 5000);
                clock.advance(kSecondUs / 5);
                const double full = solenoidA(module, branch);
                EXPECT_GT(half, 0) << what << ": solenoid A carries a current";
                EXPECT_NEAR(full / half, 2.0, 0.05) << what << ": current ∝ set value";
                break;
            }
            }
            busWrite(module, setValue, 0);
        }
    }
}

// The node scripts/run starts (`--simulate dma-pn-v51:3`): every module of the node is
// commissioned, not just the first.
TEST(CommissionedPreset, EveryModuleOfTheNodeIsCommissioned)
{
    SimClock clock;
    SimDeviceSpec spec;
    spec.family = "dma-pn-v51";
    spec.modules = 3;
    auto device = SimDevice::build(clock, *builtinDictionaries(), spec);
    ASSERT_TRUE(device.ok());
    HcsNode &node = *(*device)->node();
    ASSERT_EQ(node.moduleCount(), 3u);
    for (std::size_t i = 0; i < node.moduleCount(); ++i) {
        HcsModule &module = node.module(i);
        busWrite(module, "A1.01", 4000);
        clock.advance(4 * kSecondUs);
        EXPECT_NEAR(module.storage().get("d1.11"), 4000, 100) << "module " << i + 1;
    }
}

// The preset is the machine's stored setting: it survives a power cycle.
TEST(CommissionedPreset, SurvivesAPowerCycle)
{
    SimClock clock;
    auto device = simulator(clock, "dma-pn-v51", 3, false);
    ASSERT_TRUE(device);
    HcsModule &module = device->node()->module(0);
    module.setPowered(false);
    module.setPowered(true);
    for (const PresetWrite &w : commissionedValues(module))
        EXPECT_EQ(module.storage().get(w.name), w.raw) << w.name;
}

// `--factory`: every readable row reads its dictionary default, as on a module fresh from the
// factory; the position loop takes its feedback from the bus (C1.09 = 0), so d1.11 stays at 0
// after a step — the state the preset exists to avoid.
TEST(CommissionedPreset, FactoryStartsFromTheDictionaryDefaults)
{
    for (const auto &[family, mode] : simulatedModes()) {
        SimClock clock;
        auto device = simulator(clock, family, mode, true);
        ASSERT_TRUE(device);
        HcsModule &module = device->node()->module(0);
        for (const ParamMeta *row : readableRows(module)) {
            if (row->block == "d")
                continue; // the plant's display values
            EXPECT_EQ(module.storage().word(*row->id), expectedFreshWord(*row, module))
                << family << " mode " << mode << " " << row->name;
        }
        if (mode == 3) {
            busWrite(module, "A1.01", 5000);
            clock.advance(2 * kSecondUs);
            EXPECT_EQ(module.storage().get("d1.11"), 0) << family << ": feedback from the bus";
        }
    }
}
