// How deeply a JSON text nests, counted before any parser sees it: nlohmann::json parses and
// destroys nested values recursively, so a hostile "[[[[…" from a file must be refused first.
// Brackets inside strings do not count. Pure; any thread.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace vt::dev {

// The offset of the first '[' or '{' that opens level limit + 1, or nullopt when the text stays
// within `limit` levels.
std::optional<std::size_t> jsonTooDeepAt(std::string_view text, int limit);

} // namespace vt::dev
