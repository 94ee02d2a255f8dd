#include "sim/commissioned_preset.h"

#include "sim/axis_model.h"
#include "sim/hcs_module.h"
#include "sim/param_io.h"

#include <array>

namespace vt::dev::sim {
namespace {

// Raw values in the dictionaries' units: factors ×100 (100 == 1.00), V in mV, I-portion in
// mV/s per V (1000 == 1.000). Rows and selections: DMA Profinet manual §6, DMA Profibus
// Anleitung §7, OPAT manual §7 (IDs 0x29 C1.00, 0x32..0x36 C1.09..C1.13, 0x3A C1.17, 0x3D C1.20,
// 0x43 C1.26, 0x70 E17). Why each value: docs/SIMULATOR.md "Commissioned preset".
constexpr std::array kPreset{
    // A machine on a PLC takes its set values from the bus only; the analogue inputs are not
    // wired ("To switch off the analogue set value set E17 = 2").
    PresetEntry{PresetScope::Module, "E17", 2},

    // Every loop with a sensor: the module's own controller (P-PT1-I-DT1; the DMA default 0
    // leaves the loop open), the sensor signal taken as it is (gain 1.00, offset 0, positive), so
    // d1.11 reads the measured quantity as 0 … 10 V of its range, KP1 = 2.00 without extra gain.
    PresetEntry{PresetScope::Loop, "C1.00", 1},   // P-PT1-I-DT1
    PresetEntry{PresetScope::Loop, "C1.10", 100}, // gain 1.00
    PresetEntry{PresetScope::Loop, "C1.11", 0},   // offset 0.000 V
    PresetEntry{PresetScope::Loop, "C1.12", 1},   // positive
    PresetEntry{PresetScope::Loop, "C1.13", 200}, // KP1 2.00
    PresetEntry{PresetScope::Loop, "C1.20", 1},   // gain ×1

    // Position loop: a 0 … 10 V position sensor over the stroke (1 V = a tenth of it). With
    // KP1 = 2.00 a small I-portion: 0.3 % overshoot and a lag error that the I-portion removes in
    // seconds (docs/SIMULATOR-PLANT.md) — a decent loop that can still be tuned.
    PresetEntry{PresetScope::PositionLoop, "C1.09", 4},   // 0 … 10 V
    PresetEntry{PresetScope::PositionLoop, "C1.17", 500}, // I 0.500
    PresetEntry{PresetScope::PositionLoop, "C1.26", 0},   // 0 … 10 V has no live zero

    // Pressure loop: a 4 … 20 mA transducer over the pressure range, cable fracture detection on
    // (its live zero makes a broken cable visible). A pressure in a volume with leakage needs
    // the I-portion (a P-only loop keeps a third of the set value as lag error at KP1 = 2.00).
    PresetEntry{PresetScope::PressureLoop, "C1.09", 2},    // 4 … 20 mA
    PresetEntry{PresetScope::PressureLoop, "C1.17", 2000}, // I 2.000
    PresetEntry{PresetScope::PressureLoop, "C1.26", 1},    // cable fracture detection active
};

// A loop branch whose sensor row offers nothing but "off" (the OPAT's C2.09: "0 = off (used for
// Profibus application)") cannot read a sensor: the PLC closes that loop through A2.02.
bool sensorSelectable(const HcsModule &module, int branch)
{
    const ParamMeta *sensor = module.storage().find(branchName("C1.09", branch));
    return sensor && sensor->max > 0;
}

bool applies(PresetScope scope, BranchRole role)
{
    switch (scope) {
    case PresetScope::Module: return false;
    case PresetScope::Loop:
        return role == BranchRole::PositionLoop || role == BranchRole::PressureLoop;
    case PresetScope::PositionLoop: return role == BranchRole::PositionLoop;
    case PresetScope::PressureLoop: return role == BranchRole::PressureLoop;
    }
    return false;
}

} // namespace

std::span<const PresetEntry> commissionedPreset()
{
    return kPreset;
}

std::vector<std::pair<int, BranchRole>> branchRoles(HcsModule &module)
{
    std::vector<std::pair<int, BranchRole>> out;
    for (int branch : {1, 2}) {
        if (module.openLoop(branch)) {
            out.emplace_back(branch, BranchRole::OpenLoop);
        } else if (module.closedLoop(branch)) {
            BranchRole role = isPressureBranch(module.mode(), branch) ? BranchRole::PressureLoop
                                                                      : BranchRole::PositionLoop;
            if (!sensorSelectable(module, branch))
                role = BranchRole::BusFeedback;
            out.emplace_back(branch, role);
        }
    }
    return out;
}

std::vector<PresetWrite> commissionedValues(HcsModule &module)
{
    const auto roles = branchRoles(module);
    std::vector<PresetWrite> out;
    const auto add = [&](std::string name, std::int32_t raw) {
        if (module.storage().find(name))
            out.push_back({std::move(name), raw});
    };
    for (const PresetEntry &entry : kPreset) {
        if (entry.scope == PresetScope::Module) {
            add(std::string(entry.name), entry.raw);
            continue;
        }
        for (const auto &[branch, role] : roles)
            if (applies(entry.scope, role))
                add(branchName(entry.name, branch), entry.raw);
    }
    return out;
}

void applyCommissionedPreset(HcsModule &module)
{
    HcsStorage &storage = module.storage();
    for (const PresetWrite &write : commissionedValues(module)) {
        const ParamMeta *row = storage.find(write.name);
        storage.setRaw(*row->id, write.raw);
        if (HcsStorage::isEeprom(*row))
            storage.commit(*row->id, write.raw);
    }
}

} // namespace vt::dev::sim
