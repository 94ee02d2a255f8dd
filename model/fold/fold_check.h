// Checks of a FoldPlan before it is applied or handed to the PLC programmer:
// duplicate addresses, ranges against the dictionaries, CMD 15 limits, SNUM, mixed modes.
#pragma once

#include "core/local_text.h"
#include "fold_plan.h"

#include <vector>

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
};

struct FoldFinding
{
    FoldSeverity severity = FoldSeverity::Info;
    FoldCheckCode code = FoldCheckCode::NoModules;
    int module = -1;        // index into FoldPlan::modules; -1 = the node as a whole
    std::string parameter;  // "E22", "E17", … when the finding is about one parameter
    dev::LocalText message; // full sentence with the manual's reason

    bool operator==(const FoldFinding &) const = default;
};

// All findings, node-level first, then by module. `dictionaries` = nullptr uses
// dev::builtinDictionaries(); ranges come from the module's own dictionary (foldDictionary()).
std::vector<FoldFinding> checkFoldPlan(const FoldPlan &plan,
                                       const dev::DictionarySet *dictionaries = nullptr);

bool hasErrors(const std::vector<FoldFinding> &findings);
std::string_view foldSeverityKey(FoldSeverity severity); // "info", "warning", "error"
dev::LocalText foldSeverityText(FoldSeverity severity);

} // namespace vt::model
