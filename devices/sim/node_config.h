// NodeConfig and makeNode: a simulated node by dictionary family id, as the simulator app, the
// CLI and the tests build one — makeNode(clock, "opat", 3) is an OPAT master (V34) with two CAN
// slaves (V31, DIP switches 1 and 2); makeNode(clock, "dma-pn-v51", 3) three DMA-2 modules with
// E22 = 1, 2, 3. docs/SIMULATOR.md.
#pragma once

#include "core/result.h"
#include "sim/hcs_node.h"

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace vt::dev {
class DictionarySet;
}

namespace vt::dev::sim {

struct NodeConfig
{
    std::string family; // HCS dictionary family id: "opat", "dma-pn-v13", "dma-pb-v32", …
    std::size_t modules =
        1;               // every module of the node: OPAT 1..8 (master + 0..7 slaves), DMA 1..32
    int mode = 0;        // E00 of every module; 0: the family's first mode
    std::string version; // DMA: major version; empty: the family's newest (V32 of "31"/"32")
    // Module addresses in order (OPAT: 0 = master, then DIP switches; DMA: E22). Empty: OPAT
    // 0, 1, 2, …; DMA 1, 2, 3, … Repeating an address configures the duplicate-address fault.
    std::vector<std::uint8_t> addresses;
    HcsNodeOptions node;
    // Applied to every module (dictionary, version, mode and address are set by makeNode).
    HcsModuleConfig moduleTemplate;
};

// The families makeNode accepts: the concrete HCS families of the built-in dictionaries.
std::vector<std::string> simulatedFamilies(const DictionarySet &set);

// Fails with a message for an unknown or non-HCS family, a module count outside the family's
// range or a mode the family does not have. `set` must outlive the node.
Result<std::unique_ptr<HcsNode>, std::string> makeNode(SimClock &clock, const DictionarySet &set,
                                                       const NodeConfig &config);
// Same with the built-in dictionaries.
Result<std::unique_ptr<HcsNode>, std::string> makeNode(SimClock &clock, const NodeConfig &config);
Result<std::unique_ptr<HcsNode>, std::string> makeNode(SimClock &clock, std::string_view family,
                                                       std::size_t modules = 1);

} // namespace vt::dev::sim
