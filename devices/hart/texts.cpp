// HART texts, English and German. Command names after HART-7 manual §5.1, status texts after
// §4.4.1; further response codes after the HART common response code table.
#include "hart/texts.h"

namespace vt::dev::hart {

LocalText commandText(std::uint8_t command)
{
    switch (command) {
    case 0: return {"Read Unique Identifier", "Eindeutige Kennung lesen"};
    case 1: return {"Read Primary Variable", "Primärvariable lesen"};
    case 2:
        return {"Read Loop Current and Percent of Range",
                "Schleifenstrom und Prozent des Messbereichs lesen"};
    case 3:
        return {"Read Dynamic Variables and Loop Current",
                "Dynamische Variablen und Schleifenstrom lesen"};
    case 6: return {"Write Polling Address", "Polling-Adresse schreiben"};
    case 7: return {"Read Loop Configuration", "Schleifenkonfiguration lesen"};
    case 8:
        return {"Read Dynamic Variable Classifications",
                "Klassifizierung der dynamischen Variablen lesen"};
    case 9: return {"Read Device Variables with Status", "Gerätevariablen mit Status lesen"};
    case 11:
        return {"Read Unique Identifier Associated with Tag", "Eindeutige Kennung zum Tag lesen"};
    case 12: return {"Read Message", "Nachricht lesen"};
    case 13: return {"Read Tag, Descriptor, Date", "Tag, Beschreibung, Datum lesen"};
    case 14:
        return {"Read Primary Variable Transducer Information",
                "Sensordaten der Primärvariable lesen"};
    case 15: return {"Read Device Information", "Geräteinformationen lesen"};
    case 16: return {"Read Final Assembly Number", "Endmontagenummer lesen"};
    case 17: return {"Write Message", "Nachricht schreiben"};
    case 18: return {"Write Tag, Descriptor, Date", "Tag, Beschreibung, Datum schreiben"};
    case 19: return {"Write Final Assembly Number", "Endmontagenummer schreiben"};
    case 20: return {"Read Long Tag", "Langen Tag lesen"};
    case 21:
        return {"Read Unique Identifier Associated with Long Tag",
                "Eindeutige Kennung zum langen Tag lesen"};
    case 22: return {"Write Long Tag", "Langen Tag schreiben"};
    case 38:
        return {"Reset Configuration Changed Flag",
                "Merker \"Konfiguration geändert\" zurücksetzen"};
    case 48: return {"Read Additional Device Status", "Zusätzlichen Gerätestatus lesen"};
    case 128: return {"Read parameter (1 byte)", "Parameter lesen (1 Byte)"};
    case 129: return {"Write parameter (1 byte)", "Parameter schreiben (1 Byte)"};
    case 130: return {"Read parameter (2 bytes)", "Parameter lesen (2 Byte)"};
    case 131: return {"Write parameter (2 bytes)", "Parameter schreiben (2 Byte)"};
    case 132: return {"Read parameter (4 bytes)", "Parameter lesen (4 Byte)"};
    case 133: return {"Write parameter (4 bytes)", "Parameter schreiben (4 Byte)"};
    default: break;
    }
    const std::string n = std::to_string(command);
    if (command < 128)
        return {"common-practice command " + n, "Common-Practice-Kommando " + n};
    return {"device-specific command " + n, "gerätespezifisches Kommando " + n};
}

LocalText responseCodeText(std::uint8_t code)
{
    switch (code) {
    case 0: return {"no error", "kein Fehler"};
    case 1: return {"undefined", "undefiniert"};
    case 2: return {"invalid selection", "ungültige Auswahl"};
    case 3: return {"passed parameter too large", "übergebener Parameter zu groß"};
    case 4: return {"passed parameter too small", "übergebener Parameter zu klein"};
    case 5:
        return {"wrong byte count (too few data bytes)",
                "falsche Byteanzahl (zu wenige Datenbytes)"};
    case 6: return {"device-specific command error", "Fehler im gerätespezifischen Kommando"};
    case 7: return {"in write-protect mode", "im Schreibschutzmodus"};
    case 16: return {"access restricted", "Zugriff eingeschränkt"};
    case 32: return {"busy", "beschäftigt"};
    case 33: return {"delayed response initiated", "verzögerte Antwort eingeleitet"};
    case 34: return {"delayed response running", "verzögerte Antwort läuft"};
    case 35: return {"delayed response dead", "verzögerte Antwort abgebrochen"};
    case 36: return {"delayed response conflict", "Konflikt bei verzögerter Antwort"};
    case 64: return {"command not implemented", "Kommando nicht implementiert"};
    default: break;
    }
    const std::string n = std::to_string(code);
    if (code >= 8 && code <= 15)
        return {"command-specific response " + n, "kommandospezifische Antwort " + n};
    return {"response code " + n, "Antwortcode " + n};
}

LocalText commErrorBitText(int bit)
{
    switch (bit) {
    case 6: return {"vertical parity error", "vertikaler Paritätsfehler"};
    case 5: return {"overrun error", "Überlauffehler"};
    case 4: return {"framing error", "Rahmenfehler"};
    case 3: return {"longitudinal parity error", "Längsparitätsfehler"};
    case 1: return {"buffer overflow", "Pufferüberlauf"};
    default: return {"reserved", "reserviert"};
    }
}

LocalText deviceStatusBitText(int bit)
{
    switch (bit) {
    case 0: return {"PV out of limits", "Primärvariable außerhalb der Grenzen"};
    case 1: return {"non-PV out of limits", "Nicht-Primärvariable außerhalb der Grenzen"};
    case 2: return {"PV analog output saturated", "Analogausgang der Primärvariable gesättigt"};
    case 3: return {"PV analog output fixed", "Analogausgang der Primärvariable fest"};
    case 4: return {"more status available", "weiterer Status verfügbar"};
    case 5: return {"cold start", "Kaltstart"};
    case 6: return {"configuration changed", "Konfiguration geändert"};
    case 7: return {"device malfunction", "Gerätestörung"};
    default: return {"reserved", "reserviert"};
    }
}

bool isErrorResponse(std::uint8_t code)
{
    if (code & 0x80)
        return true; // communication error
    if (code == 0)
        return false;
    // HART common response codes: 8 and 14 are warnings for many commands, 24..27 and 96..127 too.
    if (code == 8 || code == 14 || (code >= 24 && code <= 27) || (code >= 96 && code <= 127))
        return false;
    return true;
}

std::string unitSymbol(std::uint8_t unit)
{
    switch (unit) {
    case 6: return "psi";
    case 7: return "bar";
    case 8: return "mbar";
    case 12: return "kPa";
    case 32: return "°C";
    case 33: return "°F";
    case 35: return "K";
    case 36: return "mV";
    case 37: return "Ω";
    case 38: return "Hz";
    case 39: return "mA";
    case 45: return "m";
    case 47: return "in";
    case 48: return "cm";
    case 49: return "mm";
    case 51: return "s";
    case 57: return "%";
    case 58: return "V";
    default: return {};
    }
}

} // namespace vt::dev::hart
