// Modbus TCP ADUs, MBAP header + PDU (Modbus Messaging on TCP/IP Implementation Guide V1.0b
// §3.1.3): ValveTune's link to a gateway or the simulator over TCP (ARCHITECTURE.md).
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/result.h"
#include "pdu.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace vt::dev::modbus {

inline constexpr std::size_t kMbapSize = 7;    // transaction(2) protocol(2) length(2) unit(1)
inline constexpr std::size_t kMaxTcpAdu = 260; // 7 + 253 (Implementation Guide §4.2)
// The length field counts the unit id and the PDU: 2..254, so that an ADU never exceeds 260.
inline constexpr std::uint16_t kMinMbapLength = 2;
inline constexpr std::uint16_t kMaxMbapLength = 254;

struct Mbap
{
    std::uint16_t transaction = 0;
    std::uint16_t protocol = 0; // always 0 (Modbus)
    std::uint16_t length = 0;   // bytes after the length field
    std::uint8_t unit = 0;

    std::size_t aduSize() const { return 6u + length; }
    bool operator==(const Mbap &) const = default;
};

struct TcpRequest
{
    std::uint16_t transaction = 0;
    std::uint8_t unit = 1;
    RequestPdu pdu;

    bool operator==(const TcpRequest &) const = default;
};

struct TcpResponse
{
    std::uint16_t transaction = 0;
    std::uint8_t unit = 1;
    ResponsePdu pdu;

    bool operator==(const TcpResponse &) const = default;
};

// Decodes and checks the 7-byte header only: protocol id 0 (BadValue at 2), length 2..254
// (BadLength at 4). Bytes after the header are not looked at.
Result<Mbap, DecodeError> decodeMbap(std::span<const std::uint8_t> bytes);

Result<Bytes, DecodeError> encodeTcp(const TcpRequest &request);
Result<Bytes, DecodeError> encodeTcp(const TcpResponse &response);
Result<TcpRequest, DecodeError> decodeTcpRequest(std::span<const std::uint8_t> adu);
Result<TcpResponse, DecodeError> decodeTcpResponse(std::span<const std::uint8_t> adu);

} // namespace vt::dev::modbus
