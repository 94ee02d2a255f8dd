// The commissioned preset: the parameter values a simulated HCS module starts with on top of its
// dictionary defaults, so the built-in simulator and valvetune-sim behave as a machine that has
// been commissioned on a PLC — a position loop with its sensor, a pressure loop with its
// transducer, bus set values only — instead of a module fresh from the factory, whose closed loop
// takes its feedback from the bus (C1.09 = 0) and shows nothing to tune. The values are data, by
// dictionary row name, in one table (commissioned_preset.cpp); docs/SIMULATOR.md "Commissioned
// preset" says what each one is for. `--factory` skips the preset.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vt::dev::sim {

class HcsModule;

// What a branch of a module does with its valve, by mode (HcsModule::buildPlants,
// makeAxisForMode), and whether its feedback can be wired to the card.
enum class BranchRole {
    OpenLoop,     // modes 1, 2: the set value drives the solenoids
    PositionLoop, // mode 3, branch 1 of mode 6: a cylinder with a position sensor
    PressureLoop, // mode 4, both branches of mode 8, branch 2 of mode 6: a pressure transducer
    BusFeedback,  // a loop whose sensor row offers only "off": the PLC closes it via A2.02 (OPAT)
};

// Which rows an entry goes to: every module, every loop branch with a sensor, or every branch
// of one role (the branch-1 name is written; branch 2 takes its twin, C1.13 → C2.13).
enum class PresetScope {
    Module,
    Loop, // every position and pressure loop
    PositionLoop,
    PressureLoop,
};

struct PresetEntry
{
    PresetScope scope = PresetScope::Module;
    std::string_view name; // dictionary row name, branch 1
    std::int32_t raw = 0;  // raw value as the row stores it
};

// The table, in the order it is applied.
std::span<const PresetEntry> commissionedPreset();

// One row the preset writes on a module: its name as the module has it and the raw value.
struct PresetWrite
{
    std::string name;
    std::int32_t raw = 0;
};

// The module's branches (1, or 1 and 2) with their roles.
std::vector<std::pair<int, BranchRole>> branchRoles(HcsModule &module);
// The rows the preset writes on this module (version and mode decide), in table order. Every
// name is a row the module has; an entry whose row the module lacks is left out.
std::vector<PresetWrite> commissionedValues(HcsModule &module);
// Writes commissionedValues into the module's image and its EEPROM copy (a commissioned machine
// keeps its settings over a power cycle).
void applyCommissionedPreset(HcsModule &module);

} // namespace vt::dev::sim
