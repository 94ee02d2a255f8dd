// NewFileChoice: what File ▸ New asks for (family, version, mode, modules of an HCS node), and
// the parameter file it starts: one module record per module, with a value row for every
// writable parameter of that version and mode whose dictionary gives a factory default (rows
// without one are left out rather than invented). Pure functions on plain values.
#pragma once

#include "dict/dictionary.h"
#include "files/param_file.h"

#include <chrono>
#include <string>
#include <vector>

namespace vt::model {

struct NewFileChoice
{
    const dev::Dictionary *dictionary = nullptr; // from the DictionarySet; outlives the choice
    std::string version; // first module's major version; "" when the family has none
    std::string mode;    // as the dictionary lists it: "3", "vpoc"
    int modeRaw = -1;    // HCS E00 as a number; -1 when the mode is not numeric
    int modules = 1;     // modules of the node (HCS only)

    bool valid() const;
};

// Modules a new file of this family may hold: OPAT 1 + 7 CAN slaves (OPAT manual §1.4), DMA-2 5
// (the CMD 15 telegram carries up to 5 modules, ARCHITECTURE.md), a Wandfluh device 1.
int maxModules(const dev::Dictionary &dictionary);

// Address and version of module `index`: an OPAT node is the master V34 at SADR 0 and CAN slaves
// V31 at DIP addresses 1..7 (OPAT manual §1.2/§1.4); a lone OPAT V31 slave sits at 1; DMA-2
// modules at E22 = 1, 2, … with the chosen version; a Wandfluh device at 0 (HART poll address)
// or 1 (DSP-408 CANopen node).
struct ModulePlace
{
    int address = 0;
    std::string version;
};
std::vector<ModulePlace> modulePlaces(const NewFileChoice &choice);

dev::files::ParamFile newParamFile(const NewFileChoice &choice, const std::string &tool,
                                   std::chrono::system_clock::time_point created);

} // namespace vt::model
