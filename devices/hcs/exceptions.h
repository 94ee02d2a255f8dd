// The node's exception codes (EXCE of an error response) per family and command, in English and
// German; Modbus exception responses reuse these meanings (ARCHITECTURE.md "Protocol decisions").
#pragma once

#include "core/local_text.h"
#include "types.h"

#include <cstdint>
#include <optional>

namespace vt::dev::hcs {

// Text of EXCE `code` in an error response to `command` (3, 6 or 15, without bit 7):
// OPAT manual §2.3 / §2.6 / §3.3 (codes 1..12); DMA Profinet manual §3.3 / §3.6 (1..6) and
// §4.3 (1..9), German from the DMA Profibus Anleitung §3.3 / §3.6 / §4.3.
// nullopt for a code the family's table does not list.
std::optional<LocalText> exceptionText(Family family, std::uint8_t command, std::uint8_t code);

// Same, but never empty: "unknown exception 42" for an unlisted code.
LocalText exceptionTextOrUnknown(Family family, std::uint8_t command, std::uint8_t code);

// Highest code in the table (12 for OPAT; 6 or 9 for DMA).
std::uint8_t maxExceptionCode(Family family, std::uint8_t command);

} // namespace vt::dev::hcs
