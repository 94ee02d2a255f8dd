// The inspector's paste box: turns whatever a user pastes (hex dumps with spaces, 0x, commas,
// newlines; candump "605#4B41…") into one frame. Untrusted input: lengths are bounded up front.
#pragma once

#include "core/byte_writer.h"
#include "core/result.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace vt::dev::inspect {

inline constexpr std::size_t kMaxInputChars = 64 * 1024; // longer pastes are refused, not cut
inline constexpr std::size_t kMaxFrameBytes = 4096;      // far above every frame spoken here

struct HexInput
{
    Bytes bytes;
    std::optional<std::uint32_t> cobId; // from candump notation "<id>#<data>"
};

struct HexInputError
{
    std::size_t position = 0; // character index of the problem
    std::string reason;       // English, for logs; the UI words its own message
};

Result<HexInput, HexInputError> parseHexInput(std::string_view text);

} // namespace vt::dev::inspect
