// Shared helpers of the simulated-module tests: the HCS families and their versions/modes, what
// each readable row must read on a fresh module (the dictionary's default, or the module's own
// identity rows), and consecutive-ID read blocks of at most 8 (OPAT manual §2.1).
#pragma once

#include "dict/dictionary_loader.h"
#include "hcs/node_rules.h"
#include "sim/hcs_module.h"
#include "sim/hcs_storage.h"

#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace vt::dev::sim::test {

// One simulated module variant: family, major version and mode.
struct Variant
{
    std::string family;
    std::string version;
    int mode = 0;
    std::string name() const { return family + "-v" + version + "-mode" + std::to_string(mode); }
};

// Every concrete HCS family with each of its versions and modes.
inline std::vector<Variant> allVariants()
{
    std::vector<Variant> out;
    const auto &set = builtinDictionaries();
    if (!set.ok()) {
        ADD_FAILURE() << "built-in dictionaries do not load";
        return out;
    }
    for (const std::string &family : set->families()) {
        const Dictionary *dict = set->find(family);
        if (dict->protocol != DeviceProtocol::Hcs)
            continue;
        for (const std::string &version : dict->versions)
            for (const std::string &mode : dict->modes)
                out.push_back({family, version, std::stoi(mode)});
    }
    return out;
}

inline const Dictionary &dictionary(const std::string &family)
{
    const auto &set = builtinDictionaries();
    static const Dictionary empty;
    if (!set.ok() || !set->find(family)) {
        ADD_FAILURE() << "no built-in dictionary " << family;
        return empty;
    }
    return *set->find(family);
}

inline HcsModuleConfig configFor(const Variant &v, std::uint8_t address = 1)
{
    HcsModuleConfig c;
    c.dictionary = &dictionary(v.family);
    c.version = v.version;
    c.mode = v.mode;
    c.address = address;
    return c;
}

// What a fresh, enabled module without errors reads for `row`: the dictionary default (rows
// without one: 0 pulled into the row's range), except the rows the module itself fills in.
inline std::uint16_t expectedFreshWord(const ParamMeta &row, const HcsModule &module)
{
    if (row.name == "Vers")
        return static_cast<std::uint16_t>(std::stoi(module.version()) * 100);
    if (row.name == "E00")
        return static_cast<std::uint16_t>(module.mode());
    if (row.name == "E22")
        return module.address();
    if (row.name == "0xB0")
        return 0x0400; // HW_ENABLE: the enable is wired, as in the manuals' examples
    if (row.defaultValue)
        return static_cast<std::uint16_t>(
            static_cast<std::int32_t>(std::lround(*row.defaultValue)));
    return static_cast<std::uint16_t>(HcsStorage::defaultRaw(row));
}

// The module's readable rows in ID order.
inline std::vector<const ParamMeta *> readableRows(const HcsModule &module)
{
    std::vector<const ParamMeta *> rows;
    for (int id = 0; id <= 0xFFFF; ++id) {
        const ParamMeta *row = module.storage().meta(id);
        if (row && row->readable())
            rows.push_back(row);
        if (id > 0x400)
            break; // HCS IDs end near 0x103 (OPAT manual §7)
    }
    return rows;
}

// Runs of consecutive readable IDs, split into blocks of ≤ 8 as the session reads them.
inline std::vector<hcs::ReadBlock> readBlocks(const std::vector<const ParamMeta *> &rows)
{
    std::vector<hcs::ReadBlock> blocks;
    std::size_t i = 0;
    while (i < rows.size()) {
        std::size_t j = i + 1;
        while (j < rows.size() && *rows[j]->id == *rows[j - 1]->id + 1)
            ++j;
        for (const hcs::ReadBlock &b : hcs::splitReads(static_cast<std::uint16_t>(*rows[i]->id),
                                                       static_cast<std::uint32_t>(j - i)))
            blocks.push_back(b);
        i = j;
    }
    return blocks;
}

} // namespace vt::dev::sim::test
