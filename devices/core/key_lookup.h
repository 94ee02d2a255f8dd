// keyLookup(): the inverse of a vocabulary's key() over all its values — the body every
// fromKey<Enum> specialisation (enum_key.h) shares. Apart from enum_key.h so that the many files
// that only name a vocabulary do not compile it.
#pragma once

#include <optional>
#include <string_view>

namespace vt::dev {

template<typename Enum, typename Values>
std::optional<Enum> keyLookup(const Values &all, std::string_view text)
{
    for (Enum value : all)
        if (text == key(value))
            return value;
    return std::nullopt;
}

} // namespace vt::dev
