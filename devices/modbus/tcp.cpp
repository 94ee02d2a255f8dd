#include "tcp.h"

#include "core/byte_reader.h"
#include "core/decode_helpers.h"

#include <string>

namespace vt::dev::modbus {
namespace {

Result<Bytes, DecodeError> wrap(std::uint16_t transaction, std::uint8_t unit,
                                Result<Bytes, DecodeError> pdu)
{
    if (!pdu.ok()) {
        DecodeError e = pdu.error();
        e.offset += kMbapSize;
        return e;
    }
    ByteWriter w;
    w.u16be(transaction)
        .u16be(0)
        .u16be(static_cast<std::uint16_t>(pdu->size() + 1))
        .u8(unit)
        .bytes(*pdu);
    return w.take();
}

// Header and length checks; on success `pdu` is the PDU span.
Result<Mbap, DecodeError> frame(std::span<const std::uint8_t> adu,
                                std::span<const std::uint8_t> &pdu)
{
    auto m = decodeMbap(adu);
    if (!m.ok())
        return m;
    const std::size_t size = m->aduSize();
    if (adu.size() < size)
        return decodeError(DecodeErrc::Truncated, adu.size(),
                           "MBAP length " + std::to_string(m->length) + " announces " +
                               std::to_string(size) + " bytes");
    if (adu.size() > size)
        return decodeError(DecodeErrc::TooLong, size,
                           std::to_string(adu.size() - size) + " bytes after the ADU");
    pdu = adu.subspan(kMbapSize, size - kMbapSize);
    return m;
}

} // namespace

Result<Mbap, DecodeError> decodeMbap(std::span<const std::uint8_t> bytes)
{
    ByteReader r(bytes);
    Mbap m;
    m.transaction = r.u16be();
    m.protocol = r.u16be();
    m.length = r.u16be();
    m.unit = r.u8();
    if (r.failed())
        return truncated(r, "the MBAP header has 7 bytes");
    if (m.protocol != 0)
        return decodeError(DecodeErrc::BadValue, 2,
                           "protocol id " + std::to_string(m.protocol) + " is not 0 (Modbus)");
    if (m.length < kMinMbapLength || m.length > kMaxMbapLength)
        return decodeError(DecodeErrc::BadLength, 4,
                           "MBAP length " + std::to_string(m.length) +
                               " outside 2..254 (ADU ≤ 260 bytes)");
    return m;
}

Result<Bytes, DecodeError> encodeTcp(const TcpRequest &request)
{
    return wrap(request.transaction, request.unit, encodePdu(request.pdu));
}

Result<Bytes, DecodeError> encodeTcp(const TcpResponse &response)
{
    return wrap(response.transaction, response.unit, encodePdu(response.pdu));
}

Result<TcpRequest, DecodeError> decodeTcpRequest(std::span<const std::uint8_t> adu)
{
    std::span<const std::uint8_t> pdu;
    auto m = frame(adu, pdu);
    if (!m.ok())
        return m.error();
    auto p = decodeRequestPdu(pdu, kMbapSize);
    if (!p.ok())
        return p.error();
    return TcpRequest{m->transaction, m->unit, std::move(p).value()};
}

Result<TcpResponse, DecodeError> decodeTcpResponse(std::span<const std::uint8_t> adu)
{
    std::span<const std::uint8_t> pdu;
    auto m = frame(adu, pdu);
    if (!m.ok())
        return m.error();
    auto p = decodeResponsePdu(pdu, kMbapSize);
    if (!p.ok())
        return p.error();
    return TcpResponse{m->transaction, m->unit, std::move(p).value()};
}

} // namespace vt::dev::modbus
