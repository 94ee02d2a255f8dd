// Consistency rules every loaded dictionary must satisfy (docs/DICTIONARY.md "Validation").
#pragma once

#include "dictionary.h"

#include <vector>

namespace vt::dev {

// Returns one error per broken rule; `file` is left empty for the caller to fill.
std::vector<DictionaryError> validateDictionary(const Dictionary &dict);

} // namespace vt::dev
