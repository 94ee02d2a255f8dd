// Which dictionary rows a parameter file carries: settings only (ARCHITECTURE.md "Trust rules",
// docs/DICTIONARY.md "Row kinds"). Process values (set values, control words) and live values
// (display values, status) change at run time; a file that held them would write a set value
// back or report a stale display value as a difference. Pure; any thread.
#pragma once

#include "dict/param_meta.h"

namespace vt::dev::files {

// True for a setting: saved in a file, compared with the device, written by Write Changes and
// `valvetune-cli write`. False for process and live values.
bool isFileRow(const ParamMeta &meta);

} // namespace vt::dev::files
