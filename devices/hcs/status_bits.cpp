#include "status_bits.h"

#include <utility>

namespace vt::dev::hcs {
namespace {

using Bits = std::array<BitMeaning, 8>;

Bits markUsed(Bits bits, std::uint8_t usedMask)
{
    for (BitMeaning &b : bits)
        b.used = (b.mask & usedMask) != 0;
    return bits;
}

const LocalText kReserved{"reserved for special functions", "Reserviert für Sonderfunktionen"};

// German: DMA Profibus Anleitung §4.5.4 ("Setzt das Signal Din_1 aktiv", "Freigabe via Profibus
// sperren") and §4.5.1.3 (TST_CMP).
const Bits kControl{{
    {0x01, "Din_1", {"set signal Din_1 active", "Setzt das Signal Din_1 aktiv"}, false},
    {0x02, "CNTRL_1", kReserved, false},
    {0x04,
     "TST_CMP",
     {"set error/comparator output directly to 24 V (error output signalling disabled)",
      "Fehler/Komparatorausgang direkt auf 24 V setzen (Signalisierung des Fehlerausgangs "
      "deaktiviert)"},
     false},
    {0x08, "CNTRL_2", kReserved, false},
    {0x10, "Din_2", {"set signal Din_2 active", "Setzt das Signal Din_2 aktiv"}, false},
    {0x20, "CNTRL_3", kReserved, false},
    {0x40, "CNTRL_4", kReserved, false},
    {0x80, "BUS_DISABLE", {"module disabled via the bus", "Freigabe via Bus sperren"}, false},
}};

const Bits kStatusHigh{{
    {0x01, "STAT_1", kReserved, false},
    {0x02, "STAT_2", kReserved, false},
    {0x04, "HW_ENABLE", {"hardware enable is active", "Hardware Freigabe ist aktiv"}, true},
    {0x08,
     "ERROR",
     {"error is pending; the low byte holds the error number",
      "ein Fehler steht an; das Low-Byte enthält die Fehlernummer"},
     true},
    {0x10, "STAT_3", kReserved, false},
    {0x20, "STAT_4", kReserved, false},
    {0x40, "STAT_5", kReserved, false},
    {0x80, "BUS_DISABLE", {"BUS_DISABLE is set", "BUS_DISABLE ist aktiv"}, true},
}};

// Parameter 0xB0 order (OPAT manual §7, DMA Profinet manual §4.5.3, DMA Profibus Anleitung §4.5.4).
const Bits kStatusLow{{
    {0x01, "Din_1", {"Din_1 is active", "Din_1 ist aktiv"}, false},
    {0x02,
     "Dout_1",
     {"Dout_1 is active: branch 1 runs in closed loop",
      "Dout_1 ist aktiv: Zweig 1 arbeitet geregelt"},
     false},
    {0x04,
     "DKOMP_1",
     {"DKOMP_1 is active (comparator KOMP_1 inside its window)",
      "DKOMP_1 ist aktiv (Komparator KOMP_1 innerhalb des Fensters)"},
     false},
    {0x08,
     "DKOMP_11",
     {"DKOMP_11 is active (comparator KOMP_11 inside its window)",
      "DKOMP_11 ist aktiv (Komparator KOMP_11 innerhalb des Fensters)"},
     false},
    {0x10, "Din_2", {"Din_2 is active", "Din_2 ist aktiv"}, false},
    {0x20,
     "Dout_2",
     {"Dout_2 is active: branch 2 runs in closed loop",
      "Dout_2 ist aktiv: Zweig 2 arbeitet geregelt"},
     false},
    {0x40,
     "DKOMP_2",
     {"DKOMP_2 is active (comparator KOMP_2 inside its window)",
      "DKOMP_2 ist aktiv (Komparator KOMP_2 innerhalb des Fensters)"},
     false},
    {0x80,
     "DKOMP_22",
     {"DKOMP_22 is active (comparator KOMP_22 inside its window)",
      "DKOMP_22 ist aktiv (Komparator KOMP_22 innerhalb des Fensters)"},
     false},
}};

struct NumberText
{
    std::uint8_t number;
    LocalText text;
};

// DMA Profinet manual §4.5.1.1 / DMA Profibus Anleitung §4.5.1.1 ("Generell gilt aber folgende
// Fehlertabelle", status high byte 0x0C = HW_ENABLE | ERROR).
const std::array<NumberText, 10> kDmaErrors{{
    {1, {"error of operation (general error)", "Allgemeiner Fehler"}},
    {2,
     {"wire break at set point S1.06 (current signal < 2 mA)",
      "Drahtbruch des Analog-Einganges S1.06 erkannt (Stromeingang < 2 mA)"}},
    {3,
     {"excess current or short circuit at the output stages (peak current > 8 A)",
      "Kurzschluss der Ausgangsstufen erkannt (Spitzenstrom > 8 A)"}},
    {4,
     {"wire break at set point S1.05 (current signal < 2 mA)",
      "Drahtbruch des Analog-Einganges S1.05 erkannt (Stromeingang < 2 mA)"}},
    {5,
     {"over current at set point S1.06 (current signal > 25 mA)",
      "Überstrom am Analog-Eingang S1.06 erkannt (Stromeingang > 25 mA)"}},
    {6,
     {"over current at set point S1.05 (current signal > 25 mA)",
      "Überstrom am Analog-Eingang S1.05 erkannt (Stromeingang > 25 mA)"}},
    {7, {"not applicable", "Nicht verwendet"}},
    {8,
     {"over current, short circuit or open circuit at the output stages (current deviation > 250 "
      "mA for about 100 ms)",
      "Überstrom, Kurzschluss oder Unterbrechung an den Endstufen (Differenz Sollstrom/Iststrom > "
      "250 mA für ca. 100 ms)"}},
    {9,
     {"input signal at set point S1.06 with E15 = 8 (5 ± 4.5 V) outside the valid range (about < "
      "0.43 V / > 9.58 V)",
      "Eingangssignal @ Sollwert S1.06 und Auswahl E15 = 8 (5 … ±4,5 V) außerhalb des gültigen "
      "Bereiches (ca. < 0,43 V / > 9,58 V)"}},
    {10,
     {"timeout error: no valid fieldbus telegram within E23",
      "Timeout-Fehler: kein gültiges Bustelegramm innerhalb E23 (Parameter E23 prüfen)"}},
}};

// OPAT manual §7, ID 0x102 "ERR Internal Error of the device".
const std::array<NumberText, 12> kOpatErrors{{
    {2, {"wire break sensor 1", "Drahtbruch Sensor 1"}},
    {4, {"wire break sensor 2", "Drahtbruch Sensor 2"}},
    {5, {"current overload > 22 mA at sensor 1", "Überstrom > 22 mA an Sensor 1"}},
    {6, {"current overload > 22 mA at sensor 2", "Überstrom > 22 mA an Sensor 2"}},
    {7,
     {"CAN error, no connection to slave or master",
      "CAN-Fehler, keine Verbindung zu Slave oder Master"}},
    {8, {"wire break at the output stages", "Drahtbruch an den Endstufen"}},
    {9, {"wire break on the set value", "Drahtbruch am Sollwert"}},
    {10, {"CAN error, receiving error", "CAN-Fehler, Empfangsfehler"}},
    {11, {"Profibus error, no connection to the PLC", "Profibus-Fehler, keine Verbindung zur SPS"}},
    {12,
     {"CAN error, no connection to the CAN master", "CAN-Fehler, keine Verbindung zum CAN-Master"}},
    {13, {"CAN timeout error", "CAN-Timeout-Fehler"}},
    {23, {"calibration error", "Kalibrierfehler"}},
}};

} // namespace

std::array<BitMeaning, 8> controlBits(Profile profile)
{
    return markUsed(kControl, profileInfo(profile).controlBits);
}

std::array<BitMeaning, 8> statusHighBits(Profile /*profile*/)
{
    // Identical in every version: 0x04 HW_ENABLE, 0x08 ERROR, 0x80 BUS_DISABLE.
    return kStatusHigh;
}

std::array<BitMeaning, 8> statusLowBits(Profile profile, bool opatPrintedOrder)
{
    const ProfileInfo &info = profileInfo(profile);
    Bits bits = markUsed(kStatusLow, info.statusLowBits);
    if (opatPrintedOrder && info.family == Family::Opat) {
        // OPAT manual §3.5.2: 0x02 = DKOMP_1, 0x04 = Dout_1, 0x20 = DKOMP_2, 0x40 = Dout_2.
        std::swap(bits[1].name, bits[2].name);
        std::swap(bits[1].text, bits[2].text);
        std::swap(bits[5].name, bits[6].name);
        std::swap(bits[5].text, bits[6].text);
    }
    return bits;
}

ModuleStatus decodeStatus(std::uint16_t word)
{
    ModuleStatus s;
    s.hwEnable = (word & kStatusHwEnable) != 0;
    s.error = (word & kStatusError) != 0;
    s.busDisable = (word & kStatusBusDisable) != 0;
    const auto low = static_cast<std::uint8_t>(word & 0xFF);
    // DMA Profinet manual §4.5.3: "if 'Error occurred' bit is set: error number, otherwise: …".
    if (s.error)
        s.errorNumber = low;
    else
        s.signalBits = low;
    return s;
}

std::optional<LocalText> errorNumberText(Family family, std::uint8_t number)
{
    if (family == Family::Opat) {
        for (const NumberText &e : kOpatErrors)
            if (e.number == number)
                return e.text;
        return std::nullopt;
    }
    for (const NumberText &e : kDmaErrors)
        if (e.number == number)
            return e.text;
    return std::nullopt;
}

} // namespace vt::dev::hcs
