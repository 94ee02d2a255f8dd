// CMD 15 rows for hcs::describe(): module data, control bytes, status words and what VALUE1 /
// VALUE2 mean for the software version and mode (profiles.h).
#include "cmd15.h"
#include "core/decimal_text.h"
#include "core/hex.h"
#include "describe_rows.h"
#include "status_bits.h"

#include <algorithm>
#include <string>

namespace vt::dev::hcs::detail {
namespace {

const LocalText kReservedHere{"not applicable in this version/mode, reserved",
                              "in diesem Modus nicht verfügbar, reserviert"};

// The worked examples of OPAT manual §3.4 and the DMA manuals §4.4 print status 0x40 00 as
// "Hardware Enable is active"; every bit table, parameter 0xB0 and the PLC recordings of OPAT
// manual §4.2 (2#0000_0100) and §5.6 (0x04, 0x0C) put HW_ENABLE at 0x04.
const LocalText kStat5Note{
    "reserved; the manuals' CMD 15 examples print 0x40 for \"hardware enable active\", but the bit "
    "tables, parameter 0xB0 "
    "and the recorded telegrams (OPAT manual §4.2, §5.6) use 0x04 (HW_ENABLE)",
    "reserviert; die CMD-15-Beispiele der Anleitungen zeigen 0x40 für „Hardware Enable ist aktiv“, "
    "die Bittabellen, "
    "Parameter 0xB0 und die aufgezeichneten Telegramme (OPAT manual §4.2, §5.6) verwenden 0x04 "
    "(HW_ENABLE)"};

const ProfileInfo &chosen(const DescribeOptions &o)
{
    return profileInfo(o.profile.value_or(defaultProfile(o.family)));
}

void profileRow(Rows &rows, const DescribeOptions &o)
{
    const ProfileInfo &info = chosen(o);
    LocalText text =
        o.profile
            ? join({"CMD 15 layout", "CMD 15 Belegung"}, info.title)
            : join({"CMD 15 layout assumed (no software version / mode given)",
                    "CMD 15 Belegung angenommen (keine Software-Version / kein Modus angegeben)"},
                   info.title);
    text = {text.en + " — " + std::string(info.source), text.de + " — " + std::string(info.source)};
    if (info.family != o.family)
        text = join(text,
                    {"this layout belongs to the other device family",
                     "diese Belegung gehört zur anderen Gerätefamilie"},
                    "; ");
    rows.add("profile", 0, 0, 0, std::string(info.key), text);
}

LocalText cooked(std::int16_t v, ValueUnit unit)
{
    return formatScaled(v, 3, unit == ValueUnit::Milliampere ? "A" : "V");
}

LocalText valueText(const char *slot, const ValueMeaning &m, std::int16_t v)
{
    const std::string head = std::string(slot) + " = " + std::string(m.parameter) + " ";
    const LocalText c = cooked(v, m.unit);
    return {head + m.text.en + ": " + c.en, head + m.text.de + ": " + c.de};
}

void bitRows(Rows &rows, const std::string &prefix, std::size_t offset, int depth,
             std::uint8_t value, const std::array<BitMeaning, 8> &bits, bool stat5Note)
{
    for (const BitMeaning &b : bits) {
        if ((value & b.mask) == 0)
            continue;
        LocalText text = b.text;
        if (stat5Note && b.mask == 0x40 && !b.used)
            text = kStat5Note;
        else if (!b.used)
            text = join(text, kReservedHere, "; ");
        rows.add(prefix + std::string(b.name), offset, 1, depth, hexByte(b.mask), text);
    }
}

} // namespace

bool describeCyclicRequest(Rows &rows, ByteReader &r, std::uint8_t snum, const DescribeOptions &o)
{
    profileRow(rows, o);
    const ProfileInfo &info = chosen(o);
    const auto modules = modulesForSnum(o.family, snum);
    if (!modules)
        return false;
    for (std::size_t i = 0; i < *modules; ++i) {
        if (r.remaining() < 1)
            return false;
        const std::string addr = std::to_string(moduleAddress(o.family, i));
        const std::string base = "DAT" + addr;
        const std::size_t at = r.offset();
        rows.add(base, at, std::min(kCyclicModuleSize, r.remaining()), 0, {},
                 {"data for the module with SADR " + addr, "Daten für das Modul mit SADR " + addr});
        const std::uint8_t control = r.u8();
        const LocalText head{"control byte (byte for special functions)",
                             "Steuer-Byte (Byte für spezielle Funktionen)"};
        rows.add(base + ".1", at, 1, 1, hexByte(control),
                 control == 0 ? join(head, {"no bit set", "kein Bit gesetzt"}) : head);
        bitRows(rows, base + ".1.", at, 2, control, controlBits(info.profile), false);
        if (r.remaining() < 2)
            return false;
        const std::int16_t v1 = r.i16be();
        rows.add(base + ".2", at + 1, 2, 1, std::to_string(v1),
                 valueText("VALUE1", info.request1, v1));
        if (r.remaining() < 2)
            return false;
        const std::int16_t v2 = r.i16be();
        rows.add(base + ".3", at + 3, 2, 1, std::to_string(v2),
                 valueText("VALUE2", info.request2, v2));
    }
    return true;
}

bool describeCyclicResponse(Rows &rows, ByteReader &r, std::uint8_t sadr, const DescribeOptions &o)
{
    profileRow(rows, o);
    const ProfileInfo &info = chosen(o);
    if (r.remaining() < 2)
        return false;
    const std::uint16_t status = r.u16be();
    rows.add("DAT.1", 3, 2, 0, hexWord(status),
             {"status word (module state)", "Statuswort (Slave (Modul) Status)"});
    const auto high = static_cast<std::uint8_t>(status >> 8);
    const auto low = static_cast<std::uint8_t>(status & 0xFF);
    bitRows(rows, "DAT.1H.", 3, 1, high, statusHighBits(info.profile), true);
    const ModuleStatus s = decodeStatus(status);
    if (s.error) {
        const std::string n = std::to_string(s.errorNumber);
        const auto what = errorNumberText(o.family, s.errorNumber);
        rows.add("DAT.1L.error", 4, 1, 1, n,
                 what ? join({"error number " + n, "Fehlernummer " + n}, *what)
                      : LocalText{"error number " + n + " (not in the manual's table)",
                                  "Fehlernummer " + n + " (nicht in der Tabelle der Anleitung)"});
    } else {
        bitRows(rows, "DAT.1L.", 4, 1, low, statusLowBits(info.profile, o.opatPrintedStatusOrder),
                false);
    }
    const std::string from = std::to_string(sadr);
    if (r.remaining() < 2)
        return false;
    const std::int16_t v1 = r.i16be();
    LocalText t1 = valueText("VALUE1", info.response1, v1);
    rows.add("DAT.2", 5, 2, 0, std::to_string(v1),
             join(t1, {"from the module with SADR " + from, "vom Modul mit SADR " + from}, ", "));
    if (r.remaining() < 2)
        return false;
    const std::int16_t v2 = r.i16be();
    LocalText t2 = valueText("VALUE2", info.response2, v2);
    rows.add("DAT.3", 7, 2, 0, std::to_string(v2),
             join(t2, {"from the module with SADR " + from, "vom Modul mit SADR " + from}, ", "));
    return true;
}

} // namespace vt::dev::hcs::detail
