// key() / fromKey<Enum>(): the string form of a vocabulary enum (STYLE.md rule 18). Keys exist
// only at the edges — command lines, settings, files, logs; everything between uses the enum.
// Each vocabulary declares `const char *key(Enum)` and a specialisation of fromKey beside its
// enum; fromKey returns nullopt for a key the vocabulary does not have.
#pragma once

#include <optional>
#include <string_view>

namespace vt::dev {

template<typename Enum> std::optional<Enum> fromKey(std::string_view key);

} // namespace vt::dev
