// Opening a .vtpar parameter file against the connected modules, shared by `write` and `diff`:
// load and check the file (docs/FILE-FORMAT.md), pair its modules with the connection's — on a
// whole node (DeviceRun::wholeNode()) by address, each module of the file with the node's module
// at that address, and the modules either side lacks named (FilePlan::unmatched); on one module
// (--module, --unit, a serial line) a one-module file goes onto it, a larger file gives the
// record at its address —, refuse a file of another family, map each record onto the module's
// dictionary (param_file_map.h) and keep the settable rows (read/write settings; process and
// live values are skipped) with the file's raw values. CLI thread.
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

// A module that is on one side only: in the file but not on the node, or the reverse.
struct UnmatchedModule
{
    int address = 0;
    bool inFile = false; // true: the file's module (family below); false: the node's (module)
    std::string family;
    model::ModuleInfo module;
};

struct FilePlan
{
    std::vector<ModulePlan> modules; // the pairs, in the node's address order
    std::vector<UnmatchedModule> unmatched;
};

// nullopt after printing why (*code: 2 for a bad file or a file that does not fit, 1/3 when a
// module does not identify). forWrite: rows out of range or of the wrong type refuse the whole
// file (nothing is sent); for a diff they are only skipped. Unmatched modules are left to the
// command to report.
std::optional<FilePlan> planFile(DeviceRun &run, const char *command, const QString &path,
                                 bool forWrite, int *code);

// "the file's module 4 is not on the node; the node's module 3 (dma-pn-v51) is not in the file"
std::string unmatchedText(const std::vector<UnmatchedModule> &unmatched);
Json unmatchedJson(const std::vector<UnmatchedModule> &unmatched);

// The device's current values of the plan's readable rows; nullopt after printing why (*code).
std::optional<std::map<const dev::ParamMeta *, dev::RawValue>>
readCurrent(DeviceRun &run, const ModulePlan &plan, int *code);

Json skippedJson(const std::vector<SkippedRow> &skipped);

} // namespace vt::cli
