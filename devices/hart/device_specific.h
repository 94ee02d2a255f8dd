// Wandfluh device-specific HART commands 128..133 (HART-7 manual §4.4.1): read or write one
// parameter addressed by IND, PNU and instance; the command number fixes the value width.
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/field_span.h"
#include "core/result.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vt::dev::hart {

// HART-7 manual §4.4.1 table "data type / number of bytes / command number".
inline constexpr std::uint8_t kReadByte = 128;
inline constexpr std::uint8_t kWriteByte = 129;
inline constexpr std::uint8_t kReadWord = 130;
inline constexpr std::uint8_t kWriteWord = 131;
inline constexpr std::uint8_t kReadDoubleWord = 132;
inline constexpr std::uint8_t kWriteDoubleWord = 133;

enum class ValueType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float };

bool isParameterCommand(std::uint8_t command); // 128..133
bool isWriteCommand(std::uint8_t command);     // 129, 131, 133
std::size_t valueWidth(std::uint8_t command);  // 1, 2, 4; 0 when not 128..133
std::size_t valueWidth(ValueType type);
std::uint8_t readCommand(ValueType type);
std::uint8_t writeCommand(ValueType type);

// §4.4.1 "IND and PNU correspond to the description of the parameter; the instance number
// corresponds to the channel number" (channel 1 = instance 0).
struct ParamRef
{
    std::uint8_t ind = 0;
    std::uint8_t pnu = 0;
    std::uint8_t instance = 0;
    bool operator==(const ParamRef &) const = default;
};

// One request or response of commands 128..133. `raw` holds the value bytes big-endian,
// zero-extended; absent only in a read request (data bytes 1..3 only).
struct ParamAccess
{
    std::uint8_t command = kReadByte;
    ParamRef ref;
    std::optional<std::uint32_t> raw;
    bool operator==(const ParamAccess &) const = default;
};

ParamAccess readParam(ValueType type, ParamRef ref);
ParamAccess writeParam(ValueType type, ParamRef ref, std::uint32_t raw);

// Sign-extends `raw` of `width` bytes; reinterprets 4 bytes as IEEE 754.
std::int32_t asSigned(std::uint32_t raw, std::size_t width);
float asFloat(std::uint32_t raw);
std::uint32_t rawFromSigned(std::int32_t value, std::size_t width);

// Exactly 3 bytes (read request) or 3 + width bytes (the rest): BadLength / TooLong otherwise.
Result<ParamAccess, DecodeError> decodeParamAccess(std::uint8_t command, bool response,
                                                   std::span<const std::uint8_t> data);
// BadValue when the command is not 128..133 or `raw` is missing where the layout needs it.
Result<Bytes, DecodeError> encodeParamAccess(const ParamAccess &access, bool response);

std::optional<DecodeError> describeParamAccess(std::uint8_t command, bool response,
                                               std::span<const std::uint8_t> data,
                                               std::size_t offset, int depth,
                                               std::vector<FieldSpan> &out);

} // namespace vt::dev::hart
