// Parameter values as the parameter services carry them. Wandfluh — HART commands 128..133
// (HART-7 manual §4.4.1) and the CiA 408 objects over CANopen SDO: the width of the row's type
// (1, 2 or 4 bytes), two's complement for signed rows, IEEE 754 single for float rows. HCS: one
// 16-bit word per ID (OPAT manual §2.1). Shared by the node image, HART and CANopen adapters;
// pure functions, any thread.
#pragma once

#include "dict/param_meta.h"
#include "dict/raw_value.h"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace vt::dev::access {

// The value's bits, zero-extended to 32 (only the low wireBytes() count, dict/param_meta.h);
// nullopt for text, a text row, a non-finite number, a fraction on an integer row or a value the
// type cannot hold.
std::optional<std::uint32_t> rawToWireBits(const ParamMeta &row, const RawValue &value);
// The low wireBytes() bytes of `bits` as the row's type reads them (signed rows sign-extended).
double wireBitsToRaw(const ParamMeta &row, std::uint32_t bits);

// The HCS word a write of `value` to `row` carries; nullopt for text, a fraction, or a value
// outside the row's type (65535 for an int16 row would otherwise arrive as -1).
std::optional<std::uint16_t> hcsWordOf(const ParamMeta &row, const RawValue &value);

} // namespace vt::dev::access
