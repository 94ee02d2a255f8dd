// MonitorDefaults: what the live monitor plots when it starts and which rows its set-value step
// may write, per family and mode, as data in the dictionary ("monitor" key, docs/DICTIONARY.md
// "Monitor defaults"). The manual quotation that justifies each choice sits beside it in the file.
// Owner: the Dictionary that holds it; immutable after loading, any thread may read.
#pragma once

#include "core/local_text.h"
#include "dsp408/state_machine.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vt::dev {

// A row whose value must be `value` before a bus set value drives the valve alone (HCS E17 = 2;
// SD7 db_Local = 0 and db_DeviceMode = 1 "Command value from fieldbus"), and the manual's reason.
// A state rule asks instead for a DSP-408 device state (ED1/SD1 manual and HART-7 manual §4.2.2:
// only DEVICE_MODE_ACTIVE "the device functions are enabled"): `row` is then the status word that
// reports it and `writeRow` = `value` the control word that commands it.
struct SetValueActivation
{
    std::string row;
    double value = 0;
    LocalText reason; // the manual's words, shown when the step is refused
    std::optional<dsp408::State> state;
    std::string writeRow; // empty: `row` itself is written

    // The row written to meet the rule.
    const std::string &written() const { return writeRow.empty() ? row : writeRow; }
    // Whether `held` (the raw value read from `row`) meets the rule.
    bool holds(double held) const;
};

// A row whose value says the module is in error (OPAT ERR "0 = no error present"; DMA 0xB0 bit
// 11 "Error"): while (value & mask) differs from `ok`, a workbench test stops.
struct FaultRow
{
    std::string row;
    std::uint32_t mask = 0xFFFF'FFFF;
    std::uint32_t ok = 0;
};

struct MonitorDefaults
{
    std::vector<std::string> channels;          // plotted when monitoring starts, in this order
    std::vector<std::string> setValues;         // rows the step writes; empty: no step
    std::vector<SetValueActivation> activation; // checked in this order
    // Set value → the row that answers it (the workbench's actual value: d1.11 for A1.01 in
    // closed loop, the solenoid current in open loop). A set value without one has no analysis.
    std::map<std::string, std::string> responses;
    std::optional<FaultRow> fault; // none: the module reports errors only to the PLC
    LocalText noSetValue;          // why there is no step, when setValues is empty
};

// The dictionary-level defaults and their per-mode overrides (a mode entry replaces the keys it
// gives).
struct MonitorPlan
{
    MonitorDefaults all;
    std::map<std::string, MonitorDefaults> byMode;

    // The defaults for `mode` (a family mode string, "" when unknown).
    const MonitorDefaults &forMode(const std::string &mode) const;
};

} // namespace vt::dev
