#include "stw1_zsw1.h"

#include <array>

namespace vt::dev::profidrive {
namespace {

// English: OPAT manual §5.2.1 / §5.4.1 (the PROFIdrive profile tables, speed control mode) and the
// OPAT details of §5.2.2 / §5.4.2. German: the PROFIdrive profile's usual German terms.
const std::array<WordBit, 16> kStw1{{
    {1u << 0, "ON/OFF1", {"ON (OPAT: enable OPAT)", "EIN (OPAT: OPAT freigeben)"}, {"OFF1", "AUS1"}},
    {1u << 1, "OFF2", {"no coast stop (no OFF2)", "kein Austrudeln (kein AUS2)"}, {"coast stop (OFF2)", "Austrudeln (AUS2)"}},
    {1u << 2, "OFF3", {"no quick stop (no OFF3)", "kein Schnellhalt (kein AUS3)"}, {"quick stop (OFF3)", "Schnellhalt (AUS3)"}},
    {1u << 3, "ENABLE_OPERATION", {"enable operation", "Betrieb freigeben"}, {"disable operation", "Betrieb sperren"}},
    {1u << 4, "RAMP_GENERATOR", {"enable ramp generator", "Hochlaufgeber freigeben"}, {"reset ramp generator", "Hochlaufgeber zurücksetzen"}},
    {1u << 5, "UNFREEZE_RAMP", {"unfreeze ramp generator", "Hochlaufgeber fortsetzen"}, {"freeze ramp generator", "Hochlaufgeber anhalten"}},
    {1u << 6, "ENABLE_SETPOINT", {"enable setpoint", "Sollwert freigeben"}, {"disable setpoint", "Sollwert sperren"}},
    {1u << 7, "FAULT_ACK", {"fault acknowledge (0 → 1; OPAT: clears a pending error once its cause is gone)",
                            "Störung quittieren (0 → 1; OPAT: löscht einen anstehenden Fehler, wenn die Ursache behoben ist)"}, {}},
    {1u << 8, "JOG1", {"jog 1 on", "Tippen 1 ein"}, {}},
    {1u << 9, "JOG2", {"jog 2 on", "Tippen 2 ein"}, {}},
    {1u << 10, "CONTROL_BY_PLC", {"control by PLC", "Führung durch SPS"}, {"no control by PLC", "keine Führung durch SPS"}},
    {1u << 11, "BIT11", {"device-specific, not used by the OPAT", "gerätespezifisch, vom OPAT nicht verwendet"}, {}, true, false},
    {1u << 12, "Din_1", {"set signal Din_1 active (needs hardware enable)", "Signal Din_1 aktiv setzen (nur mit Hardware Freigabe)"}, {}, true},
    {1u << 13, "TST_CMP", {"set error/comparator output directly to 24 V (error output signalling disabled)",
                           "Fehler/Komparatorausgang direkt auf 24 V setzen (Signalisierung des Fehlerausgangs deaktiviert)"}, {}, true},
    {1u << 14, "Din_2", {"set signal Din_2 active (needs hardware enable)", "Signal Din_2 aktiv setzen (nur mit Hardware Freigabe)"}, {}, true},
    {1u << 15, "BIT15", {"device-specific, not used by the OPAT", "gerätespezifisch, vom OPAT nicht verwendet"}, {}, true, false},
}};

const std::array<WordBit, 16> kZsw1{{
    {1u << 0, "READY_TO_SWITCH_ON", {"ready to switch on", "einschaltbereit"}, {"not ready to switch on", "nicht einschaltbereit"}},
    {1u << 1, "READY_TO_OPERATE", {"ready to operate", "betriebsbereit"}, {"not ready to operate", "nicht betriebsbereit"}},
    {1u << 2, "OPERATION_ENABLED", {"operation enabled (OPAT is enabled)", "Betrieb freigegeben (OPAT ist freigegeben)"},
     {"operation disabled", "Betrieb gesperrt"}},
    {1u << 3, "FAULT", {"fault present (NIST_A holds the OPAT error number)", "Störung wirksam (NIST_A enthält die OPAT-Fehlernummer)"},
     {"no fault", "keine Störung"}},
    {1u << 4, "NO_OFF2", {"coast stop not activated (no OFF2)", "kein Austrudeln aktiv (kein AUS2)"}, {"coast stop activated (OFF2)", "Austrudeln aktiv (AUS2)"}},
    {1u << 5, "NO_OFF3", {"quick stop not activated (no OFF3)", "kein Schnellhalt aktiv (kein AUS3)"}, {"quick stop activated (OFF3)", "Schnellhalt aktiv (AUS3)"}},
    {1u << 6, "SWITCHING_ON_INHIBITED", {"switching on inhibited", "Einschaltsperre"}, {"switching on not inhibited", "keine Einschaltsperre"}},
    {1u << 7, "WARNING", {"warning present", "Warnung wirksam"}, {"no warning", "keine Warnung"}},
    {1u << 8, "SPEED_ERROR_OK", {"speed error within tolerance range", "Drehzahlabweichung im Toleranzbereich"},
     {"speed error out of tolerance range", "Drehzahlabweichung außerhalb des Toleranzbereichs"}},
    {1u << 9, "CONTROL_REQUESTED", {"control requested", "Führung gefordert"}, {"no control requested", "keine Führung gefordert"}},
    {1u << 10, "SETPOINT_REACHED", {"f or n reached or exceeded", "Vergleichswert erreicht oder überschritten"}, {"f or n not reached", "Vergleichswert nicht erreicht"}},
    {1u << 11, "BIT11", {"device-specific, not used by the OPAT", "gerätespezifisch, vom OPAT nicht verwendet"}, {}, true, false},
    {1u << 12, "Komp_1", {"signal at comparator 1 (Komp_1)", "Signal an Komparator 1 (Komp_1)"}, {}, true},
    {1u << 13, "Komp_11", {"signal at comparator 11 (Komp_11)", "Signal an Komparator 11 (Komp_11)"}, {}, true},
    {1u << 14, "Dout_1", {"controller in closed loop (signal Dout_1 set)", "Regler im geschlossenen Regelkreis (Signal Dout_1 gesetzt)"}, {}, true},
    {1u << 15, "BIT15", {"device-specific, not used by the OPAT", "gerätespezifisch, vom OPAT nicht verwendet"}, {}, true, false},
}};

} // namespace

std::span<const WordBit> stw1Bits()
{
    return kStw1;
}

std::span<const WordBit> zsw1Bits()
{
    return kZsw1;
}

} // namespace vt::dev::profidrive
