// Checks of a FoldPlan before it is applied or handed to the PLC programmer:
// duplicate addresses, ranges against the dictionaries, CMD 15 limits, SNUM, mixed modes. The
// checks are Qt-free (the fuzz build has no Qt): a finding names its sentences and their values,
// and foldFindingText() (fold_check_text.cpp) renders them through tr() when they are shown.
#pragma once

#include "core/local_text.h"
#include "fold_plan.h"

#include <variant>
#include <vector>

class QString;

namespace vt::dev {
class DictionarySet;
}

namespace vt::model {

enum class FoldSeverity { Info, Warning, Error };

// What a finding is about, so the wizard can jump to the right page and tests can match it.
enum class FoldCheckCode {
    NoModules,           // plan without modules
    TooManyModules,      // more modules than the node can take at all
    Cmd15Limit,          // more modules than one CMD 15 telegram reaches (DMA 5, OPAT 8)
    AddressOutOfRange,   // E22 / SADR outside what the node allows
    AddressBeyondCmd15,  // DMA E22 > 5: only CMD 3 / CMD 6 reach the module
    DuplicateAddress,    // two modules with the same E22 / SADR
    AddressOrder,        // not 1..n left to right (DMA) / master not SADR 0 (OPAT)
    SnumMismatch,        // plcSnum does not match the module count
    MixedModes,          // modules in different modes / versions on one node
    UnknownLayout,       // version/mode without a CMD 15 layout in the manuals
    UnknownVersion,      // version not described for this node / position
    OptionOutOfRange,    // option value outside the dictionary's range
    OptionNotApplicable, // option set on a module it does not apply to
    OptionConsequence, // a valid option value with a consequence worth saying (E24 = 126, E28 = 2…)
    ProductNumber,     // DMA Profibus: GSD file cannot be decided from the product number
    NodeMismatch,      // the plan differs from what the connected node reported
};

// One sentence of a finding; its %1, %2 … are filled with FoldSentence::args in order.
enum class FoldText {
    NoModules,
    TooManyOpat,            // modules
    TooManyDma,             // modules
    Cmd15Limit,             // modules
    ProductNumberUndecided, // product number
    ProductNumberMissing,
    OpatMasterSadr,
    OpatSlaveSwitch, // module, address
    E22Off,          // module, address
    E22Range,        // module, address
    E22BeyondCmd15,  // module, address
    DuplicateSadr,   // module list, SADR
    DuplicateE22,    // module list, E22
    AddressGap,      // modules, first and last address CMD 15 reaches
    OpatSwitchOrder,
    DmaE22Order,
    SnumOpat,       // SNUM sent, modules, SNUM wanted
    SnumDma,        // SNUM sent, modules, SNUM wanted
    SnumRange,      // valid SNUM range
    SnumWaits,      // the node waits for modules not installed
    SnumBeyond,     // modules beyond SNUM never answer
    SnumLength,     // longest telegram
    VersionUnknown, // module, address
    VersionNotHere, // module, address, version, versions described
    NoLayout,       // module, address, version, mode
    MixedModes,
    OptionNotBus,       // module, address, option
    OptionNotInVersion, // module, address, option, version
    OptionOutOfRange,   // module, address, option, value, min, max, label
    E24Master,
    E24Address, // address
    E28Stop,
    E28Flag,
    E28Ignore,
    E23Off,      // module, address
    E17Analogue, // module, address
    E26Off,      // module, address
    CanBaudDiffers,
    CanBaudReboot,
    NodeDiffers, // module, address, planned version, planned mode, node's version, node's mode
    NodeMissing, // module, address
    NodeExtra,   // address, version, mode
};

// A value in a sentence: a number or name (the same in both languages, or a dictionary's
// bilingual label) or a module's address, which is worded in the language shown.
using FoldArg = std::variant<dev::LocalText, FoldAddress>;

struct FoldSentence
{
    FoldText text = FoldText::NoModules;
    std::vector<FoldArg> args;

    bool operator==(const FoldSentence &) const = default;
};

struct FoldFinding
{
    FoldSeverity severity = FoldSeverity::Info;
    FoldCheckCode code = FoldCheckCode::NoModules;
    int module = -1;       // index into FoldPlan::modules; -1 = the node as a whole
    std::string parameter; // "E22", "E17", … when the finding is about one parameter
    std::vector<FoldSentence> sentences; // with the manual's reason; foldFindingText() says them

    bool operator==(const FoldFinding &) const = default;
};

// All findings, node-level first, then by module. `dictionaries` = nullptr uses
// dev::builtinDictionaries(); ranges come from the module's own dictionary (foldDictionary()).
std::vector<FoldFinding> checkFoldPlan(const FoldPlan &plan,
                                       const dev::DictionarySet *dictionaries = nullptr);

bool hasErrors(const std::vector<FoldFinding> &findings);
std::string_view foldSeverityKey(FoldSeverity severity); // "info", "warning", "error"

// The finding's sentences and the severity in the language shown now (Qt; fold_check_text.cpp).
QString foldFindingText(const FoldFinding &finding);
QString foldSeverityText(FoldSeverity severity);

} // namespace vt::model
