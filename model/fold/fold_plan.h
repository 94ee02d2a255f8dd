// FoldPlan: what one multi-module node (a "fold") should look like — node type, its modules with
// software version, mode, address and bus options — as a plain value the wizard, the CLI, the
// checks, the PLC configuration and the plan file share. Qt-free (strings are UTF-8)
// so the plan file parser can be fuzzed like the devices/ codecs; its few words for people are
// said through tr() in fold_plan_text.cpp.
#pragma once

#include "hcs/profiles.h"
#include "hcs/types.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

class QString;

namespace vt::dev {
struct Dictionary;
struct ParamMeta;
class DictionarySet;
} // namespace vt::dev

namespace vt::model {

// OPAT manual §1.4 / §3: OPAT master (Profibus slave + CAN master, SADR 0) with CAN slaves.
// DMA Profibus Anleitung §1.3 / §4–5 and DMA Profinet manual §1.3 / §4–5: DMA-2 modules behind a
// Profibus or Profinet node module, SADR = E22.
enum class FoldNode { Opat, DmaProfibus, DmaProfinet };

std::string_view foldNodeKey(FoldNode node);                   // "opat", "dma-pb", "dma-pn"
std::optional<FoldNode> foldNodeFromKey(std::string_view key); // inverse (CLI, plan file)
dev::hcs::Family foldFamily(FoldNode node);                    // Opat / Dma
// "DMA-2 modules on a PROFIBUS node", through tr() (Qt; fold_plan_text.cpp).
QString foldNodeTitle(FoldNode node);

// Modules one CMD 15 telegram reaches: OPAT master + 7 slaves = 8 (OPAT manual §1.6, §3.1);
// DMA E22 = 1..5 (DMA Profibus Anleitung §1.5, DMA Profinet manual §1.5).
std::size_t foldMaxCmd15Modules(FoldNode node);
// Highest module count the wizard can plan at all. DMA: E22 up to 32 (the rest only by CMD 3/6);
// OPAT: master + 7 slaves (rotary switch 1..7).
std::size_t foldMaxModules(FoldNode node);

// Software versions the manuals describe for the node (major number, e.g. 15, 22, 31, 32 for
// DMA Profibus; 13, 51 for DMA Profinet; 34 for the OPAT master, 31 for OPAT CAN slaves).
std::vector<int> foldVersions(FoldNode node, std::size_t moduleIndex);

// Bus options a module may carry (raw values, as in the dictionaries). nullopt = "leave as it is"
// (not written by Apply, not shown in the PLC sheet). Which apply where: foldOptionNames().
struct FoldModuleOptions
{
    std::optional<int> e17; // set value source / activation mode (all nodes)
    std::optional<int> e23; // bus telegram timeout window, 1 == 10 ms, 0 = off (all nodes)
    std::optional<int> e24; // OPAT master only: PROFIBUS address, 126 = set by the master
    std::optional<int> e26; // OPAT only: CAN baud rate (master and slaves must agree)
    std::optional<int> e28; // OPAT master only: behaviour when a CAN slave is lost

    bool operator==(const FoldModuleOptions &) const = default;
};

struct FoldModule
{
    int version = 0; // software major version (13, 15, 22, 31, 32, 34, 51); 0 = not known
    int mode = 0;    // E00 operating mode (1, 2, 3, 4, 6, 8); 0 = not known
    // DMA: E22 (1..32, CMD 15 for 1..5). OPAT: SADR, 0 = master, 1..7 = CAN slave rotary switch.
    int address = 0;
    FoldModuleOptions options;
    std::string name; // UTF-8 free text for the PLC sheet ("lift cylinder"); may be empty

    bool operator==(const FoldModule &) const = default;
};

struct FoldPlan
{
    FoldNode node = FoldNode::DmaProfibus;
    // Order as mounted: DMA from the left (E22 = 1) towards the node module (DMA Profinet manual
    // §4.1); OPAT modules[0] is the master (SADR 0), then the CAN slaves.
    std::vector<FoldModule> modules;
    // DMA Profibus Anleitung §6.1.1: the last two digits of the node's product number decide the
    // GSD file ("5 xxx xxx x1 … x4" → hcs0220.gsd, "5 005 xxx x5" → hcs0ea7.gsd). Empty = not
    // known.
    std::string productNumber;
    // SNUM the PLC program sends, when it already exists and should be checked; nullopt = the plan
    // decides (snum follows from the module count).
    std::optional<int> plcSnum;
    std::string title; // UTF-8 free text: machine / node name for the sheet
    std::string notes; // UTF-8 free text

    bool operator==(const FoldPlan &) const = default;
};

// A consistent plan with `modules` modules: addresses 1..n (DMA) or 0, 1..n−1 (OPAT), the
// family's worked-example version/mode (DMA PB V15 mode 1, DMA PN V13 mode 1, OPAT V34/V31
// mode 3), no options. `modules` is not clamped: the checks report an impossible count.
FoldPlan defaultFoldPlan(FoldNode node, std::size_t modules);

// Dictionary family of a module ("opat", "dma-pb-v32", "dma-pn-v51"); "" when the version is
// not known or the node has no dictionary for it.
std::string foldDictionaryFamily(FoldNode node, const FoldModule &module);
// That dictionary from the given set (normally dev::builtinDictionaries()), or nullptr.
const dev::Dictionary *foldDictionary(const dev::DictionarySet &set, FoldNode node,
                                      const FoldModule &module);

// CMD 15 layout of a module (what VALUE1/VALUE2 and the bits mean); nullopt when the manuals
// define none for its version/mode. Version 0 / mode 0 pick the family default (profiles.h).
std::optional<dev::hcs::Profile> foldProfile(FoldNode node, const FoldModule &module);

// Option parameters ("E17", "E23", "E24", "E26", "E28") that apply to modules[index] of the node,
// in wizard order. OPAT: E24/E28 on the master only; E26 on all (OPAT manual §1.4, §7). DMA: E17,
// E23.
std::vector<std::string> foldOptionNames(FoldNode node, std::size_t index);
std::optional<int> foldOption(const FoldModuleOptions &options, std::string_view name);
void setFoldOption(FoldModuleOptions &options, std::string_view name, std::optional<int> value);

// A module's address as its node names it: E22 on a DMA-2 node, SADR (the rotary switch, 0 for
// the master) on an OPAT node. A value, so Qt-free code can put it into a sentence; said in the
// language in force by foldAddressText().
struct FoldAddress
{
    FoldNode node = FoldNode::DmaProfinet;
    int address = 0;

    bool operator==(const FoldAddress &) const = default;
};
FoldAddress foldAddress(FoldNode node, const FoldModule &module);
// "E22 = 3" (DMA), "SADR 0 (master)" / "SADR 2 (rotary switch 2)" (OPAT), through tr() (Qt;
// fold_plan_text.cpp).
QString foldAddressText(const FoldAddress &address);
QString foldAddressText(FoldNode node, const FoldModule &module);

} // namespace vt::model
