// The built-in dictionaries by family id, for the simulator tests.
#pragma once

#include "dict/dictionary_loader.h"

#include <gtest/gtest.h>
#include <string>

namespace vt::dev::sim::test {

// The family's dictionary; an empty one (and a test failure) when there is none.
inline const Dictionary &family(const std::string &name)
{
    const auto &set = builtinDictionaries();
    if (!set.ok() || !set->find(name)) {
        ADD_FAILURE() << "no built-in dictionary " << name;
        static const Dictionary empty;
        return empty;
    }
    return *set->find(name);
}

} // namespace vt::dev::sim::test
