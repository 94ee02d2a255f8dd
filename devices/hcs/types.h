// Shared vocabulary of the HCS node telegrams (CMD 3 / 6 / 15): device families, command codes,
// the node's limits and the decode options used by every HCS codec.
#pragma once

#include "core/direction.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace vt::dev::hcs {

// OPAT: Profibus master module (SADR 0) + up to 7 CAN slaves (OPAT manual §1.4).
// DMA: DMA-2 modules behind a Profinet / Profibus node, SADR = E22 (DMA Profinet manual §1.5).
enum class Family : std::uint8_t { Opat, Dma };

std::string_view familyName(Family family);                  // "opat" / "dma"
std::optional<Family> familyFromName(std::string_view name); // inverse, for options and the CLI

// OPAT manual §1.6, DMA Profinet manual §1.5: the three node commands.
inline constexpr std::uint8_t kCmdRead = 3;    // read up to 8 consecutive parameter IDs
inline constexpr std::uint8_t kCmdWrite = 6;   // write one parameter ID
inline constexpr std::uint8_t kCmdCyclic = 15; // fast multi-module set values / status
// OPAT manual §2.3: an error response carries the command with bit 7 set (0x83, 0x86, 0x8F).
inline constexpr std::uint8_t kErrorBit = 0x80;

// OPAT manual §2.1, DMA Profinet manual §3.1: "N-low … 1 to 8 (maximal 8 parameters readable at
// once)"; §2.2/§3.2: "CNT … Maximal 16 data bytes" (exception 3 = "CNT==0 or CNT > 16").
inline constexpr std::uint16_t kMaxReadCount = 8;
inline constexpr std::uint8_t kMaxReadDataBytes = 16;

// Fixed telegram lengths (OPAT manual §2.1, §2.4, §2.5, §2.3, §3.2).
inline constexpr std::size_t kReadRequestSize = 7;
inline constexpr std::size_t kWriteSize = 7;
inline constexpr std::size_t kExceptionSize = 4;
inline constexpr std::size_t kCyclicResponseSize = 9;
inline constexpr std::size_t kCyclicHeaderSize = 3;
inline constexpr std::size_t kCyclicModuleSize = 5;

struct DecodeOptions
{
    Family family = Family::Dma;
    // A PLC process image is often longer than the telegram in it (DMA Profinet manual §4.5.4:
    // one 42-byte module serves every fold). When set, bytes after the telegram are ignored
    // instead of being reported as DecodeErrc::TooLong.
    bool allowPadding = false;
};

} // namespace vt::dev::hcs
