// Reading every module of a node for a whole-node command (read, report): identify each module
// (DeviceRun::identifyModules()), read every readable row, print the rows that failed, and the
// settings as a parameter file (files/file_rows.h: no process or live values).
// Owner: the command's run function.
#pragma once

#include "device_run.h"
#include "files/param_file.h"

#include <optional>
#include <vector>

namespace vt::cli {

struct ModuleRead
{
    model::ModuleInfo module;
    model::ReadResult result;
};

// Every module read in address order; rows that failed are printed on stderr and raise *code
// (a module that does not identify ends it: nullopt, *code says how to exit). Stops after a
// lost link with what was read so far.
std::optional<std::vector<ModuleRead>> readNode(DeviceRun &run, int *code);

// The settings of `reads` as a parameter file (tool and creation time filled in).
dev::files::ParamFile paramFileOf(const std::vector<ModuleRead> &reads);

} // namespace vt::cli
