// PROFIdrive standard telegram 1 as the OPAT implements it (OPAT manual §5.1–5.5): PZD 2/2 words,
// STW1 + NSOLL_A from the PLC, ZSW1 + NIST_A back; set and actual values in N2 normalisation.
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/result.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace vt::dev::profidrive {

inline constexpr std::size_t kTelegram1Size = 4; // OPAT manual §5.1 "PZD length 2/2 words"

// PLC → drive (OPAT manual §5.1 table 87: STW1, NSOLL_A).
struct Setpoint
{
    std::uint16_t stw1 = 0;
    std::int16_t nsollA = 0; // N2

    bool operator==(const Setpoint &) const = default;
};

// Drive → PLC (ZSW1, NIST_A). While ZSW1 bit 3 (fault) is set NIST_A carries the OPAT error
// number instead of the actual value (OPAT manual §5.4.1, §5.6).
struct Actual
{
    std::uint16_t zsw1 = 0;
    std::int16_t nistA = 0; // N2, or the error number

    bool operator==(const Actual &) const = default;
};

Bytes encode(const Setpoint &setpoint);
Bytes encode(const Actual &actual);
// Exactly 4 bytes unless allowTrailing (then the words are the first 4 bytes of a longer image).
Result<Setpoint, DecodeError> decodeSetpoint(std::span<const std::uint8_t> bytes,
                                             bool allowTrailing = false);
Result<Actual, DecodeError> decodeActual(std::span<const std::uint8_t> bytes,
                                         bool allowTrailing = false);

// N2 (PROFIdrive profile, coding 113, quoted in OPAT manual §5.3): 0x4000 = 100 %, range −200 % ..
// +200 % − 2^-14. OPAT: 100 % = 10 V. The manual also says "100% = 0x2000, means internal of the
// OPAT set point of 10.0V" (§5.3), but its own worked example "Set-value = 0x0700 == 1,093V"
// (§5.6) only works with 0x4000 = 10 V (0x0700 / 0x4000 × 10 V = 1.094 V; with 0x2000 it would be
// 2.188 V) — ARCHITECTURE.md "PROFIdrive N2" decides for 0x4000; the full scale is a parameter.
inline constexpr double kN2FullScale = 16384.0; // 0x4000 = 100 %
inline constexpr double kOpatVoltsAt100Percent = 10.0;

double n2ToPercent(std::int16_t n2);
double n2ToVolts(std::int16_t n2, double voltsAt100 = kOpatVoltsAt100Percent);
// Rounded to the nearest step and clamped to the int16 range.
std::int16_t percentToN2(double percent);
std::int16_t voltsToN2(double volts, double voltsAt100 = kOpatVoltsAt100Percent);
// The HCS raw unit (1000 = 1.000 V, e.g. B1.01 at ID 0x100) from N2, rounded: 0x4000 → 10000.
int n2ToMillivolts(std::int16_t n2, double voltsAt100 = kOpatVoltsAt100Percent);

} // namespace vt::dev::profidrive
