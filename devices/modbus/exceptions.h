// Modbus exception codes: the standard names (Modbus Application Protocol V1.1b3 §7) and what a
// code means coming from an HCS module (ARCHITECTURE.md "Protocol decisions").
#pragma once

#include "core/local_text.h"
#include "hcs/types.h"

#include <cstdint>
#include <optional>

namespace vt::dev::modbus {

inline constexpr std::uint8_t kIllegalFunction = 1;
inline constexpr std::uint8_t kIllegalDataAddress = 2;
inline constexpr std::uint8_t kIllegalDataValue = 3;
inline constexpr std::uint8_t kServerDeviceFailure = 4;

// "illegal data address" … ; nullopt for a code the standard does not define.
std::optional<LocalText> exceptionName(std::uint8_t code);

// The HCS node defined its telegrams "nach Modbus Standard" (DMA Profibus Anleitung, revision
// 14.08.2006): FC | 0x80 + code carries the EXCE of the HCS table for CMD = FC.
// The HCS meaning: hcs::exceptionText(family, function, code), e.g. FC 3 code 3 →
// "CNT == 0 or CNT > 16". nullopt when the HCS table has no such entry.
std::optional<LocalText> hcsMeaning(std::uint8_t function, std::uint8_t code, hcs::Family family);

// Both in one line: "illegal data address — HCS: wrong ID".
LocalText exceptionText(std::uint8_t function, std::uint8_t code, hcs::Family family);

} // namespace vt::dev::modbus
