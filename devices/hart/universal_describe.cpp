// Field descriptions of the universal command payloads, one layout table per command and
// direction after the HART-7 manual §5.1 (byte numbers there = offsets here).
#include "core/byte_reader.h"
#include "core/hex.h"
#include "hart/texts.h"
#include "hart/universal.h"

#include <string>

namespace vt::dev::hart {
namespace {

enum class Kind { U8, Hex8, U16, Hex16, U24, U32, F32, Unit, Packed, Latin1, Date, Raw, HwRev };

struct Spec
{
    std::string key;
    Kind kind;
    std::size_t size; // for Packed, Latin1, Raw
    LocalText text;
};

std::size_t sizeOf(const Spec &s)
{
    switch (s.kind) {
    case Kind::U8:
    case Kind::Hex8:
    case Kind::Unit:
    case Kind::HwRev: return 1;
    case Kind::U16:
    case Kind::Hex16: return 2;
    case Kind::U24:
    case Kind::Date: return 3;
    case Kind::U32:
    case Kind::F32: return 4;
    case Kind::Packed:
    case Kind::Latin1:
    case Kind::Raw: return s.size;
    }
    return 1;
}

std::string valueOf(const Spec &s, std::span<const std::uint8_t> b)
{
    ByteReader r(b);
    switch (s.kind) {
    case Kind::U8: return std::to_string(r.u8());
    case Kind::Hex8: return hexByte(r.u8());
    case Kind::U16: return std::to_string(r.u16be());
    case Kind::Hex16: return hexWord(r.u16be());
    case Kind::U24: {
        const std::uint32_t high = r.u8();
        return std::to_string(high << 16 | r.u16be());
    }
    case Kind::U32: return std::to_string(r.u32be());
    case Kind::F32: return formatFloat(floatFromBits(r.u32be()));
    case Kind::Unit: {
        const std::uint8_t u = r.u8();
        const std::string sym = unitSymbol(u);
        return sym.empty() ? std::to_string(u) : std::to_string(u) + " (" + sym + ")";
    }
    case Kind::Packed: return "\"" + unpackAscii(b) + "\"";
    case Kind::Latin1: return "\"" + latin1ToUtf8(b) + "\"";
    case Kind::Date: {
        Date d;
        d.day = r.u8();
        d.month = r.u8();
        d.yearSince1900 = r.u8();
        return formatDate(d);
    }
    case Kind::Raw: return toHex(b);
    case Kind::HwRev: {
        const std::uint8_t v = r.u8();
        return std::to_string(v >> 3) + " / " + std::to_string(v & 0x07);
    }
    }
    return {};
}

using Layout = std::vector<Spec>;

const Layout &identityLayout()
{
    static const Layout l{
        {"expansion_code",
         Kind::U8,
         0,
         {"device type code for expansion (254)", "Gerätetyp-Erweiterungscode (254)"}},
        {"expanded_device_type", Kind::Hex16, 0, {"expanded device type", "erweiterter Gerätetyp"}},
        {"min_request_preambles",
         Kind::U8,
         0,
         {"minimum number of request preambles", "Mindestanzahl Präambeln der Anfrage"}},
        {"hart_revision",
         Kind::U8,
         0,
         {"HART protocol major revision", "HART-Protokoll-Hauptversion"}},
        {"device_revision", Kind::U8, 0, {"device revision level", "Geräterevision"}},
        {"software_revision", Kind::U8, 0, {"software revision level", "Softwarerevision"}},
        {"hardware_revision",
         Kind::HwRev,
         0,
         {"hardware revision / physical signaling code",
          "Hardwarerevision / Code der physikalischen Signalisierung"}},
        {"flags", Kind::Hex8, 0, {"flags", "Flags"}},
        {"device_id", Kind::U24, 0, {"device identification", "Gerätekennung"}},
        {"min_response_preambles",
         Kind::U8,
         0,
         {"minimum number of response preambles", "Mindestanzahl Präambeln der Antwort"}},
        {"max_device_variables",
         Kind::U8,
         0,
         {"maximum number of device variables", "Höchstzahl der Gerätevariablen"}},
        {"config_change_counter",
         Kind::U16,
         0,
         {"configuration change counter", "Konfigurationsänderungszähler"}},
        {"extended_status",
         Kind::Hex8,
         0,
         {"extended field device status", "erweiterter Feldgerätestatus"}},
        {"manufacturer_id",
         Kind::U16,
         0,
         {"manufacturer identification code", "Herstellerkennung"}},
        {"private_label",
         Kind::U16,
         0,
         {"private label distributor code", "Kennung des Vertriebspartners"}},
        {"device_profile", Kind::U8, 0, {"device profile", "Geräteprofil"}},
    };
    return l;
}

Spec unitSpec(const std::string &key, const std::string &en, const std::string &de)
{
    return {key + "_unit", Kind::Unit, 0, {en + " unit code", "Einheitencode " + de}};
}

Spec floatSpec(const std::string &key, const std::string &en, const std::string &de)
{
    return {key, Kind::F32, 0, {en, de}};
}

Layout fixedLayout(std::uint8_t command, bool response)
{
    const Spec tag{"tag", Kind::Packed, 6, {"tag (packed ASCII)", "Tag (Packed ASCII)"}};
    const Spec message{
        "message", Kind::Packed, 24, {"message (packed ASCII)", "Nachricht (Packed ASCII)"}};
    const Spec longTag{
        "long_tag", Kind::Latin1, 32, {"long tag (ISO Latin-1)", "langer Tag (ISO Latin-1)"}};
    const Spec fan{
        "final_assembly_number", Kind::U24, 0, {"final assembly number", "Endmontagenummer"}};
    const Layout loopConfig{
        {"poll_address", Kind::U8, 0, {"polling address", "Polling-Adresse"}},
        {"loop_current_mode", Kind::U8, 0, {"loop current mode", "Schleifenstrommodus"}},
    };
    const Layout tdd{
        tag,
        {"descriptor",
         Kind::Packed,
         12,
         {"descriptor (packed ASCII)", "Beschreibung (Packed ASCII)"}},
        {"date", Kind::Date, 0, {"date (day, month, year)", "Datum (Tag, Monat, Jahr)"}}};
    switch (command) {
    case 0: return response ? identityLayout() : Layout{};
    case 11: return response ? identityLayout() : Layout{tag};
    case 21: return response ? identityLayout() : Layout{longTag};
    case 1:
        if (!response)
            return {};
        return {unitSpec("pv", "primary variable", "Primärvariable"),
                floatSpec("pv", "primary variable (actual value)", "Primärvariable (Istwert)")};
    case 2:
        if (!response)
            return {};
        return {floatSpec("loop_current", "loop current (mA)", "Schleifenstrom (mA)"),
                floatSpec("percent_of_range", "percent of range", "Prozent des Messbereichs")};
    case 6: return loopConfig;
    case 7: return response ? loopConfig : Layout{};
    case 8:
        if (!response)
            return {};
        return {{"pv_classification",
                 Kind::U8,
                 0,
                 {"primary variable classification", "Klassifizierung Primärvariable"}},
                {"sv_classification",
                 Kind::U8,
                 0,
                 {"secondary variable classification", "Klassifizierung Sekundärvariable"}},
                {"tv_classification",
                 Kind::U8,
                 0,
                 {"tertiary variable classification", "Klassifizierung Tertiärvariable"}},
                {"qv_classification",
                 Kind::U8,
                 0,
                 {"quaternary variable classification", "Klassifizierung Quartärvariable"}}};
    case 12: return response ? Layout{message} : Layout{};
    case 17: return {message};
    case 13: return response ? tdd : Layout{};
    case 18: return tdd;
    case 14:
        if (!response)
            return {};
        return {
            {"transducer_serial",
             Kind::U24,
             0,
             {"transducer serial number", "Seriennummer des Sensors"}},
            {"transducer_unit",
             Kind::Unit,
             0,
             {"transducer limits / minimum span unit code",
              "Einheitencode Sensorgrenzen / Mindestspanne"}},
            floatSpec("upper_transducer_limit", "upper transducer limit", "obere Sensorgrenze"),
            floatSpec("lower_transducer_limit", "lower transducer limit", "untere Sensorgrenze"),
            floatSpec("minimum_span", "minimum span", "Mindestspanne")};
    case 15:
        if (!response)
            return {};
        return {{"alarm_selection", Kind::U8, 0, {"alarm selection code", "Alarmauswahlcode"}},
                {"transfer_function",
                 Kind::U8,
                 0,
                 {"PV transfer function code", "Übertragungsfunktion PV"}},
                {"range_unit",
                 Kind::Unit,
                 0,
                 {"PV range values unit code", "Einheitencode Messbereich PV"}},
                floatSpec("upper_range", "PV upper range value", "oberer Messbereichswert PV"),
                floatSpec("lower_range", "PV lower range value", "unterer Messbereichswert PV"),
                floatSpec("damping", "PV damping value (s)", "Dämpfung PV (s)"),
                {"write_protect", Kind::U8, 0, {"write protect code", "Schreibschutzcode"}},
                {"reserved", Kind::U8, 0, {"reserved (250)", "reserviert (250)"}},
                {"analog_channel_flags",
                 Kind::Hex8,
                 0,
                 {"PV analog channel flags", "Flags des Analogkanals PV"}}};
    case 16: return response ? Layout{fan} : Layout{};
    case 19: return {fan};
    case 20: return response ? Layout{longTag} : Layout{};
    case 22: return {longTag};
    case 38:
        return {{"config_change_counter",
                 Kind::U16,
                 0,
                 {"configuration change counter", "Konfigurationsänderungszähler"}}};
    case 48:
        return {
            {"device_specific_status",
             Kind::Raw,
             6,
             {"device-specific status", "gerätespezifischer Status"}},
            {"extended_status",
             Kind::Hex8,
             0,
             {"extended device status", "erweiterter Gerätestatus"}},
            {"operating_mode", Kind::U8, 0, {"device operating mode", "Betriebsart des Geräts"}},
            {"standardized_status_0",
             Kind::Hex8,
             0,
             {"standardized status 0", "standardisierter Status 0"}},
            {"standardized_status_1",
             Kind::Hex8,
             0,
             {"standardized status 1", "standardisierter Status 1"}},
            {"analog_channel_saturated",
             Kind::Hex8,
             0,
             {"analog channel saturated", "Analogkanal gesättigt"}},
            {"standardized_status_2",
             Kind::Hex8,
             0,
             {"standardized status 2", "standardisierter Status 2"}},
            {"standardized_status_3",
             Kind::Hex8,
             0,
             {"standardized status 3", "standardisierter Status 3"}},
            {"analog_channel_fixed", Kind::Hex8, 0, {"analog channel fixed", "Analogkanal fest"}},
            {"device_specific_status_2",
             Kind::Raw,
             11,
             {"device-specific status", "gerätespezifischer Status"}}};
    default: return {};
    }
}

// Variable layouts: command 3 (up to 4 variables), command 9 (up to 8 slots + time stamp).
Layout variableLayout(std::uint8_t command, bool response, std::size_t size)
{
    Layout l;
    if (command == 3 && response) {
        l.push_back(floatSpec("loop_current", "loop current (mA)", "Schleifenstrom (mA)"));
        const char *names[4][3] = {{"pv", "primary variable", "Primärvariable"},
                                   {"sv", "secondary variable", "Sekundärvariable"},
                                   {"tv", "tertiary variable", "Tertiärvariable"},
                                   {"qv", "quaternary variable", "Quartärvariable"}};
        for (std::size_t i = 0; i < 4 && 4 + 5 * (i + 1) <= size; ++i) {
            l.push_back(unitSpec(names[i][0], names[i][1], names[i][2]));
            l.push_back(floatSpec(names[i][0], names[i][1], names[i][2]));
        }
    } else if (command == 9 && !response) {
        for (std::size_t i = 0; i < 8 && i < size; ++i) {
            const std::string n = std::to_string(i);
            l.push_back({"slot" + n + "_code",
                         Kind::U8,
                         0,
                         {"slot " + n + ": device variable code",
                          "Slot " + n + ": Code der Gerätevariable"}});
        }
    } else if (command == 9) {
        l.push_back({"extended_status",
                     Kind::Hex8,
                     0,
                     {"extended field device status", "erweiterter Feldgerätestatus"}});
        std::size_t i = 0;
        for (; i < 8 && 1 + 8 * (i + 1) <= size; ++i) {
            const std::string n = std::to_string(i);
            const std::string p = "slot" + n;
            const std::string en = "slot " + n + ": ";
            const std::string de = "Slot " + n + ": ";
            l.push_back({p + "_code",
                         Kind::U8,
                         0,
                         {en + "device variable code", de + "Code der Gerätevariable"}});
            l.push_back({p + "_classification",
                         Kind::U8,
                         0,
                         {en + "classification", de + "Klassifizierung"}});
            l.push_back({p + "_unit", Kind::Unit, 0, {en + "unit code", de + "Einheitencode"}});
            l.push_back({p + "_value", Kind::F32, 0, {en + "value", de + "Wert"}});
            l.push_back({p + "_status", Kind::Hex8, 0, {en + "status", de + "Status"}});
        }
        if (1 + 8 * i + 4 <= size)
            l.push_back({"slot0_timestamp",
                         Kind::U32,
                         0,
                         {"slot 0 data time stamp (1/32 ms)", "Zeitstempel Slot 0 (1/32 ms)"}});
    }
    return l;
}

} // namespace

std::optional<DecodeError> describeUniversal(std::uint8_t command, bool response,
                                             std::span<const std::uint8_t> data, std::size_t offset,
                                             int depth, std::vector<FieldSpan> &out)
{
    auto decoded = decodeUniversal(command, response, data);
    const Layout layout = (command == 3 || command == 9)
                              ? variableLayout(command, response, data.size())
                              : fixedLayout(command, response);
    const std::string prefix = "hart.cmd" + std::to_string(command) + ".";
    ByteReader r(data);
    for (const Spec &s : layout) {
        const std::size_t at = r.offset();
        const auto bytes = r.bytes(sizeOf(s));
        if (r.failed())
            break;
        out.push_back(
            {prefix + s.key, offset + at, bytes.size(), depth, valueOf(s, bytes), s.text});
    }
    if (!r.failed() && r.remaining() > 0)
        out.push_back({prefix + "additional",
                       offset + r.offset(),
                       r.remaining(),
                       depth,
                       toHex(r.bytes(r.remaining())),
                       {"additional bytes (not in the manual's layout)",
                        "zusätzliche Bytes (nicht im Layout des Handbuchs)"}});
    if (!decoded.ok()) {
        DecodeError e = decoded.error();
        e.offset += offset;
        return e;
    }
    return std::nullopt;
}

} // namespace vt::dev::hart
