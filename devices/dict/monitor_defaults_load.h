// Reads and checks a dictionary's "monitor" key (docs/DICTIONARY.md "Monitor defaults"): every
// name must be a row of the family that can play its part (a channel is readable and numeric, a
// set value writable and gated as valve-moving, a mode a mode of the family).
#pragma once

#include "dictionary.h"
#include "monitor_defaults.h"

#include <nlohmann/json.hpp>
#include <vector>

namespace vt::dev {

// The plan in `monitor` (the key's value) for `dict`, whose rows must be indexed already; one
// error per broken rule in `errors`, `file` left empty for the caller.
MonitorPlan loadMonitorDefaults(const nlohmann::json &monitor, const Dictionary &dict,
                                std::vector<DictionaryError> &errors);

} // namespace vt::dev
