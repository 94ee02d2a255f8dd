// SDO abort codes of CiA 301 (table "SDO abort codes", §7.2.4.3.17), English and German.
#include "canopen/sdo.h"
#include "core/hex.h"

#include <array>
#include <string>
#include <vector>

namespace vt::dev::canopen {
namespace {

struct AbortCode
{
    std::uint32_t code;
    const char *en;
    const char *de;
};

constexpr std::array kAbortCodes{
    AbortCode{0x05030000, "Toggle bit not alternated", "Toggle-Bit nicht gewechselt"},
    AbortCode{0x05040000, "SDO protocol timed out", "Zeitüberschreitung im SDO-Protokoll"},
    AbortCode{0x05040001, "Client/server command specifier not valid or unknown",
              "Client-/Server-Kommandospezifizierer ungültig oder unbekannt"},
    AbortCode{0x05040002, "Invalid block size (block mode only)",
              "Ungültige Blockgröße (nur Blockmodus)"},
    AbortCode{0x05040003, "Invalid sequence number (block mode only)",
              "Ungültige Sequenznummer (nur Blockmodus)"},
    AbortCode{0x05040004, "CRC error (block mode only)", "CRC-Fehler (nur Blockmodus)"},
    AbortCode{0x05040005, "Out of memory", "Kein Speicher mehr verfügbar"},
    AbortCode{0x06010000, "Unsupported access to an object",
              "Nicht unterstützter Zugriff auf ein Objekt"},
    AbortCode{0x06010001, "Attempt to read a write only object",
              "Leseversuch auf ein nur beschreibbares Objekt"},
    AbortCode{0x06010002, "Attempt to write a read only object",
              "Schreibversuch auf ein nur lesbares Objekt"},
    AbortCode{0x06020000, "Object does not exist in the object dictionary",
              "Objekt existiert nicht im Objektverzeichnis"},
    AbortCode{0x06040041, "Object cannot be mapped to the PDO",
              "Objekt kann nicht in das PDO gemappt werden"},
    AbortCode{0x06040042,
              "The number and length of the objects to be mapped would exceed PDO length",
              "Anzahl und Länge der zu mappenden Objekte würden die PDO-Länge überschreiten"},
    AbortCode{0x06040043, "General parameter incompatibility reason",
              "Allgemeine Parameter-Inkompatibilität"},
    AbortCode{0x06040047, "General internal incompatibility in the device",
              "Allgemeine interne Inkompatibilität im Gerät"},
    AbortCode{0x06060000, "Access failed due to a hardware error",
              "Zugriff wegen eines Hardwarefehlers fehlgeschlagen"},
    AbortCode{0x06070010, "Data type does not match, length of service parameter does not match",
              "Datentyp passt nicht, Länge des Dienstparameters passt nicht"},
    AbortCode{0x06070012, "Data type does not match, length of service parameter too high",
              "Datentyp passt nicht, Länge des Dienstparameters zu groß"},
    AbortCode{0x06070013, "Data type does not match, length of service parameter too low",
              "Datentyp passt nicht, Länge des Dienstparameters zu klein"},
    AbortCode{0x06090011, "Sub-index does not exist", "Subindex existiert nicht"},
    AbortCode{0x06090030, "Invalid value for parameter (download only)",
              "Ungültiger Parameterwert (nur Download)"},
    AbortCode{0x06090031, "Value of parameter written too high (download only)",
              "Geschriebener Parameterwert zu groß (nur Download)"},
    AbortCode{0x06090032, "Value of parameter written too low (download only)",
              "Geschriebener Parameterwert zu klein (nur Download)"},
    AbortCode{0x06090036, "Maximum value is less than minimum value",
              "Maximalwert ist kleiner als Minimalwert"},
    AbortCode{0x060A0023, "Resource not available: SDO connection",
              "Ressource nicht verfügbar: SDO-Verbindung"},
    AbortCode{0x08000000, "General error", "Allgemeiner Fehler"},
    AbortCode{0x08000020, "Data cannot be transferred or stored to the application",
              "Daten können nicht zur Anwendung übertragen oder dort gespeichert werden"},
    AbortCode{0x08000021,
              "Data cannot be transferred or stored to the application because of local control",
              "Daten können wegen lokaler Steuerung nicht zur Anwendung übertragen oder dort "
              "gespeichert werden"},
    AbortCode{0x08000022,
              "Data cannot be transferred or stored to the application because of the present "
              "device state",
              "Daten können wegen des aktuellen Gerätezustands nicht zur Anwendung übertragen oder "
              "dort gespeichert werden"},
    AbortCode{0x08000023,
              "Object dictionary dynamic generation fails or no object dictionary is present",
              "Dynamische Erzeugung des Objektverzeichnisses fehlgeschlagen oder kein "
              "Objektverzeichnis vorhanden"},
    AbortCode{0x08000024, "No data available", "Keine Daten verfügbar"},
};

} // namespace

bool isKnownAbortCode(std::uint32_t code)
{
    for (const AbortCode &a : kAbortCodes)
        if (a.code == code)
            return true;
    return false;
}

std::vector<std::uint32_t> knownAbortCodes()
{
    std::vector<std::uint32_t> codes;
    codes.reserve(kAbortCodes.size());
    for (const AbortCode &a : kAbortCodes)
        codes.push_back(a.code);
    return codes;
}

LocalText abortCodeText(std::uint32_t code)
{
    for (const AbortCode &a : kAbortCodes)
        if (a.code == code)
            return {a.en, a.de};
    const std::string hex = hexWord(static_cast<std::uint16_t>(code >> 16)) +
                            hexWord(static_cast<std::uint16_t>(code)).substr(2);
    return {"unknown abort code " + hex, "unbekannter Abbruchcode " + hex};
}

} // namespace vt::dev::canopen
