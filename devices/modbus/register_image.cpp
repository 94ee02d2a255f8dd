#include "register_image.h"

#include "core/byte_reader.h"
#include "core/decode_helpers.h"
#include "core/hex.h"
#include "modbus/pdu.h"

#include <string>

namespace vt::dev::modbus {
namespace {

bool isRead(std::uint8_t fc)
{
    return fc == kFcReadHoldingRegisters || fc == kFcReadInputRegisters;
}

bool isHandled(std::uint8_t fc)
{
    return isRead(fc) || fc == kFcWriteMultipleRegisters;
}

std::optional<DecodeError> extra(const ByteReader &r)
{
    if (r.atEnd())
        return std::nullopt;
    return tooLong(r, std::to_string(r.data().size() - r.offset()) + " bytes after the PDU");
}

DecodeError unhandled(std::uint8_t fc)
{
    return decodeError(DecodeErrc::UnexpectedCommand, 0,
                       "function code " + hexByte(fc) + "; this codec handles 3, 4 and 16");
}

} // namespace

Result<Bytes, DecodeError> encodeRegisterPdu(const RegisterRequest &pdu)
{
    ByteWriter w;
    if (const auto *q = std::get_if<RegisterRead>(&pdu)) {
        if (!isRead(q->function))
            return decodeError(DecodeErrc::BadValue, 0, "a register read is FC 3 or 4");
        if (q->count < 1 || q->count > kMaxReadRegisters)
            return decodeError(DecodeErrc::BadValue, 3,
                               "quantity " + std::to_string(q->count) + " outside 1..125");
        w.u8(q->function).u16be(q->start).u16be(q->count);
        return w.take();
    }
    const auto &wq = std::get<RegisterWrite>(pdu);
    if (wq.values.empty() || wq.values.size() > kMaxWriteRegisters)
        return decodeError(DecodeErrc::BadValue, 3,
                           "quantity " + std::to_string(wq.values.size()) + " outside 1..123");
    w.u8(kFcWriteMultipleRegisters)
        .u16be(wq.start)
        .u16be(static_cast<std::uint16_t>(wq.values.size()))
        .u8(static_cast<std::uint8_t>(2 * wq.values.size()));
    for (std::uint16_t v : wq.values)
        w.u16be(v);
    return w.take();
}

Result<Bytes, DecodeError> encodeRegisterPdu(const RegisterResponse &pdu)
{
    ByteWriter w;
    if (const auto *a = std::get_if<RegisterReadAnswer>(&pdu)) {
        if (!isRead(a->function))
            return decodeError(DecodeErrc::BadValue, 0, "a register read is FC 3 or 4");
        if (a->registers.empty() || a->registers.size() > kMaxReadRegisters)
            return decodeError(DecodeErrc::BadValue, 1,
                               std::to_string(a->registers.size()) + " registers; 1..125");
        w.u8(a->function).u8(static_cast<std::uint8_t>(2 * a->registers.size()));
        for (std::uint16_t v : a->registers)
            w.u16be(v);
    } else if (const auto *wa = std::get_if<RegisterWriteAnswer>(&pdu)) {
        w.u8(kFcWriteMultipleRegisters).u16be(wa->start).u16be(wa->count);
    } else {
        const auto &e = std::get<RegisterException>(pdu);
        if (e.function == 0 || (e.function & kExceptionBit) != 0)
            return decodeError(DecodeErrc::BadValue, 0, "exception function code must be 1..127");
        w.u8(static_cast<std::uint8_t>(e.function | kExceptionBit)).u8(e.code);
    }
    return w.take();
}

Result<RegisterRequest, DecodeError> decodeRegisterRequest(std::span<const std::uint8_t> pdu)
{
    ByteReader r(pdu);
    const std::uint8_t fc = r.u8();
    if (r.failed())
        return truncated(r, "the PDU needs a function code");
    if (!isHandled(fc))
        return unhandled(fc);
    const std::uint16_t start = r.u16be();
    const std::uint16_t count = r.u16be();
    if (isRead(fc)) {
        if (r.failed())
            return truncated(r, "a register read PDU has 5 bytes");
        if (auto e = extra(r))
            return *e;
        if (count < 1 || count > kMaxReadRegisters)
            return decodeError(DecodeErrc::BadValue, 3,
                               "quantity " + std::to_string(count) + " outside 1..125");
        return RegisterRequest{RegisterRead{fc, start, count}};
    }
    const std::uint8_t bytes = r.u8();
    if (r.failed())
        return truncated(r, "an FC 16 request needs start, quantity and byte count");
    // §6.12: quantity 1..123 and byte count = 2 × quantity, else exception 3.
    if (count < 1 || count > kMaxWriteRegisters)
        return decodeError(DecodeErrc::BadValue, 3,
                           "quantity " + std::to_string(count) + " outside 1..123");
    if (bytes != 2 * count)
        return decodeError(DecodeErrc::BadLength, 5,
                           "byte count " + std::to_string(bytes) + " is not 2 × " +
                               std::to_string(count));
    RegisterWrite write{start, {}};
    write.values.reserve(count);
    for (unsigned i = 0; i < count; ++i)
        write.values.push_back(r.u16be());
    if (r.failed())
        return truncated(r, "the byte count announces " + std::to_string(bytes) + " data bytes");
    if (auto e = extra(r))
        return *e;
    return RegisterRequest{std::move(write)};
}

Result<RegisterResponse, DecodeError> decodeRegisterResponse(std::span<const std::uint8_t> pdu)
{
    ByteReader r(pdu);
    const std::uint8_t fc = r.u8();
    if (r.failed())
        return truncated(r, "the PDU needs a function code");
    if ((fc & kExceptionBit) != 0) {
        const auto function = static_cast<std::uint8_t>(fc & ~kExceptionBit);
        if (!isHandled(function))
            return unhandled(fc);
        const std::uint8_t code = r.u8();
        if (r.failed())
            return truncated(r, "an exception response needs its code");
        if (auto e = extra(r))
            return *e;
        return RegisterResponse{RegisterException{function, code}};
    }
    if (!isHandled(fc))
        return unhandled(fc);
    if (isRead(fc)) {
        const std::uint8_t count = r.u8();
        if (r.failed())
            return truncated(r, "a register read answer needs its byte count");
        if (count == 0 || count % 2 != 0 || count > 2 * kMaxReadRegisters)
            return decodeError(DecodeErrc::BadLength, 1,
                               "byte count " + std::to_string(count) + " must be even and 2..250");
        RegisterReadAnswer a{fc, {}};
        a.registers.reserve(count / 2u);
        for (unsigned i = 0; i < count / 2u; ++i)
            a.registers.push_back(r.u16be());
        if (r.failed())
            return truncated(r, "the byte count announces " + std::to_string(count) + " bytes");
        if (auto e = extra(r))
            return *e;
        return RegisterResponse{std::move(a)};
    }
    RegisterWriteAnswer a{r.u16be(), r.u16be()};
    if (r.failed())
        return truncated(r, "an FC 16 answer PDU has 5 bytes");
    if (auto e = extra(r))
        return *e;
    return RegisterResponse{a};
}

Bytes wrapAdu(std::uint16_t transaction, std::uint8_t unit, std::span<const std::uint8_t> pdu)
{
    ByteWriter w;
    w.u16be(transaction)
        .u16be(0)
        .u16be(static_cast<std::uint16_t>(pdu.size() + 1))
        .u8(unit)
        .bytes(pdu);
    return w.take();
}

Result<std::optional<AduCut>, DecodeError> cutAdu(std::span<const std::uint8_t> stream)
{
    if (stream.size() < kMbapSize)
        return std::optional<AduCut>{};
    auto header = decodeMbap(stream);
    if (!header.ok())
        return header.error();
    const std::size_t size = header->aduSize();
    if (stream.size() < size)
        return std::optional<AduCut>{};
    return std::optional<AduCut>{
        AduCut{*header, stream.subspan(kMbapSize, size - kMbapSize), size}};
}

} // namespace vt::dev::modbus
