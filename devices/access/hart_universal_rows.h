// The SD7 dictionary's `hart` block: values the HART universal commands carry rather than an
// IND/PNU parameter (docs/dictionary-notes/sd7.md "Universal-command data"). Each row is a field
// of one command's data: its read command, byte offset and encoding, and the command that writes
// it (HART-7 manual §5.1.1–§5.1.22).
#pragma once

#include "core/byte_writer.h"
#include "dict/param_meta.h"
#include "dict/raw_value.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace vt::dev::access {

enum class UniversalEncoding {
    PackedAscii,
    Latin1,
    UInt8,
    UInt16,
    UInt24,
    UInt32,
    Float,
    HighFiveBits,
    // Not in the data: the response's second status byte, "field device status" (HART-7 manual
    // §4.4.1), which every answer carries; read with the command the field names.
    DeviceStatusByte
};

struct UniversalField
{
    std::uint8_t readCommand = 0;
    std::size_t offset = 0; // in the response data, after the two status bytes
    std::size_t width = 1;  // bytes
    UniversalEncoding encoding = UniversalEncoding::UInt8;
    std::optional<std::uint8_t> writeCommand; // none: read only over HART
};

// The field of a `hart` row; nullopt for other rows.
std::optional<UniversalField> universalField(const ParamMeta &row);

// The row's value from a response's data and its second status byte; nullopt when the data is
// too short.
std::optional<RawValue> decodeUniversalField(const UniversalField &field,
                                             std::span<const std::uint8_t> data,
                                             std::uint8_t deviceStatus);

// Writes `value` into `record` (the command's whole data, e.g. the 21 bytes of command 18) at
// the field's place; false when the value does not fit the encoding.
bool encodeUniversalField(const UniversalField &field, const RawValue &value, Bytes &record);

// Characters a text row holds: a packed-ASCII field carries four per three bytes (HART-7 manual
// §2.3: tag 6 bytes = 8 characters); other text rows their `length`; 0 for no limit.
int textCapacity(const ParamMeta &row);

// Bytes of the write command's data (command 17: 24, 18: 21, 19: 3, 22: 32); 0 for others.
std::size_t universalRecordSize(std::uint8_t writeCommand);

} // namespace vt::dev::access
