#include "describe.h"

#include "core/byte_reader.h"
#include "core/decimal_text.h"
#include "core/hex.h"
#include "hcs/status_bits.h"
#include "mixed.h"
#include "stw1_zsw1.h"
#include "telegram1.h"

#include <string>

namespace vt::dev::profidrive {
namespace {

void add(std::vector<FieldSpan> &out, std::string key, std::size_t offset, std::size_t length,
         int depth, std::string value, LocalText text)
{
    out.push_back(
        FieldSpan{std::move(key), offset, length, depth, std::move(value), std::move(text)});
}

LocalText join(const LocalText &a, const LocalText &b, const char *sep = ": ")
{
    return {a.en + sep + b.en, a.de + sep + b.de};
}

// One row per bit: the standard bits 0..10 always (their 0 has a meaning too: OFF2 active, …),
// device-specific ones only when set.
void wordBits(std::vector<FieldSpan> &out, const std::string &prefix, std::size_t offset,
              std::uint16_t word, std::span<const WordBit> bits)
{
    for (std::size_t i = 0; i < bits.size(); ++i) {
        const WordBit &b = bits[i];
        const bool set = (word & b.mask) != 0;
        if (!set && (b.deviceSpecific || b.whenClear.en.empty()))
            continue;
        // Bits 8..15 are in the first (high) byte of the big-endian word.
        const std::size_t at = i >= 8 ? offset : offset + 1;
        LocalText text = set ? b.whenSet : b.whenClear;
        if (!b.used)
            text = join(text, {"unexpected", "unerwartet"}, " — ");
        add(out, prefix + std::string(b.name), at, 1, 1, set ? "1" : "0",
            join({"bit " + std::to_string(i), "Bit " + std::to_string(i)}, text));
    }
}

LocalText n2Text(std::int16_t n2, double voltsAt100)
{
    const LocalText pct = formatDecimal(n2ToPercent(n2), 2, "%");
    const LocalText volts = formatDecimal(n2ToVolts(n2, voltsAt100), 3, "V");
    return {"N2 " + hexWord(static_cast<std::uint16_t>(n2)) + " = " + pct.en + " = " + volts.en,
            "N2 " + hexWord(static_cast<std::uint16_t>(n2)) + " = " + pct.de + " = " + volts.de};
}

// Rows for the 4 PROFIdrive bytes; returns false when they are not all there.
bool driveRows(std::vector<FieldSpan> &out, std::span<const std::uint8_t> bytes,
               const DescribeOptions &o)
{
    ByteReader r(bytes);
    const bool request = o.direction == Direction::Request;
    if (r.remaining() < 2)
        return false;
    const std::uint16_t word = r.u16be();
    if (request) {
        add(out, "STW1", 0, 2, 0, hexWord(word), {"control word 1 (STW1)", "Steuerwort 1 (STW1)"});
        wordBits(out, "STW1.", 0, word, stw1Bits());
        if ((word & stw1::kOpatRun) != stw1::kOpatRun)
            add(out, "note", 0, 0, 0, {},
                {"the OPAT uses the set value only with bits 0..6 and 10 set (0x047F; OPAT manual "
                 "§5.2.1)",
                 "der OPAT verwendet den Sollwert nur mit gesetzten Bits 0..6 und 10 (0x047F; OPAT "
                 "manual §5.2.1)"});
    } else {
        add(out, "ZSW1", 0, 2, 0, hexWord(word), {"status word 1 (ZSW1)", "Zustandswort 1 (ZSW1)"});
        wordBits(out, "ZSW1.", 0, word, zsw1Bits());
    }
    if (r.remaining() < 2)
        return false;
    const std::int16_t value = r.i16be();
    if (request) {
        add(out, "NSOLL_A", 2, 2, 0, std::to_string(value),
            join({"speed set point NSOLL_A = OPAT set value",
                  "Drehzahlsollwert NSOLL_A = OPAT-Sollwert"},
                 n2Text(value, o.voltsAt100Percent)));
    } else if ((word & zsw1::kFault) != 0) {
        // OPAT manual §5.4.1: "BIT3 = 1 = OPAT error appeared, the error number is shown in the
        // NIST1 value".
        const auto number = static_cast<std::uint8_t>(value & 0xFF);
        const auto what = value >= 0 && value <= 0xFF
                              ? hcs::errorNumberText(hcs::Family::Opat, number)
                              : std::nullopt;
        add(out, "NIST_A", 2, 2, 0, std::to_string(value),
            join({"NIST_A = OPAT error number " + std::to_string(value) + " (ZSW1 bit 3 set)",
                  "NIST_A = OPAT-Fehlernummer " + std::to_string(value) + " (ZSW1 Bit 3 gesetzt)"},
                 what.value_or(LocalText{"not in the ERR table (ID 0x102)",
                                         "nicht in der ERR-Tabelle (ID 0x102)"})));
    } else {
        add(out, "NIST_A", 2, 2, 0, std::to_string(value),
            join({"actual value NIST_A = d1.11 feedback value",
                  "Istwert NIST_A = d1.11 Istwert, Regelgröße"},
                 n2Text(value, o.voltsAt100Percent)));
    }
    return true;
}

} // namespace

Description describe(std::span<const std::uint8_t> bytes, const DescribeOptions &o)
{
    Description d;
    d.protocol = "profidrive";
    const bool mixed = o.layout == Layout::MixedCmd15 ||
                       (o.layout == Layout::Auto && bytes.size() > kTelegram1Size);
    const bool request = o.direction == Direction::Request;
    const bool complete = driveRows(d.fields, bytes, o);

    if (!mixed) {
        if (request) {
            auto s = decodeSetpoint(bytes);
            if (s.ok())
                d.summary = {"telegram 1: STW1 " + hexWord(s->stw1) + ", NSOLL_A " +
                                 std::to_string(s->nsollA),
                             "Telegramm 1: STW1 " + hexWord(s->stw1) + ", NSOLL_A " +
                                 std::to_string(s->nsollA)};
            else
                d.error = s.error();
        } else {
            auto a = decodeActual(bytes);
            if (a.ok())
                d.summary = {"telegram 1: ZSW1 " + hexWord(a->zsw1) + ", NIST_A " +
                                 std::to_string(a->nistA),
                             "Telegramm 1: ZSW1 " + hexWord(a->zsw1) + ", NIST_A " +
                                 std::to_string(a->nistA)};
            else
                d.error = a.error();
        }
        if (complete && bytes.size() > kTelegram1Size)
            add(d.fields, "extra", kTelegram1Size, bytes.size() - kTelegram1Size, 0,
                std::to_string(bytes.size() - kTelegram1Size),
                {"bytes after telegram 1", "Bytes nach Telegramm 1"});
    } else {
        if (complete) {
            add(d.fields, "cmd15", kTelegram1Size, bytes.size() - kTelegram1Size, 0, {},
                {"CMD 15 telegram for the node (OPAT manual §5.6)",
                 "CMD-15-Telegramm für den Knoten (OPAT manual §5.6)"});
            hcs::DescribeOptions node = o.node;
            node.direction = o.direction;
            const Description inner = hcs::describe(bytes.subspan(kTelegram1Size), node);
            for (FieldSpan f : inner.fields) {
                f.offset +=
                    kTelegram1Size; // explanatory rows (length 0) point at the CMD 15 part too
                f.depth += 1;
                d.fields.push_back(std::move(f));
            }
        }
        const hcs::DecodeOptions dop{o.node.family, o.node.allowPadding};
        if (request) {
            auto m = decodeMixedRequest(bytes, dop);
            if (m.ok())
                d.summary = {"telegram 1 STW1 " + hexWord(m->drive.stw1) + " + CMD 15 for " +
                                 std::to_string(m->node.modules.size()) + " module(s)",
                             "Telegramm 1 STW1 " + hexWord(m->drive.stw1) + " + CMD 15 für " +
                                 std::to_string(m->node.modules.size()) + " Modul(e)"};
            else
                d.error = m.error();
        } else {
            auto m = decodeMixedResponse(bytes, dop);
            if (m.ok())
                d.summary = {"telegram 1 ZSW1 " + hexWord(m->drive.zsw1) + " + CMD 15 response",
                             "Telegramm 1 ZSW1 " + hexWord(m->drive.zsw1) + " + CMD 15 Antwort"};
            else
                d.error = m.error();
        }
    }
    if (d.error) {
        const LocalText why = describeError(*d.error);
        d.summary = {"invalid PROFIdrive image: " + why.en,
                     "ungültiges PROFIdrive-Abbild: " + why.de};
    }
    return d;
}

} // namespace vt::dev::profidrive
