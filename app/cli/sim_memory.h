// The in-process simulator as a bench device: within one process, every `--sim FAMILY[:MODULES]`
// connection reaches a simulator holding what the previous command with the same spec left in
// its parameters (the writable rows), as a device on the bench would between two tool runs. Each
// valvetune-cli process starts with fresh simulators; the golden tests run commands in sequence
// in one process (set, then get) and forget the simulators between tests.
// The HCS modules, the ED1/SD1 and the SD7 (with its HART texts) alike. CLI thread only (not
// thread-safe).
#pragma once

namespace vt::model {
class SimEndpoint;
}

namespace vt::cli {

// Loads what the last simulator of the same spec held into `sim` (nothing the first time).
void restoreSimulator(model::SimEndpoint &sim);
// Keeps the parameters of `sim` for the next connection with its spec.
void rememberSimulator(const model::SimEndpoint &sim);
// Back to fresh simulators (between tests).
void forgetSimulators();

} // namespace vt::cli
