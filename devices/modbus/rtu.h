// Modbus RTU ADUs: unit id + PDU + CRC-16/MODBUS, low CRC byte first (Modbus over Serial Line
// V1.02 §2.5.1) — the frame ValveTune speaks to HCS modules on RS232/RS485 (ARCHITECTURE.md).
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/direction.h"
#include "core/result.h"
#include "pdu.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace vt::dev::modbus {

inline constexpr std::size_t kMaxRtuAdu = 256; // Modbus over Serial Line §2.5.1
inline constexpr std::size_t kRtuOverhead = 3; // unit id + CRC

struct RtuRequest
{
    std::uint8_t unit = 1; // module address (E22) on RS485; 1 by default point-to-point
    RequestPdu pdu;

    bool operator==(const RtuRequest &) const = default;
};

struct RtuResponse
{
    std::uint8_t unit = 1;
    ResponsePdu pdu;

    bool operator==(const RtuResponse &) const = default;
};

Result<Bytes, DecodeError> encodeRtu(const RtuRequest &request);
Result<Bytes, DecodeError> encodeRtu(const RtuResponse &response);

// Errors: Truncated / TooLong against the length the header announces, BadChecksum at the CRC
// (offset size − 2), then whatever the PDU decoder finds (offsets within the ADU).
Result<RtuRequest, DecodeError> decodeRtuRequest(std::span<const std::uint8_t> adu);
Result<RtuResponse, DecodeError> decodeRtuResponse(std::span<const std::uint8_t> adu);

// Length of the RTU frame at the start of `bytes`, from its header: 0 = need more bytes to tell;
// nullopt = a function code this codec does not frame (the de-framer resynchronises).
std::optional<std::size_t> rtuFrameLength(std::span<const std::uint8_t> bytes, Direction direction);

// True when the last two bytes of `adu` are the CRC of the rest (low byte first).
bool rtuCrcOk(std::span<const std::uint8_t> adu);

} // namespace vt::dev::modbus
