// Modbus PDUs for what HCS modules speak (ARCHITECTURE.md "Protocol decisions"): FC 3 read holding
// registers (register = parameter ID), FC 6 write single register, exceptions (FC | 0x80 + code).
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/direction.h"
#include "core/result.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace vt::dev::modbus {

inline constexpr std::uint8_t kFcReadHoldingRegisters = 3;
inline constexpr std::uint8_t kFcWriteSingleRegister = 6;
inline constexpr std::uint8_t kExceptionBit = 0x80;
// Modbus Application Protocol V1.1b3 §6.3: "Quantity of Registers 1 to 125 (0x7D)". The HCS
// node's stricter ≤ 8 is not a codec rule: see withinHcsReadLimit() / hcs::splitReads().
inline constexpr std::uint16_t kMaxReadRegisters = 125;
inline constexpr std::size_t kMaxPduSize = 253; // Modbus Application Protocol §4.1

struct ReadRequest
{
    std::uint16_t start = 0; // first register = first parameter ID
    std::uint16_t count = 0; // 1..125

    bool operator==(const ReadRequest &) const = default;
};

struct ReadResponse
{
    std::vector<std::uint16_t> registers; // 1..125; byte count = 2 × size

    bool operator==(const ReadResponse &) const = default;
};

struct WriteRequest
{
    std::uint16_t address = 0; // register = parameter ID
    std::uint16_t value = 0;

    bool operator==(const WriteRequest &) const = default;
};

// FC 6 response: the request echoed (Modbus Application Protocol §6.6).
struct WriteResponse
{
    std::uint16_t address = 0;
    std::uint16_t value = 0;

    bool operator==(const WriteResponse &) const = default;
};

struct ExceptionResponse
{
    std::uint8_t function = 0; // the request's function code, without bit 7
    std::uint8_t code = 0;     // exception code; meaning: exceptions.h

    bool operator==(const ExceptionResponse &) const = default;
};

using RequestPdu = std::variant<ReadRequest, WriteRequest>;
using ResponsePdu = std::variant<ReadResponse, WriteResponse, ExceptionResponse>;

// The HCS rule "maximal 8 parameters readable at once" (OPAT manual §2.1), for callers that
// talk to HCS modules; the codec itself allows 125.
bool withinHcsReadLimit(const ReadRequest &request);

// Fail with BadValue for a count outside 1..125, a register list outside 1..125 or an exception
// function code with bit 7 set.
Result<Bytes, DecodeError> encodePdu(const RequestPdu &pdu);
Result<Bytes, DecodeError> encodePdu(const ResponsePdu &pdu);

// Decode a whole PDU. Offsets in errors are relative to the PDU plus `base` (its offset in the
// ADU), so RTU/TCP errors point into the frame. Unknown function codes: UnexpectedCommand.
Result<RequestPdu, DecodeError> decodeRequestPdu(std::span<const std::uint8_t> pdu,
                                                 std::size_t base = 0);
Result<ResponsePdu, DecodeError> decodeResponsePdu(std::span<const std::uint8_t> pdu,
                                                   std::size_t base = 0);

// Length of the PDU that starts `pdu` as far as its first bytes tell (for de-framing):
// 0 = not enough bytes yet to know; nullopt = a function code this codec does not frame.
// FC 3 response: 2 + byte count; FC 3/6 request and FC 6 response: 5; exception: 2.
std::optional<std::size_t> pduLength(std::span<const std::uint8_t> pdu, Direction direction);

} // namespace vt::dev::modbus
