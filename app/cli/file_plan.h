// Opening a .vtpar parameter file against the connected modules, shared by `write` and `diff`:
// load and check the file (docs/FILE-FORMAT.md), pair its modules with the connection's (by
// address; a one-module file goes onto the one selected module), refuse a file of another family,
// map each record onto the module's dictionary (param_file_map.h) and keep the settable rows
// (read/write settings; process and live values are skipped) with the file's raw values. CLI
// thread.
#pragma once

#include "device_run.h"
#include "dict/param_meta.h"
#include "dict/raw_value.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vt::cli {

struct PlannedRow
{
    const dev::ParamMeta *row = nullptr; // writable
    dev::RawValue value;                 // the file's raw value
};

struct SkippedRow
{
    std::string name;
    // "unknown", "not-applicable", "out-of-range", "type-mismatch", "not-a-setting" (reason:
    // "process" or "live", never written)
    std::string status;
    std::string reason;
};

struct ModulePlan
{
    model::ModuleInfo module;
    std::vector<PlannedRow> rows;    // in file order
    std::vector<SkippedRow> skipped; // file rows not applied (reported, never written)
};

// nullopt after printing why (*code: 2 for a bad file or a file that does not fit, 1/3 when a
// module does not identify). forWrite: rows out of range or of the wrong type refuse the whole
// file (nothing is sent); for a diff they are only skipped.
std::optional<std::vector<ModulePlan>> planFile(DeviceRun &run, const char *command,
                                                const QString &path, bool forWrite, int *code);

// The device's current values of the plan's readable rows; nullopt after printing why (*code).
std::optional<std::map<const dev::ParamMeta *, dev::RawValue>>
readCurrent(DeviceRun &run, const ModulePlan &plan, int *code);

Json skippedJson(const std::vector<SkippedRow> &skipped);

} // namespace vt::cli
