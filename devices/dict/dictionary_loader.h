// Loads and validates device dictionaries (docs/DICTIONARY.md): resolves `extends`, `kind`,
// `remove` and named scales, and reports every problem with file and row. Pure: the caller
// supplies the file texts (embedded resources, or files from disk for tests and tools).
#pragma once

#include "core/result.h"
#include "dictionary.h"

#include <string>
#include <vector>

namespace vt::dev {

struct DictionaryFile
{
    std::string name; // "opat.json"
    std::string text;
};

using DictionaryErrors = std::vector<DictionaryError>;

Result<DictionarySet, DictionaryErrors> loadDictionaries(const std::vector<DictionaryFile> &files);

// The dictionaries compiled into the program from resources/dictionaries/.
const std::vector<DictionaryFile> &embeddedDictionaryFiles();

// Loads the embedded dictionaries once; later calls return the same set. A broken embedded
// dictionary is a build defect: the errors are returned so the caller can report and stop.
const Result<DictionarySet, DictionaryErrors> &builtinDictionaries();

} // namespace vt::dev
