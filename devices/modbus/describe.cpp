#include "describe.h"

#include "core/byte_reader.h"
#include "core/hex.h"
#include "crc.h"
#include "exceptions.h"
#include "rtu.h"
#include "tcp.h"

#include <string>

namespace vt::dev::modbus {
namespace {

struct Rows
{
    std::vector<FieldSpan> &out;

    void add(std::string key, std::size_t offset, std::size_t length, std::string value,
             LocalText text, int depth = 0)
    {
        out.push_back(
            FieldSpan{std::move(key), offset, length, depth, std::move(value), std::move(text)});
    }
};

LocalText join(const LocalText &a, const LocalText &b, const char *sep = ": ")
{
    return {a.en + sep + b.en, a.de + sep + b.de};
}

LocalText idText(std::uint16_t id, const DescribeOptions &o)
{
    return o.parameters.idText(id, {"parameter ID", "Parameter-ID"});
}

LocalText valueText(std::uint16_t id, std::uint16_t raw, bool idKnown, const DescribeOptions &o)
{
    return o.parameters.valueText(id, raw, idKnown);
}

std::string signedText(std::uint16_t raw)
{
    return std::to_string(static_cast<std::int16_t>(raw));
}

LocalText functionText(std::uint8_t fc)
{
    switch (fc) {
    case kFcReadHoldingRegisters:
        return {"function 3: read holding registers (HCS CMD 3: read parameters)",
                "Funktion 3: Holding-Register lesen (HCS CMD 3: Parameter lesen)"};
    case kFcWriteSingleRegister:
        return {"function 6: write single register (HCS CMD 6: write a parameter)",
                "Funktion 6: einzelnes Register schreiben (HCS CMD 6: Parameter schreiben)"};
    case kFcReadHoldingRegisters | kExceptionBit:
        return {"exception response to function 3 (bit 7 set)",
                "Ausnahmeantwort auf Funktion 3 (Bit 7 gesetzt)"};
    case kFcWriteSingleRegister | kExceptionBit:
        return {"exception response to function 6 (bit 7 set)",
                "Ausnahmeantwort auf Funktion 6 (Bit 7 gesetzt)"};
    default:
        return {"function code not handled by this codec",
                "von diesem Codec nicht behandelter Funktionscode"};
    }
}

// PDU rows from `pdu` (the bytes available for it) at ADU offset `base`.
void pduRows(Rows &rows, std::span<const std::uint8_t> pdu, std::size_t base,
             const DescribeOptions &o)
{
    ByteReader r(pdu);
    if (r.remaining() < 1)
        return;
    const std::uint8_t fc = r.u8();
    rows.add("pdu.function", base, 1, hexByte(fc), functionText(fc));
    const bool request = o.direction == Direction::Request;
    if ((fc & kExceptionBit) != 0) {
        if (request || r.remaining() < 1)
            return;
        const std::uint8_t code = r.u8();
        rows.add(
            "pdu.exception", base + 1, 1, std::to_string(code),
            join({"exception code", "Ausnahmecode"},
                 exceptionText(static_cast<std::uint8_t>(fc & ~kExceptionBit), code, o.family)));
        return;
    }
    if (fc == kFcReadHoldingRegisters && !request) {
        if (r.remaining() < 1)
            return;
        const std::uint8_t count = r.u8();
        rows.add("pdu.byteCount", base + 1, 1, std::to_string(count),
                 {"byte count (2 × registers)", "Byteanzahl (2 × Register)"});
        for (unsigned i = 0; i < count / 2u && r.remaining() >= 2; ++i) {
            const std::size_t at = base + r.offset();
            const std::uint16_t raw = r.u16be();
            const std::string n = std::to_string(i + 1);
            const bool idKnown = o.requestStart.has_value() && *o.requestStart + i <= 0xFFFFu;
            const auto id = static_cast<std::uint16_t>(o.requestStart.value_or(0) + i);
            LocalText text{"register " + n, "Register " + n};
            if (idKnown)
                text = join(text, idText(id, o));
            rows.add("pdu.register" + n, at, 2, signedText(raw),
                     join(text, valueText(id, raw, idKnown, o), ", "));
        }
        return;
    }
    if (fc != kFcReadHoldingRegisters && fc != kFcWriteSingleRegister)
        return;
    if (r.remaining() < 2)
        return;
    const std::uint16_t first = r.u16be();
    if (fc == kFcReadHoldingRegisters) {
        rows.add("pdu.start", base + 1, 2, hexWord(first),
                 join({"first register", "erstes Register"}, idText(first, o)));
        if (r.remaining() < 2)
            return;
        const std::uint16_t count = r.u16be();
        rows.add("pdu.count", base + 3, 2, std::to_string(count),
                 {"quantity of registers (Modbus: 1..125; HCS modules read at most 8)",
                  "Anzahl der Register (Modbus: 1..125; HCS-Module lesen höchstens 8)"});
        if (count > 8)
            rows.add("note", 0, 0, {},
                     {"more than 8 registers: an HCS module answers exception 3 (OPAT manual §2.1)",
                      "mehr als 8 Register: ein HCS-Modul antwortet mit Ausnahme 3 (DMA Profibus "
                      "Anleitung §3.1)"});
        return;
    }
    rows.add("pdu.address", base + 1, 2, hexWord(first),
             join({"register", "Register"}, idText(first, o)));
    if (r.remaining() < 2)
        return;
    const std::uint16_t value = r.u16be();
    rows.add("pdu.value", base + 3, 2, signedText(value),
             join({"register value", "Registerwert"}, valueText(first, value, true, o), ", "));
}

LocalText pduSummary(const RequestPdu &p)
{
    if (const auto *q = std::get_if<ReadRequest>(&p))
        return {"FC 3 read " + std::to_string(q->count) + " register(s) from " + hexWord(q->start),
                "FC 3 lese " + std::to_string(q->count) + " Register ab " + hexWord(q->start)};
    const auto &w = std::get<WriteRequest>(p);
    return {"FC 6 write " + hexWord(w.address) + " = " + signedText(w.value),
            "FC 6 schreibe " + hexWord(w.address) + " = " + signedText(w.value)};
}

LocalText pduSummary(const ResponsePdu &p, hcs::Family family)
{
    if (const auto *a = std::get_if<ReadResponse>(&p))
        return {"FC 3 response, " + std::to_string(a->registers.size()) + " register(s)",
                "FC 3 Antwort, " + std::to_string(a->registers.size()) + " Register"};
    if (const auto *w = std::get_if<WriteResponse>(&p))
        return {"FC 6 response " + hexWord(w->address) + " = " + signedText(w->value),
                "FC 6 Antwort " + hexWord(w->address) + " = " + signedText(w->value)};
    const auto &e = std::get<ExceptionResponse>(p);
    const LocalText t = exceptionText(e.function, e.code, family);
    return {"exception to FC " + std::to_string(e.function) + ": " + std::to_string(e.code) + " " +
                t.en,
            "Ausnahme zu FC " + std::to_string(e.function) + ": " + std::to_string(e.code) + " " +
                t.de};
}

void finish(Description &d, const std::optional<DecodeError> &error, LocalText summary,
            const std::string &unit)
{
    if (error) {
        d.error = error;
        const LocalText why = describeError(*error);
        d.summary = {"invalid Modbus frame: " + why.en, "ungültiges Modbus-Telegramm: " + why.de};
        return;
    }
    d.summary = {summary.en + " (unit " + unit + ")", summary.de + " (Gerät " + unit + ")"};
}

} // namespace

Description describeRtu(std::span<const std::uint8_t> adu, const DescribeOptions &o)
{
    Description d;
    d.protocol = "modbus-rtu";
    Rows rows{d.fields};
    ByteReader r(adu);
    const std::uint8_t unit = r.u8();
    if (!r.failed())
        rows.add("unit", 0, 1, std::to_string(unit),
                 {"unit id (module address; E22 on RS485)",
                  "Geräteadresse (Moduladresse; E22 bei RS485)"});
    const auto length = rtuFrameLength(adu, o.direction);
    const bool framed = length && *length >= kRtuOverhead + 2 && *length <= adu.size();
    const std::size_t pduEnd = framed ? *length - 2 : adu.size();
    if (adu.size() > 1)
        pduRows(rows, adu.subspan(1, pduEnd - 1), 1, o);
    if (framed) {
        ByteReader c(adu);
        c.skip(*length - 2);
        const std::uint16_t got = c.u16le();
        const std::uint16_t want = crc16(adu.first(*length - 2));
        rows.add(
            "crc", *length - 2, 2, hexWord(got),
            got == want
                ? LocalText{"CRC-16/MODBUS (low byte first): correct",
                            "CRC-16/MODBUS (Low-Byte zuerst): korrekt"}
                : LocalText{"CRC-16/MODBUS (low byte first): wrong, expected " + hexWord(want),
                            "CRC-16/MODBUS (Low-Byte zuerst): falsch, erwartet " + hexWord(want)});
        if (adu.size() > *length)
            rows.add("extra", *length, adu.size() - *length, std::to_string(adu.size() - *length),
                     {"bytes after the end of the frame", "Bytes nach dem Ende des Telegramms"});
    }
    if (o.direction == Direction::Request) {
        auto q = decodeRtuRequest(adu);
        finish(d, q.ok() ? std::nullopt : std::optional(q.error()),
               q.ok() ? pduSummary(q->pdu) : LocalText{}, std::to_string(unit));
    } else {
        auto a = decodeRtuResponse(adu);
        finish(d, a.ok() ? std::nullopt : std::optional(a.error()),
               a.ok() ? pduSummary(a->pdu, o.family) : LocalText{}, std::to_string(unit));
    }
    return d;
}

Description describeTcp(std::span<const std::uint8_t> adu, const DescribeOptions &o)
{
    Description d;
    d.protocol = "modbus-tcp";
    Rows rows{d.fields};
    ByteReader r(adu);
    const std::uint16_t transaction = r.u16be();
    if (!r.failed())
        rows.add("mbap.transaction", 0, 2, std::to_string(transaction),
                 {"transaction identifier (pairs request and response)",
                  "Transaktionskennung (ordnet Antwort und Anfrage zu)"});
    const std::uint16_t protocol = r.u16be();
    if (!r.failed())
        rows.add("mbap.protocol", 2, 2, std::to_string(protocol),
                 protocol == 0
                     ? LocalText{"protocol identifier: 0 = Modbus", "Protokollkennung: 0 = Modbus"}
                     : LocalText{"protocol identifier: not Modbus (must be 0)",
                                 "Protokollkennung: nicht Modbus (muss 0 sein)"});
    const std::uint16_t length = r.u16be();
    if (!r.failed())
        rows.add("mbap.length", 4, 2, std::to_string(length),
                 {"length: bytes that follow (unit id + PDU)",
                  "Länge: folgende Bytes (Geräteadresse + PDU)"});
    const std::uint8_t unit = r.u8();
    if (!r.failed())
        rows.add("mbap.unit", 6, 1, std::to_string(unit),
                 {"unit identifier (module address behind the gateway)",
                  "Geräteadresse (Modul hinter dem Gateway)"});
    if (adu.size() > kMbapSize) {
        const std::size_t end = length >= 1 && 6u + length <= adu.size() ? 6u + length : adu.size();
        if (end > kMbapSize)
            pduRows(rows, adu.subspan(kMbapSize, end - kMbapSize), kMbapSize, o);
        if (end < adu.size())
            rows.add("extra", end, adu.size() - end, std::to_string(adu.size() - end),
                     {"bytes after the end of the ADU", "Bytes nach dem Ende des Telegramms"});
    }
    if (o.direction == Direction::Request) {
        auto q = decodeTcpRequest(adu);
        finish(d, q.ok() ? std::nullopt : std::optional(q.error()),
               q.ok() ? pduSummary(q->pdu) : LocalText{}, std::to_string(unit));
    } else {
        auto a = decodeTcpResponse(adu);
        finish(d, a.ok() ? std::nullopt : std::optional(a.error()),
               a.ok() ? pduSummary(a->pdu, o.family) : LocalText{}, std::to_string(unit));
    }
    return d;
}

} // namespace vt::dev::modbus
