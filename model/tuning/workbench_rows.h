// Which rows a workbench test uses on a module, from the dictionary's "monitor" data
// (docs/DICTIONARY.md "Monitor defaults"): the set value it drives, the row that answers it (the
// actual value the analysis and the travel window read) and the channels it records.
// Pure lookups; any thread.
#pragma once

#include "dict/dictionary.h"

#include <string>
#include <vector>

namespace vt::model {

// The set values a test may drive in `mode`, in the dictionary's order (HCS: A1.01, A2.01).
std::vector<const dev::ParamMeta *> testSetValueRows(const dev::Dictionary &dictionary,
                                                     const std::string &mode);
// The set value of HCS branch `branch` (1 or 2): the one whose row is of that branch; for rows
// without a branch (Wandfluh) the branch-th in the list. Null when there is none.
const dev::ParamMeta *testSetValueRow(const dev::Dictionary &dictionary, const std::string &mode,
                                      int branch);
// The row that answers `setValue` (null: the dictionary names none, so no analysis).
const dev::ParamMeta *responseRow(const dev::Dictionary &dictionary, const std::string &mode,
                                  const dev::ParamMeta &setValue);
// The monitor's default channels of the mode, with the response added when they lack it.
std::vector<const dev::ParamMeta *> recordedRows(const dev::Dictionary &dictionary,
                                                 const std::string &mode,
                                                 const dev::ParamMeta &setValue);

// The raw value a set value of `display` units is written as (nearest raw step, as the step and
// the signal range check send it).
double setValueRaw(const dev::ParamMeta &setValue, double display);

// The row whose value says the module is in error (the dictionary's "monitor"."fault"), or null.
const dev::FaultRow *faultCheck(const dev::Dictionary &dictionary, const std::string &mode);

} // namespace vt::model
