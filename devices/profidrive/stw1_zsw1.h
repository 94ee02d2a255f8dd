// Bits of PROFIdrive control word 1 (STW1) and status word 1 (ZSW1): the standard meanings
// (speed control mode) and the OPAT's device-specific ones (OPAT manual §5.2, §5.4).
#pragma once

#include "core/local_text.h"

#include <cstdint>
#include <span>
#include <string_view>

namespace vt::dev::profidrive {

// OPAT manual §5.2.1 (PROFIdrive table "Normalized STW1 Bits") and §5.2.2 (device specific).
namespace stw1 {
inline constexpr std::uint16_t kOn = 1u << 0;          // OPAT: "1" = enable OPAT
inline constexpr std::uint16_t kNoCoastStop = 1u << 1; // no OFF2
inline constexpr std::uint16_t kNoQuickStop = 1u << 2; // no OFF3
inline constexpr std::uint16_t kEnableOperation = 1u << 3;
inline constexpr std::uint16_t kEnableRampGenerator = 1u << 4;
inline constexpr std::uint16_t kUnfreezeRampGenerator = 1u << 5;
inline constexpr std::uint16_t kEnableSetpoint = 1u << 6;
inline constexpr std::uint16_t kFaultAcknowledge = 1u << 7; // OPAT: clears a pending error
inline constexpr std::uint16_t kJog1 = 1u << 8;
inline constexpr std::uint16_t kJog2 = 1u << 9;
inline constexpr std::uint16_t kControlByPlc = 1u << 10;
inline constexpr std::uint16_t kDin1 = 1u << 12;             // OPAT: set signal Din_1 active
inline constexpr std::uint16_t kErrorOutputTo24V = 1u << 13; // OPAT: error/comp output to 24 V
inline constexpr std::uint16_t kDin2 = 1u << 14;             // OPAT: set signal Din_2 active
// OPAT manual §5.2.1: "For using the set value Bit 0,1,2,3,4,5,6 and 10 must be set" (0x047F,
// as in the §5.6 example).
inline constexpr std::uint16_t kOpatRun = 0x047F;
} // namespace stw1

// OPAT manual §5.4.1 ("Normalized ZSW1 Bits") and §5.4.2 (device specific).
namespace zsw1 {
inline constexpr std::uint16_t kReadyToSwitchOn = 1u << 0;
inline constexpr std::uint16_t kReadyToOperate = 1u << 1;
inline constexpr std::uint16_t kOperationEnabled = 1u << 2; // OPAT: OPAT is enabled
inline constexpr std::uint16_t kFault = 1u << 3;            // OPAT: error number in NIST_A
inline constexpr std::uint16_t kNoCoastStop = 1u << 4;
inline constexpr std::uint16_t kNoQuickStop = 1u << 5;
inline constexpr std::uint16_t kSwitchingOnInhibited = 1u << 6;
inline constexpr std::uint16_t kWarning = 1u << 7;
inline constexpr std::uint16_t kSpeedErrorInTolerance = 1u << 8;
inline constexpr std::uint16_t kControlRequested = 1u << 9;
inline constexpr std::uint16_t kSetpointReached = 1u << 10;
inline constexpr std::uint16_t kKomp1 = 1u << 12;      // OPAT: signal at comparator 1
inline constexpr std::uint16_t kKomp11 = 1u << 13;     // OPAT: signal at comparator 11
inline constexpr std::uint16_t kClosedLoop = 1u << 14; // OPAT: Dout_1, controller in closed loop
} // namespace zsw1

struct WordBit
{
    std::uint16_t mask = 0;
    std::string_view name; // "ON/OFF1", "Din_1"
    LocalText whenSet;     // meaning of 1 (with the OPAT detail where the manual gives one)
    LocalText whenClear;   // meaning of 0; empty for bits whose 0 means nothing in particular
    bool deviceSpecific = false;
    bool used = true; // false: no meaning defined (bit 11 and 15 on the OPAT)
};

std::span<const WordBit> stw1Bits(); // 16 entries, bit 0 first
std::span<const WordBit> zsw1Bits();

} // namespace vt::dev::profidrive
