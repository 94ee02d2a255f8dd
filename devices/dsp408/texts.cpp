// User-visible texts of the DSP-408 codecs and state machine, English and German, worded after
// the ED1/SD1 PROFIBUS-DP manual (§4.2.2, §4.6, §4.8.2, §4.8.3). The bit names D, H, M stay as the
// profile names them (German readers know them from PASO); the German says what they mean, in the
// same words as the ED1/SD7 dictionaries' db_ControlWord / db_StatusWord bits.
#include "dsp408/pkw.h"
#include "dsp408/pzd.h"
#include "dsp408/state_machine.h"

#include <string>

namespace vt::dev::dsp408 {

LocalText requestIdText(std::uint8_t ak)
{
    switch (ak) {
    case 0: return {"no instruction", "kein Auftrag"};
    case 1: return {"read parameter value", "Parameterwert lesen"};
    case 2: return {"write parameter value (word)", "Parameterwert schreiben (Wort)"};
    case 3: return {"write parameter value (double word)", "Parameterwert schreiben (Doppelwort)"};
    case 10: return {"write parameter value (byte)", "Parameterwert schreiben (Byte)"};
    default: return {"reserved instruction signature", "reservierte Auftragskennung"};
    }
}

LocalText responseIdText(std::uint8_t ak)
{
    switch (ak) {
    case 0: return {"no response", "keine Antwort"};
    case 1: return {"parameter value (word)", "Parameterwert (Wort)"};
    case 2: return {"parameter value (double word)", "Parameterwert (Doppelwort)"};
    case 7: return {"instruction cannot be executed", "Auftrag nicht ausführbar"};
    case 11: return {"parameter value (byte)", "Parameterwert (Byte)"};
    default: return {"reserved response signature", "reservierte Antwortkennung"};
    }
}

LocalText pkwErrorText(std::uint16_t code)
{
    switch (code) {
    case 0: return {"undefined PNU", "unzulässige Parameternummer (PNU)"};
    case 1: return {"parameter not changeable", "Parameterwert nicht änderbar"};
    case 2:
        return {"lower or upper value range limit overflow",
                "untere oder obere Wertgrenze überschritten"};
    case 5: return {"data type error", "falscher Datentyp"};
    case 18: return {"other error", "sonstiger Fehler"};
    default: {
        const std::string n = std::to_string(code);
        return {"unknown error code " + n, "unbekannte Fehlernummer " + n};
    }
    }
}

LocalText controlBitText(int bit)
{
    switch (bit) {
    case 0: return {"Disable (D): state DISABLED", "Disable (D): Zustand DISABLED (gesperrt)"};
    case 1: return {"Hold enable (H): state HOLD", "Hold enable (H): Zustand HOLD (Halten)"};
    case 2:
        return {"Device mode active (M): state DEVICE_MODE_ACTIVE",
                "Device mode active (M): Zustand DEVICE_MODE_ACTIVE (Gerätemodus aktiv)"};
    case 3: return {"Reset fault (R)", "Fehler quittieren (R)"};
    case 14:
        return {"Stop: the axis stays controlled in its current position",
                "Stopp: die Achse bleibt in der aktuellen Position geregelt"};
    default: return {"reserved", "reserviert"};
    }
}

LocalText statusBitText(int bit)
{
    switch (bit) {
    case 0: return {"Disable (D)", "Disable (D): Gerät gesperrt"};
    case 1: return {"Hold enable (H)", "Hold enable (H): Halten freigegeben"};
    case 2: return {"Device mode active (M)", "Device mode active (M): Gerätemodus aktiv"};
    case 3: return {"Ready (R)", "Bereit (R)"};
    case 4: return {"local control", "lokale Steuerung"};
    case 5: return {"warning", "Warnung"};
    case 12: return {"actual value reached target window", "Istwert im Zielfenster"};
    default: return {"reserved", "reserviert"};
    }
}

const char *stateName(State state)
{
    switch (state) {
    case State::NotReady: return "NOT_READY";
    case State::Init: return "INIT";
    case State::Disabled: return "DISABLED";
    case State::Hold: return "HOLD";
    case State::DeviceModeActive: return "DEVICE_MODE_ACTIVE";
    case State::FaultReaction: return "FAULTREACTION";
    case State::FaultHold: return "FAULT_HOLD";
    case State::Fault: return "FAULT";
    }
    return "?";
}

LocalText stateText(State state)
{
    switch (state) {
    case State::NotReady: return {"not ready: self test running", "nicht bereit: Selbsttest läuft"};
    case State::Init:
        return {"initialisation: device functions disabled",
                "Initialisierung: Gerätefunktionen gesperrt"};
    case State::Disabled:
        return {"disabled: device modes can be set",
                "gesperrt: Gerätemodi können eingestellt werden"};
    case State::Hold:
        return {"hold: last set value stays active", "Halten: letzter Sollwert bleibt aktiv"};
    case State::DeviceModeActive: return {"device mode active", "Gerätemodus aktiv"};
    case State::FaultReaction: return {"fault reaction running", "Fehlerreaktion läuft"};
    case State::FaultHold: return {"fault, hold set value active", "Fehler, Halte-Sollwert aktiv"};
    case State::Fault:
        return {"fault: device functions disabled", "Fehler: Gerätefunktionen gesperrt"};
    }
    return {"unknown state", "unbekannter Zustand"};
}

const char *transitionName(Transition transition)
{
    switch (transition) {
    case Transition::None: return "-";
    case Transition::Tr0: return "TR_0";
    case Transition::Tr1: return "TR_1";
    case Transition::Tr2: return "TR_2";
    case Transition::Tr3: return "TR_3";
    case Transition::Tr4: return "TR_4";
    case Transition::Tr5: return "TR_5";
    case Transition::Tr6: return "TR_6";
    case Transition::Tr7: return "TR_7";
    case Transition::Tr8: return "TR_8";
    case Transition::Tr9: return "TR_9";
    case Transition::Tr10: return "TR_10";
    case Transition::Tr11: return "TR_11";
    case Transition::Tr12: return "TR_12";
    case Transition::Tr567: return "TR_567";
    }
    return "?";
}

LocalText transitionText(Transition transition)
{
    switch (transition) {
    case Transition::None: return {"no transition", "kein Übergang"};
    case Transition::Tr0:
        return {"supply voltage switched on", "Versorgungsspannung eingeschaltet"};
    case Transition::Tr1:
        return {"device initialisation completed", "Geräteinitialisierung abgeschlossen"};
    case Transition::Tr2: return {"bit \"Disable\" active", "Bit \"Disable\" aktiv"};
    case Transition::Tr3: return {"bit \"Hold enable\" active", "Bit \"Hold enable\" aktiv"};
    case Transition::Tr4:
        return {"bit \"Device mode active enable\" active",
                "Bit \"Device mode active enable\" aktiv"};
    case Transition::Tr5:
        return {"bit \"Device mode active enable\" not active",
                "Bit \"Device mode active enable\" nicht aktiv"};
    case Transition::Tr6:
        return {"bit \"Hold enable\" not active", "Bit \"Hold enable\" nicht aktiv"};
    case Transition::Tr7: return {"bit \"Disable\" not active", "Bit \"Disable\" nicht aktiv"};
    case Transition::Tr8: return {"error present", "Fehler liegt an"};
    case Transition::Tr9:
        return {"error reaction completed (HOLD active)",
                "Fehlerreaktion abgeschlossen (HOLD aktiv)"};
    case Transition::Tr10:
        return {"error reset, back to DISABLED", "Fehler quittiert, zurück nach DISABLED"};
    case Transition::Tr11:
        return {"error reset, back to HOLD", "Fehler quittiert, zurück nach HOLD"};
    case Transition::Tr12:
        return {"error reaction completed (DISABLED active)",
                "Fehlerreaktion abgeschlossen (DISABLED aktiv)"};
    case Transition::Tr567:
        return {"forced back to INIT (enable input off or communication)",
                "erzwungen zurück nach INIT (Freigabe-Eingang aus oder Kommunikation)"};
    }
    return {"unknown transition", "unbekannter Übergang"};
}

} // namespace vt::dev::dsp408
