#include "exceptions.h"

#include "hcs/exceptions.h"

#include <array>
#include <string>

namespace vt::dev::modbus {
namespace {

struct Named
{
    std::uint8_t code;
    LocalText text;
};

const std::array<Named, 9> kNames{{
    {1, {"illegal function", "unzulässige Funktion"}},
    {2, {"illegal data address", "unzulässige Datenadresse"}},
    {3, {"illegal data value", "unzulässiger Datenwert"}},
    {4, {"server device failure", "Fehler im Slave-Gerät"}},
    {5,
     {"acknowledge (request accepted, processing takes long)",
      "Bestätigung (Auftrag angenommen, Bearbeitung dauert)"}},
    {6, {"server device busy", "Slave-Gerät beschäftigt"}},
    {8, {"memory parity error", "Speicher-Paritätsfehler"}},
    {10, {"gateway path unavailable", "Gateway-Pfad nicht verfügbar"}},
    {11,
     {"gateway target device failed to respond", "Zielgerät hinter dem Gateway antwortet nicht"}},
}};

} // namespace

std::optional<LocalText> exceptionName(std::uint8_t code)
{
    for (const Named &n : kNames)
        if (n.code == code)
            return n.text;
    return std::nullopt;
}

std::optional<LocalText> hcsMeaning(std::uint8_t function, std::uint8_t code, hcs::Family family)
{
    return hcs::exceptionText(family, function, code);
}

LocalText exceptionText(std::uint8_t function, std::uint8_t code, hcs::Family family)
{
    const std::string n = std::to_string(code);
    LocalText out = exceptionName(code).value_or(LocalText{
        "exception " + n + " (not a standard code)", "Ausnahme " + n + " (kein Standardcode)"});
    if (auto hcs = hcsMeaning(function, code, family)) {
        out.en += " — HCS: " + hcs->en;
        out.de += " — HCS: " + hcs->de;
    }
    return out;
}

} // namespace vt::dev::modbus
