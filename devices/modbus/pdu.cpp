#include "pdu.h"

#include "core/byte_reader.h"
#include "core/decode_helpers.h"
#include "core/hex.h"
#include "hcs/types.h"

#include <optional>
#include <string>

namespace vt::dev::modbus {
namespace {

DecodeError at(DecodeErrc code, std::size_t offset, std::size_t base, std::string detail)
{
    return decodeError(code, base + offset, std::move(detail));
}

DecodeError truncatedAt(const ByteReader &r, std::size_t base, std::string detail)
{
    return decodeError(DecodeErrc::Truncated, base + r.failOffset(), std::move(detail));
}

std::optional<DecodeError> extra(const ByteReader &r, std::size_t base)
{
    if (r.atEnd())
        return std::nullopt;
    return decodeError(DecodeErrc::TooLong, base + r.offset(),
                       std::to_string(r.data().size() - r.offset()) + " bytes after the PDU");
}

bool isHandledException(std::uint8_t fc)
{
    return fc == (kFcReadHoldingRegisters | kExceptionBit) ||
           fc == (kFcWriteSingleRegister | kExceptionBit);
}

} // namespace

bool withinHcsReadLimit(const ReadRequest &request)
{
    return request.count >= 1 && request.count <= hcs::kMaxReadCount;
}

Result<Bytes, DecodeError> encodePdu(const RequestPdu &pdu)
{
    ByteWriter w;
    if (const auto *q = std::get_if<ReadRequest>(&pdu)) {
        if (q->count < 1 || q->count > kMaxReadRegisters)
            return decodeError(DecodeErrc::BadValue, 3,
                               "quantity " + std::to_string(q->count) + " outside 1..125");
        w.u8(kFcReadHoldingRegisters).u16be(q->start).u16be(q->count);
    } else {
        const auto &wq = std::get<WriteRequest>(pdu);
        w.u8(kFcWriteSingleRegister).u16be(wq.address).u16be(wq.value);
    }
    return w.take();
}

Result<Bytes, DecodeError> encodePdu(const ResponsePdu &pdu)
{
    ByteWriter w;
    if (const auto *a = std::get_if<ReadResponse>(&pdu)) {
        if (a->registers.empty() || a->registers.size() > kMaxReadRegisters)
            return decodeError(DecodeErrc::BadValue, 1,
                               std::to_string(a->registers.size()) +
                                   " registers; FC 3 answers 1..125");
        w.u8(kFcReadHoldingRegisters).u8(static_cast<std::uint8_t>(a->registers.size() * 2));
        for (std::uint16_t v : a->registers)
            w.u16be(v);
    } else if (const auto *wr = std::get_if<WriteResponse>(&pdu)) {
        w.u8(kFcWriteSingleRegister).u16be(wr->address).u16be(wr->value);
    } else {
        const auto &e = std::get<ExceptionResponse>(pdu);
        if (e.function == 0 || (e.function & kExceptionBit) != 0)
            return decodeError(DecodeErrc::BadValue, 0,
                               "exception function code " + hexByte(e.function) +
                                   " must be 1..127");
        w.u8(static_cast<std::uint8_t>(e.function | kExceptionBit)).u8(e.code);
    }
    return w.take();
}

Result<RequestPdu, DecodeError> decodeRequestPdu(std::span<const std::uint8_t> pdu,
                                                 std::size_t base)
{
    ByteReader r(pdu);
    const std::uint8_t fc = r.u8();
    if (r.failed())
        return truncatedAt(r, base, "the PDU needs a function code");
    if (fc != kFcReadHoldingRegisters && fc != kFcWriteSingleRegister)
        return at(DecodeErrc::UnexpectedCommand, 0, base,
                  "function code " + hexByte(fc) + "; this codec handles 3 and 6");
    const std::uint16_t first = r.u16be();
    const std::uint16_t second = r.u16be();
    if (r.failed())
        return truncatedAt(r, base, "an FC " + std::to_string(fc) + " request PDU has 5 bytes");
    if (auto e = extra(r, base))
        return *e;
    if (fc == kFcReadHoldingRegisters) {
        // Modbus Application Protocol §6.3: quantity 1..125, else exception 3.
        if (second < 1 || second > kMaxReadRegisters)
            return at(DecodeErrc::BadValue, 3, base,
                      "quantity " + std::to_string(second) + " outside 1..125");
        return RequestPdu{ReadRequest{first, second}};
    }
    return RequestPdu{WriteRequest{first, second}};
}

Result<ResponsePdu, DecodeError> decodeResponsePdu(std::span<const std::uint8_t> pdu,
                                                   std::size_t base)
{
    ByteReader r(pdu);
    const std::uint8_t fc = r.u8();
    if (r.failed())
        return truncatedAt(r, base, "the PDU needs a function code");
    if ((fc & kExceptionBit) != 0) {
        if (!isHandledException(fc))
            return at(DecodeErrc::UnexpectedCommand, 0, base,
                      "function code " + hexByte(fc) + "; this codec handles 0x83 and 0x86");
        const std::uint8_t code = r.u8();
        if (r.failed())
            return truncatedAt(r, base, "an exception response needs its code");
        if (auto e = extra(r, base))
            return *e;
        return ResponsePdu{ExceptionResponse{static_cast<std::uint8_t>(fc & ~kExceptionBit), code}};
    }
    if (fc == kFcReadHoldingRegisters) {
        const std::uint8_t count = r.u8();
        if (r.failed())
            return truncatedAt(r, base, "an FC 3 response needs its byte count");
        if (count == 0 || count % 2 != 0 || count > 2 * kMaxReadRegisters)
            return at(DecodeErrc::BadLength, 1, base,
                      "byte count " + std::to_string(count) + " must be even and 2..250");
        ReadResponse a;
        a.registers.reserve(count / 2u);
        for (unsigned i = 0; i < count / 2u; ++i)
            a.registers.push_back(r.u16be());
        if (r.failed())
            return truncatedAt(r, base,
                               "byte count " + std::to_string(count) + " announces " +
                                   std::to_string(count) + " data bytes");
        if (auto e = extra(r, base))
            return *e;
        return ResponsePdu{std::move(a)};
    }
    if (fc == kFcWriteSingleRegister) {
        WriteResponse a{r.u16be(), r.u16be()};
        if (r.failed())
            return truncatedAt(r, base, "an FC 6 response PDU has 5 bytes");
        if (auto e = extra(r, base))
            return *e;
        return ResponsePdu{a};
    }
    return at(DecodeErrc::UnexpectedCommand, 0, base,
              "function code " + hexByte(fc) + "; this codec handles 3 and 6");
}

std::optional<std::size_t> pduLength(std::span<const std::uint8_t> pdu, Direction direction)
{
    ByteReader r(pdu);
    const std::uint8_t fc = r.u8();
    if (r.failed())
        return 0;
    if (fc == kFcWriteSingleRegister)
        return 5;
    if (fc == kFcReadHoldingRegisters) {
        if (direction == Direction::Request)
            return 5;
        const std::uint8_t count = r.u8();
        if (r.failed())
            return 0;
        return std::size_t{2} + count;
    }
    if (direction == Direction::Response && isHandledException(fc))
        return 2;
    return std::nullopt;
}

} // namespace vt::dev::modbus
