// The HCS node telegrams a PLC exchanges with an OPAT / DMA node: CMD 3 (read), CMD 6 (write),
// their error responses, and the any-command entry points that also cover CMD 15 (cmd15.h).
#pragma once

#include "cmd15.h"
#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/result.h"
#include "types.h"

#include <cstdint>
#include <span>
#include <variant>
#include <vector>

namespace vt::dev::hcs {

// CMD 3 request, 7 bytes: TADR SADR 3 IDH IDL N-high N-low (OPAT manual §2.1).
struct ReadRequest
{
    std::uint8_t tadr = 0;
    std::uint8_t sadr = 0;
    std::uint16_t firstId = 0;
    std::uint16_t count = 0; // N; the node allows 1..8 (node_rules.h), the codec any 16-bit value

    bool operator==(const ReadRequest &) const = default;
};

// CMD 3 response, 4 + CNT bytes: TADR SADR 3 CNT DAT1H DAT1L … (OPAT manual §2.2). CNT = 2 ×
// values.
struct ReadResponse
{
    std::uint8_t tadr = 0;
    std::uint8_t sadr = 0;
    std::vector<std::uint16_t> values; // raw words; "0x8000 == -32768": see asSigned()

    bool operator==(const ReadResponse &) const = default;
};

// CMD 6 request, 7 bytes: TADR SADR 6 IDH IDL DATH DATL (OPAT manual §2.4).
struct WriteRequest
{
    std::uint8_t tadr = 0;
    std::uint8_t sadr = 0;
    std::uint16_t id = 0;
    std::uint16_t value = 0;

    bool operator==(const WriteRequest &) const = default;
};

// CMD 6 response, 7 bytes, the request echoed (OPAT manual §2.5, DMA Profinet manual §3.5).
struct WriteResponse
{
    std::uint8_t tadr = 0;
    std::uint8_t sadr = 0;
    std::uint16_t id = 0;
    std::uint16_t value = 0;

    bool operator==(const WriteResponse &) const = default;
};

// Error response, 4 bytes: TADR SADR ERR EXCE with ERR = CMD | 0x80 (OPAT manual §2.3, §2.6, §3.3).
struct ExceptionResponse
{
    std::uint8_t tadr = 0;
    std::uint8_t sadr = 0;
    std::uint8_t command = 0; // 3, 6 or 15 (bit 7 not included)
    std::uint8_t code = 0;    // EXCE; text: exceptions.h

    std::uint8_t err() const { return static_cast<std::uint8_t>(command | kErrorBit); }
    bool operator==(const ExceptionResponse &) const = default;
};

using Request = std::variant<ReadRequest, WriteRequest, CyclicRequest>;
using Response = std::variant<ReadResponse, WriteResponse, CyclicResponse, ExceptionResponse>;

inline std::int16_t asSigned(std::uint16_t raw)
{
    return static_cast<std::int16_t>(raw);
}
inline std::uint16_t asRaw(std::int16_t value)
{
    return static_cast<std::uint16_t>(value);
}

Bytes encode(const ReadRequest &request);
Bytes encode(const WriteRequest &request);
Bytes encode(const WriteResponse &response);
Bytes encode(const ExceptionResponse &response);
// Fails (BadValue) for more than 127 values: CNT is one byte.
Result<Bytes, DecodeError> encode(const ReadResponse &response);
Result<Bytes, DecodeError> encode(const Request &request, Family family);
Result<Bytes, DecodeError> encode(const Response &response);

// Typed decoders: CMD must match (UnexpectedCommand at offset 2 otherwise). Response decoders
// turn the matching error frame into DecodeErrc::DeviceException (offset 3, deviceCode = EXCE).
Result<ReadRequest, DecodeError> decodeReadRequest(std::span<const std::uint8_t> frame,
                                                   const DecodeOptions &options = {});
Result<ReadResponse, DecodeError> decodeReadResponse(std::span<const std::uint8_t> frame,
                                                     const DecodeOptions &options = {});
Result<WriteRequest, DecodeError> decodeWriteRequest(std::span<const std::uint8_t> frame,
                                                     const DecodeOptions &options = {});
Result<WriteResponse, DecodeError> decodeWriteResponse(std::span<const std::uint8_t> frame,
                                                       const DecodeOptions &options = {});
Result<ExceptionResponse, DecodeError> decodeExceptionResponse(std::span<const std::uint8_t> frame,
                                                               const DecodeOptions &options = {});

// Any command. A response whose CMD has bit 7 set is an error frame (OPAT manual §2.3) and
// decodes to ExceptionResponse; options.family decides the CMD 15 request length (cmd15.h).
Result<Request, DecodeError> decodeRequest(std::span<const std::uint8_t> frame,
                                           const DecodeOptions &options = {});
Result<Response, DecodeError> decodeResponse(std::span<const std::uint8_t> frame,
                                             const DecodeOptions &options = {});

} // namespace vt::dev::hcs
