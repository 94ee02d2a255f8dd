// Modbus PDUs that move a block of registers — FC 3 / FC 4 read holding / input registers and
// FC 16 write multiple registers (Modbus Application Protocol V1.1b3 §6.3, §6.4, §6.12) — and
// their MBAP framing. A PROFIBUS-master gateway maps a slave's cyclic output and input images to
// such register blocks (ARCHITECTURE.md "Wandfluh ED1/SD1 online"); the HCS codec (pdu.h) keeps
// its FC 3 / FC 6 parameter view.
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/direction.h"
#include "core/result.h"
#include "modbus/tcp.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace vt::dev::modbus {

inline constexpr std::uint8_t kFcReadInputRegisters = 4;
inline constexpr std::uint8_t kFcWriteMultipleRegisters = 16;
// Modbus Application Protocol §6.12: "Quantity of Registers 1 to 123 (0x7B)".
inline constexpr std::uint16_t kMaxWriteRegisters = 123;

struct RegisterRead
{
    std::uint8_t function = 3; // 3 (holding) or 4 (input registers)
    std::uint16_t start = 0;
    std::uint16_t count = 0; // 1..125

    bool operator==(const RegisterRead &) const = default;
};

struct RegisterWrite // FC 16
{
    std::uint16_t start = 0;
    std::vector<std::uint16_t> values; // 1..123

    bool operator==(const RegisterWrite &) const = default;
};

struct RegisterReadAnswer
{
    std::uint8_t function = 3;
    std::vector<std::uint16_t> registers;

    bool operator==(const RegisterReadAnswer &) const = default;
};

struct RegisterWriteAnswer // FC 16: start and quantity echoed
{
    std::uint16_t start = 0;
    std::uint16_t count = 0;

    bool operator==(const RegisterWriteAnswer &) const = default;
};

struct RegisterException
{
    std::uint8_t function = 0; // without bit 7
    std::uint8_t code = 0;

    bool operator==(const RegisterException &) const = default;
};

using RegisterRequest = std::variant<RegisterRead, RegisterWrite>;
using RegisterResponse = std::variant<RegisterReadAnswer, RegisterWriteAnswer, RegisterException>;

// BadValue for a function other than 3 / 4, a count outside the function's range.
Result<Bytes, DecodeError> encodeRegisterPdu(const RegisterRequest &pdu);
Result<Bytes, DecodeError> encodeRegisterPdu(const RegisterResponse &pdu);
// Whole PDUs; function codes other than 3, 4, 16 (and their exceptions) are UnexpectedCommand.
Result<RegisterRequest, DecodeError> decodeRegisterRequest(std::span<const std::uint8_t> pdu);
Result<RegisterResponse, DecodeError> decodeRegisterResponse(std::span<const std::uint8_t> pdu);

// MBAP header + PDU (Implementation Guide §3.1.3).
Bytes wrapAdu(std::uint16_t transaction, std::uint8_t unit, std::span<const std::uint8_t> pdu);

// One ADU cut from the front of a TCP stream.
struct AduCut
{
    Mbap header;
    std::span<const std::uint8_t> pdu;
    std::size_t size = 0; // bytes the ADU takes from the stream
};
// nullopt: more bytes are needed; an error: the header cannot be right (protocol id ≠ 0, length
// outside 2..254) — the stream is out of step.
Result<std::optional<AduCut>, DecodeError> cutAdu(std::span<const std::uint8_t> stream);

} // namespace vt::dev::modbus
