// Bits of the CMD 15 control byte ("byte for special functions") and module status word, per
// profile, and the error numbers a module reports in the status low byte when ERROR is set.
#pragma once

#include "core/local_text.h"
#include "profiles.h"
#include "types.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace vt::dev::hcs {

// Control byte DATx.1 (DMA Profinet manual §4.5.2–4.5.3, DMA Profibus Anleitung §4.5.2–4.5.6,
// OPAT manual §3.5.2–3.5.4). "Can be set only if the hardware enable is active."
inline constexpr std::uint8_t kControlDin1 = 0x01;
inline constexpr std::uint8_t kControlTstCmp = 0x04; // error/comparator output forced to 24 V
inline constexpr std::uint8_t kControlDin2 = 0x10;
inline constexpr std::uint8_t kControlBusDisable = 0x80;

// Status word DAT.1 = parameter 0xB0 "Internal digital switches" (OPAT manual §7, DMA Profinet
// manual §6): high byte HW_ENABLE / ERROR / BUS_DISABLE, low byte signals or error number.
inline constexpr std::uint16_t kStatusHwEnable = 0x0400;
inline constexpr std::uint16_t kStatusError = 0x0800;
inline constexpr std::uint16_t kStatusBusDisable = 0x8000;
inline constexpr std::uint16_t kStatusDin1 = 0x0001;
inline constexpr std::uint16_t kStatusDout1 = 0x0002;
inline constexpr std::uint16_t kStatusDkomp1 = 0x0004;
inline constexpr std::uint16_t kStatusDkomp11 = 0x0008;
inline constexpr std::uint16_t kStatusDin2 = 0x0010;
inline constexpr std::uint16_t kStatusDout2 = 0x0020;
inline constexpr std::uint16_t kStatusDkomp2 = 0x0040;
inline constexpr std::uint16_t kStatusDkomp22 = 0x0080;

struct BitMeaning
{
    std::uint8_t mask = 0;
    std::string_view name; // manual name: "BUS_DISABLE", "Din_1", "STAT_5"
    LocalText text;
    bool used = false; // false: "not applicable, reserved" in this version / mode
};

std::array<BitMeaning, 8> controlBits(Profile profile);
std::array<BitMeaning, 8> statusHighBits(Profile profile);
// opatPrintedOrder: use the order OPAT manual §3.5.2–3.5.4 prints (0x02 DKOMP_1, 0x04 Dout_1,
// 0x20 DKOMP_2, 0x40 Dout_2) instead of parameter 0xB0's, which the DMA manuals share (see
// docs/protocol-notes/hcs-modbus-profidrive.md).
std::array<BitMeaning, 8> statusLowBits(Profile profile, bool opatPrintedOrder = false);

struct ModuleStatus
{
    bool hwEnable = false;
    bool error = false;
    bool busDisable = false;
    std::uint8_t errorNumber = 0; // low byte while ERROR is set, else 0
    std::uint8_t signalBits = 0;  // low byte while ERROR is clear, else 0
};

ModuleStatus decodeStatus(std::uint16_t word);

// Error number in the status low byte while ERROR is set: DMA "0x0C xx" table (DMA Profinet
// manual §4.5.1.1, German from the DMA Profibus Anleitung §4.5.1.1); OPAT ERR codes (OPAT manual
// §7, ID 0x102, which §5.6 confirms: "Error number 2 = cable fracture at FB1").
std::optional<LocalText> errorNumberText(Family family, std::uint8_t number);

} // namespace vt::dev::hcs
