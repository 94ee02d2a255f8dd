#include "describe.h"

#include "core/byte_reader.h"
#include "core/hex.h"
#include "describe_rows.h"
#include "exceptions.h"
#include "node_rules.h"
#include "telegram.h"

#include <string>

namespace vt::dev::hcs {
namespace detail {

LocalText join(const LocalText &a, const LocalText &b, const char *sep)
{
    return {a.en + sep + b.en, a.de + sep + b.de};
}

LocalText sadrText(Family family, std::uint8_t sadr, Direction direction)
{
    const std::string n = std::to_string(sadr);
    const LocalText head = direction == Direction::Request
                               ? LocalText{"slave address", "Slave Adresse"}
                               : LocalText{"slave address of the answering module",
                                           "Adresse des antwortenden Slave (Modul)"};
    if (family == Family::Opat) {
        // OPAT manual §1.4: "the first module — the one with the PROFIBUS interface always must
        // have the SADR = 0".
        if (sadr == 0)
            return join(head, {"OPAT master", "OPAT-Master"});
        return join(head, {"OPAT CAN slave " + n + " (rotary switch)",
                           "OPAT-CAN-Slave " + n + " (Drehschalter)"});
    }
    // DMA Profinet manual §1.5: "In the slave itself the address is set by parameter E22".
    return join(head, {"module with E22 = " + n, "Modul mit E22 = " + n});
}

} // namespace detail

namespace {

using detail::join;
using detail::Rows;

std::string signedText(std::uint16_t raw)
{
    return std::to_string(asSigned(raw));
}

LocalText idText(std::uint16_t id, const DescribeOptions &o)
{
    return o.parameters.idText(id, {"ID", "ID"});
}

LocalText valueText(std::uint16_t id, std::uint16_t raw, bool idKnown, const DescribeOptions &o)
{
    return o.parameters.valueText(id, raw, idKnown);
}

LocalText commandText(std::uint8_t cmd)
{
    switch (cmd) {
    case kCmdRead:
        return {"command 3: read multiple parameters",
                "Befehl: 3 = Lesen mehrerer Parameter durch den Master"};
    case kCmdWrite:
        return {"command 6: write a single parameter",
                "Befehl: 6 = Schreiben eines einzelnen Parameters durch den Master"};
    case kCmdCyclic:
        return {"command 15: write multiple parameters (fast multi-slave command)",
                "Befehl: 15 = Schreiben mehrerer Parameter durch den Master (schneller Multi-Slave "
                "Befehl)"};
    default: return {"unknown command", "unbekannter Befehl"};
    }
}

LocalText errText(std::uint8_t err)
{
    // OPAT manual §2.3 / §2.6 / §3.3: 0x83 = read failed, 0x86 / 0x8F = write failed.
    switch (err & ~kErrorBit) {
    case kCmdRead:
        return {"error code 0x83: read failed (bit 7 of CMD 3 set)",
                "Fehler Code: 0x83 = Lesen fehlgeschlagen (Bit 7 zu Befehl 3 gesetzt)"};
    case kCmdWrite:
        return {"error code 0x86: write failed (bit 7 of CMD 6 set)",
                "Fehler Code: 0x86 = Schreiben fehlgeschlagen (Bit 7 zu Befehl 6 gesetzt)"};
    case kCmdCyclic:
        return {"error code 0x8F: write failed (bit 7 of CMD 15 set)",
                "Fehler Code: 0x8F = Schreiben fehlgeschlagen (Bit 7 zu Befehl 15 gesetzt)"};
    default:
        return {"error response to an unknown command",
                "Fehlerantwort auf einen unbekannten Befehl"};
    }
}

// Rows after the header. Each returns false when the frame ends inside the telegram.
bool readRequestRows(Rows &rows, ByteReader &r, const DescribeOptions &o)
{
    if (r.remaining() < 2)
        return false;
    const std::uint16_t id = r.u16be();
    rows.add("ID", 3, 2, 0, hexWord(id),
             join({"parameter ID of the first parameter", "Parameter-ID des ersten Parameters"},
                  idText(id, o)));
    if (r.remaining() < 2)
        return false;
    const std::uint16_t n = r.u16be();
    rows.add("N", 5, 2, 0, std::to_string(n),
             {"number of parameters (words), 1..8", "Anzahl der Parameter (Wörter), 1..8"});
    return true;
}

bool readResponseRows(Rows &rows, ByteReader &r, const DescribeOptions &o)
{
    if (r.remaining() < 1)
        return false;
    const std::uint8_t cnt = r.u8();
    rows.add("CNT", 3, 1, 0, std::to_string(cnt),
             {"number of data bytes (N × 2)", "Anzahl der Daten Bytes (N*2)"});
    for (unsigned i = 0; i < cnt / 2u; ++i) {
        if (r.remaining() < 2)
            return false;
        const std::size_t at = r.offset();
        const std::uint16_t raw = r.u16be();
        const std::string n = std::to_string(i + 1);
        LocalText text{"value of parameter " + n, "Wert des " + n + ". Parameters"};
        const bool idKnown = o.firstId.has_value() && *o.firstId + i <= 0xFFFFu;
        const auto id = static_cast<std::uint16_t>(o.firstId.value_or(0) + i);
        if (idKnown)
            text = join(text, idText(id, o));
        rows.add("DAT" + n, at, 2, 0, signedText(raw),
                 join(text, valueText(id, raw, idKnown, o), ", "));
    }
    return cnt % 2 == 0; // an odd CNT is a BadLength error, not a complete telegram
}

bool writeRows(Rows &rows, ByteReader &r, const DescribeOptions &o)
{
    if (r.remaining() < 2)
        return false;
    const std::uint16_t id = r.u16be();
    rows.add("ID", 3, 2, 0, hexWord(id), join({"parameter ID", "Parameter-ID"}, idText(id, o)));
    if (r.remaining() < 2)
        return false;
    const std::uint16_t raw = r.u16be();
    // The manuals' examples label byte 5 "DATL" and byte 6 "DATH"; the value is big-endian
    // (0x03 0xE8 = 1000), as the tables of §2.4 say (DATH first).
    rows.add("DAT", 5, 2, 0, signedText(raw),
             join({"parameter value", "Parameter Wert"}, valueText(id, raw, true, o), ", "));
    return true;
}

bool exceptionRows(Rows &rows, ByteReader &r, std::uint8_t err, const DescribeOptions &o)
{
    if (r.remaining() < 1)
        return false;
    const std::uint8_t code = r.u8();
    rows.add(
        "EXCE", 3, 1, 0, std::to_string(code),
        join({"exception", "Ausnahme"},
             exceptionTextOrUnknown(o.family, static_cast<std::uint8_t>(err & ~kErrorBit), code)));
    return true;
}

LocalText summaryOf(const Request &q)
{
    if (const auto *a = std::get_if<ReadRequest>(&q)) {
        const std::string s = "SADR " + std::to_string(a->sadr) + ", " + std::to_string(a->count);
        return {"CMD 3 read request: " + s + " parameter(s) from ID " + hexWord(a->firstId),
                "CMD 3 Leseauftrag: " + s + " Parameter ab ID " + hexWord(a->firstId)};
    }
    if (const auto *w = std::get_if<WriteRequest>(&q)) {
        const std::string s = "SADR " + std::to_string(w->sadr) + ", ID " + hexWord(w->id) + " = " +
                              signedText(w->value);
        return {"CMD 6 write request: " + s, "CMD 6 Schreibauftrag: " + s};
    }
    const auto &c = std::get<CyclicRequest>(q);
    const std::string n = std::to_string(c.modules.size());
    return {"CMD 15 request: set values for " + n + " module(s)",
            "CMD 15 Auftrag: Sollwerte für " + n + " Modul(e)"};
}

LocalText summaryOf(const Response &a, Family family)
{
    if (const auto *r = std::get_if<ReadResponse>(&a)) {
        const std::string s =
            "SADR " + std::to_string(r->sadr) + ", " + std::to_string(r->values.size());
        return {"CMD 3 response: " + s + " value(s)", "CMD 3 Antwort: " + s + " Wert(e)"};
    }
    if (const auto *w = std::get_if<WriteResponse>(&a)) {
        const std::string s = "SADR " + std::to_string(w->sadr) + ", ID " + hexWord(w->id) + " = " +
                              signedText(w->value);
        return {"CMD 6 response: " + s, "CMD 6 Antwort: " + s};
    }
    if (const auto *c = std::get_if<CyclicResponse>(&a)) {
        const std::string s = "SADR " + std::to_string(c->sadr) + ", status " + hexWord(c->status) +
                              ", VALUE1 " + std::to_string(c->value1) + ", VALUE2 " +
                              std::to_string(c->value2);
        return {"CMD 15 response: " + s, "CMD 15 Antwort: " + s};
    }
    const auto &e = std::get<ExceptionResponse>(a);
    const LocalText what = exceptionTextOrUnknown(family, e.command, e.code);
    const std::string s = std::to_string(e.command) + " (SADR " + std::to_string(e.sadr) +
                          "): EXCE " + std::to_string(e.code) + " ";
    return {"error response to CMD " + s + what.en, "Fehlerantwort auf CMD " + s + what.de};
}

void addNotes(Rows &rows, const std::vector<LocalText> &notes)
{
    for (const LocalText &n : notes)
        rows.add("note", 0, 0, 0, {}, n);
}

} // namespace

Description describe(std::span<const std::uint8_t> frame, const DescribeOptions &o)
{
    Description d;
    d.protocol = "gateway";
    Rows rows{d.fields};
    const DecodeOptions dop{o.family, o.allowPadding};
    const bool request = o.direction == Direction::Request;

    ByteReader r(frame);
    const std::size_t have = frame.size();
    const std::uint8_t tadr = r.u8();
    const std::uint8_t second = r.u8();
    const std::uint8_t cmd = r.u8();
    if (have >= 1)
        rows.add(
            "TADR", 0, 1, 0, hexByte(tadr),
            request
                ? LocalText{"telegram address, set by the PLC (a changed TADR forces a new answer)",
                            "Telegrammadresse, durch den Anwender vorzugeben (eine geänderte TADR "
                            "erzwingt eine neue Antwort)"}
                : LocalText{"telegram address, echoed from the request",
                            "Telegrammadresse, durch den Befehl vorgegeben"});
    const bool snum = request && have >= 3 && cmd == kCmdCyclic;
    if (have >= 2 && !snum)
        rows.add("SADR", 1, 1, 0, std::to_string(second),
                 detail::sadrText(o.family, second, o.direction));
    if (snum) {
        const std::string n = std::to_string(second);
        rows.add("SNUM", 1, 1, 0, n,
                 o.family == Family::Opat
                     ? LocalText{"number of connected OPAT slaves: " + n +
                                     " (the master, SADR 0, is always included)",
                                 "Anzahl der angeschlossenen OPAT-Slaves: " + n +
                                     " (der Master, SADR 0, ist immer enthalten)"}
                     : LocalText{"number of connected slaves (modules): " + n,
                                 "Anzahl der angeschlossenen Slaves (Module): " + n});
    }

    bool complete = false;
    if (have >= 3) {
        const bool isError = !request && (cmd & kErrorBit) != 0;
        rows.add(isError ? "ERR" : "CMD", 2, 1, 0, hexByte(cmd),
                 isError ? errText(cmd) : commandText(cmd));
        if (isError)
            complete = exceptionRows(rows, r, cmd, o);
        else if (cmd == kCmdRead)
            complete = request ? readRequestRows(rows, r, o) : readResponseRows(rows, r, o);
        else if (cmd == kCmdWrite)
            complete = writeRows(rows, r, o);
        else if (cmd == kCmdCyclic)
            complete = request ? detail::describeCyclicRequest(rows, r, second, o)
                               : detail::describeCyclicResponse(rows, r, second, o);
    }
    if (complete && !r.atEnd()) {
        const std::size_t extra = have - r.offset();
        if (o.allowPadding)
            rows.add("padding", r.offset(), extra, 0, std::to_string(extra),
                     {"process image bytes after the telegram (ignored)",
                      "Bytes des Prozessabbilds nach dem Telegramm (ignoriert)"});
        else
            rows.add("extra", r.offset(), extra, 0, std::to_string(extra),
                     {"bytes after the end of the telegram", "Bytes nach dem Ende des Telegramms"});
    }

    if (request) {
        auto q = decodeRequest(frame, dop);
        if (q.ok()) {
            addNotes(rows, nodeRuleNotes(*q, o.family));
            d.summary = summaryOf(*q);
        } else {
            d.error = q.error();
        }
    } else {
        auto a = decodeResponse(frame, dop);
        if (a.ok()) {
            addNotes(rows, nodeRuleNotes(*a, o.family));
            d.summary = summaryOf(*a, o.family);
        } else {
            d.error = a.error();
        }
    }
    if (d.error) {
        const LocalText why = describeError(*d.error);
        d.summary = {"invalid HCS telegram: " + why.en, "ungültiges HCS-Telegramm: " + why.de};
    }
    return d;
}

LocalText ParameterHooks::idText(std::uint16_t id, const LocalText &prefix) const
{
    LocalText t{prefix.en + " " + hexWord(id), prefix.de + " " + hexWord(id)};
    if (name)
        if (auto n = name(id))
            t = {t.en + " (" + n->en + ")", t.de + " (" + n->de + ")"};
    return t;
}

LocalText ParameterHooks::valueText(std::uint16_t id, std::uint16_t raw, bool idKnown) const
{
    LocalText t{hexWord(raw), hexWord(raw)};
    if (idKnown && cook)
        if (auto cooked = cook(id, raw))
            t = {cooked->en + ", " + t.en, cooked->de + ", " + t.de};
    return t;
}

} // namespace vt::dev::hcs
