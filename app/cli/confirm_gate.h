// The one gate for valve-moving writes on the command line (ARCHITECTURE.md "Trust rules"): a
// write that can move the actuator (ParamMeta::movesActuator: set values, the set-value source,
// enable and control words) and would change the device is confirmed by the person at the
// terminal, naming module, parameter and old -> new value; `--yes` confirms in advance for
// scripts; with neither, nothing is sent and the command exits 2 saying so.
// Owner: the command's run function, on the CLI thread.
#pragma once

#include "device_run.h"

#include <optional>
#include <vector>

namespace vt::cli {

struct GateItem
{
    const model::ModuleInfo *module = nullptr;
    const dev::ParamMeta *row = nullptr;
    dev::RawValue value;                 // what would be written
    std::optional<dev::RawValue> before; // what the device holds; the gate reads it when unknown
};

class ConfirmGate
{
public:
    // Takes `--yes` out of args (before the command checks for leftover options).
    ConfirmGate(Context &ctx, QStringList &args);

    // kExitOk: go on — nothing valve-moving would change, `--yes` was given, or the person said
    // yes. Otherwise the exit code (kExitUsage) after saying why; the caller sends nothing.
    int pass(DeviceRun &run, std::vector<GateItem> items);
    // A test signal: `what` says what it does; every valve-moving item is listed, even one the
    // device holds already (a test writes more than its first value).
    int pass(DeviceRun &run, std::vector<GateItem> items, const std::string &what);
    int pass(DeviceRun &run, const model::ModuleInfo &module,
             const std::vector<model::WriteItem> &items);

private:
    Context &m_ctx;
    bool m_yes = false;
};

} // namespace vt::cli
