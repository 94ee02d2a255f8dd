#include "rtu.h"

#include "core/byte_reader.h"
#include "core/decode_helpers.h"
#include "core/hex.h"
#include "crc.h"

#include <string>

namespace vt::dev::modbus {
namespace {

Result<Bytes, DecodeError> wrap(std::uint8_t unit, Result<Bytes, DecodeError> pdu)
{
    if (!pdu.ok()) {
        DecodeError e = pdu.error();
        e.offset += 1; // point into the ADU
        return e;
    }
    ByteWriter w;
    w.u8(unit).bytes(*pdu);
    const std::uint16_t crc = crc16(w.data());
    w.u16le(crc);
    return w.take();
}

// Structure and CRC checks shared by both directions; on success `pdu` is the PDU span.
std::optional<DecodeError> frameChecks(std::span<const std::uint8_t> adu, Direction direction,
                                       std::span<const std::uint8_t> &pdu)
{
    ByteReader r(adu);
    (void)r.u8();
    const std::uint8_t fc = r.u8();
    if (r.failed())
        return truncated(r, "an RTU frame starts with unit id and function code");
    const auto length = rtuFrameLength(adu, direction);
    if (!length)
        return decodeError(DecodeErrc::UnexpectedCommand, 1,
                           "function code " + hexByte(fc) + "; this codec handles 3 and 6");
    if (*length == 0 || adu.size() < *length)
        return decodeError(DecodeErrc::Truncated, adu.size(),
                           *length == 0
                               ? std::string("the header is incomplete")
                               : "the header announces " + std::to_string(*length) + " bytes");
    if (adu.size() > *length)
        return decodeError(DecodeErrc::TooLong, *length,
                           std::to_string(adu.size() - *length) + " bytes after the CRC");
    ByteReader c(adu);
    c.skip(*length - 2);
    const std::uint16_t got = c.u16le();
    const std::uint16_t want = crc16(adu.first(*length - 2));
    if (got != want)
        return decodeError(DecodeErrc::BadChecksum, *length - 2,
                           "CRC " + hexWord(got) + ", computed " + hexWord(want));
    pdu = adu.subspan(1, *length - kRtuOverhead);
    return std::nullopt;
}

std::uint8_t unitOf(std::span<const std::uint8_t> adu)
{
    ByteReader r(adu);
    return r.u8();
}

} // namespace

Result<Bytes, DecodeError> encodeRtu(const RtuRequest &request)
{
    return wrap(request.unit, encodePdu(request.pdu));
}

Result<Bytes, DecodeError> encodeRtu(const RtuResponse &response)
{
    return wrap(response.unit, encodePdu(response.pdu));
}

Result<RtuRequest, DecodeError> decodeRtuRequest(std::span<const std::uint8_t> adu)
{
    std::span<const std::uint8_t> pdu;
    if (auto e = frameChecks(adu, Direction::Request, pdu))
        return *e;
    auto p = decodeRequestPdu(pdu, 1);
    if (!p.ok())
        return p.error();
    return RtuRequest{unitOf(adu), std::move(p).value()};
}

Result<RtuResponse, DecodeError> decodeRtuResponse(std::span<const std::uint8_t> adu)
{
    std::span<const std::uint8_t> pdu;
    if (auto e = frameChecks(adu, Direction::Response, pdu))
        return *e;
    auto p = decodeResponsePdu(pdu, 1);
    if (!p.ok())
        return p.error();
    return RtuResponse{unitOf(adu), std::move(p).value()};
}

std::optional<std::size_t> rtuFrameLength(std::span<const std::uint8_t> bytes, Direction direction)
{
    if (bytes.empty())
        return 0;
    const auto pdu = pduLength(bytes.subspan(1), direction);
    if (!pdu)
        return std::nullopt;
    if (*pdu == 0)
        return 0;
    return *pdu + kRtuOverhead;
}

bool rtuCrcOk(std::span<const std::uint8_t> adu)
{
    if (adu.size() < 3)
        return false;
    ByteReader c(adu);
    c.skip(adu.size() - 2);
    return c.u16le() == crc16(adu.first(adu.size() - 2));
}

} // namespace vt::dev::modbus
