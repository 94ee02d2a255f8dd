// Test helpers for parameter files: a module record holding the settings of a built-in dictionary
// (or, as older versions saved them, every row) at their factory values (or a plausible in-range
// value where the manual gives none).
#pragma once

#include "dict/dictionary_loader.h"
#include "files/file_rows.h"
#include "files/param_file.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vt::dev::files::test {

inline const Dictionary &dictionary(const std::string &family)
{
    const Dictionary *d = builtinDictionaries()->find(family);
    if (!d)
        throw std::runtime_error("no dictionary " + family);
    return *d;
}

// Settings: what this version saves (file_rows.h). All: also the process and live values older
// versions saved.
enum class Rows { Settings, All };

inline ModuleRecord moduleFromDefaults(const std::string &family, int address, std::string version,
                                       std::string mode, Rows rows = Rows::Settings)
{
    ModuleRecord m;
    m.address = address;
    m.family = family;
    m.version = std::move(version);
    m.mode = std::move(mode);
    for (const ParamMeta &p : dictionary(family).params) {
        if (rows == Rows::Settings && !isFileRow(p))
            continue;
        if (p.isString()) {
            m.values.push_back(
                makeValueRow(p, std::string("VT-" + p.name)
                                    .substr(0, static_cast<std::size_t>(std::max(p.length, 0)))));
        } else {
            const double fallback = std::clamp(0.0, p.min, p.max);
            m.values.push_back(makeValueRow(p, p.defaultValue.value_or(fallback)));
        }
    }
    return m;
}

} // namespace vt::dev::files::test
