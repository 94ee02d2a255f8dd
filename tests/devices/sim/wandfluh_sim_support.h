// Shared helpers of the Wandfluh simulator tests (DSP-408, HART, CANopen): the built-in
// dictionaries by family id.
#pragma once

#include "dict/dictionary_loader.h"

#include <gtest/gtest.h>
#include <string>

namespace vt::dev::sim::test {

inline const Dictionary &wandfluhFamily(const std::string &name)
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
