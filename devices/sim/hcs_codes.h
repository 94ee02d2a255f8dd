// The EXCE codes a simulated HCS module or node answers with, named once. The numbers are the
// same in both families wherever the simulator uses them; their texts are hcs::exceptionText()'s
// tables (tests/devices/sim/hcs_codes_test.cpp checks every name against them):
//   CMD 3: OPAT manual §2.3, DMA Profinet manual §3.3 / DMA Profibus Anleitung §3.3
//   CMD 6: OPAT manual §2.6, DMA Profinet manual §3.6
//   CMD 15: OPAT manual §3.3, DMA Profinet manual §4.3 / DMA Profibus Anleitung §4.3
// A Modbus exception response carries the same code (ARCHITECTURE.md "Protocol decisions").
#pragma once

#include <cstdint>

namespace vt::dev::sim::exce {

inline constexpr std::uint8_t kNone = 0;
inline constexpr std::uint8_t kCommandNotSupported = 1; // every table
// "Wrong ID": also the answer to a write of a read-only or "not active" row, which the manuals
// do not list separately (the session cannot tell them apart, and does not need to).
inline constexpr std::uint8_t kWrongId = 2;
// CMD 6 / 15: "Wrong data value" (out of range). CMD 3: "CNT == 0 or CNT > 16", i.e. N
// outside 1..8.
inline constexpr std::uint8_t kWrongData = 3;
inline constexpr std::uint8_t kBadCount = 3;
// CMD 6: "Writing of ID failed" — the simulator's answer to a write while the EEPROM is still
// busy with the previous one (EepromBusyPolicy::Refuse; DMA Profinet manual §3.4.1).
inline constexpr std::uint8_t kWriteFailed = 4;
// CMD 3 / 6: "timeout slave, address wrong or not installed (or invalid number of slaves)".
inline constexpr std::uint8_t kSlaveTimeout = 5;
// "Internal checksum error (Modbus)" (DMA; OPAT CMD 15): what two DMA modules with the same E22
// produce on the node's internal Modbus line (both answer at once). An assumption: the DMA tables
// have no "duplicate address" code.
inline constexpr std::uint8_t kChecksum = 6;
// CMD 15: "Invalid number of connected slaves" (SNUM does not match the node).
inline constexpr std::uint8_t kInvalidSlaveCount = 7;
// CMD 15: "timeout slave, address wrong or not installed" (a module SNUM counts is missing).
inline constexpr std::uint8_t kCyclicSlaveTimeout = 8;
// OPAT: "telegram too short, Profibus output buffer too small"; DMA: "Profibus node (SADR = 0)
// … data length of the selected GSD module is too small".
inline constexpr std::uint8_t kBufferTooSmall = 9;
// OPAT only: "Two or more slaves have the same slave address".
inline constexpr std::uint8_t kDuplicateAddress = 12;

} // namespace vt::dev::sim::exce
