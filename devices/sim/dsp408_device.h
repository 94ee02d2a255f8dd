// Simulated Wandfluh ED1/SD1 "Position controller PLUS" on PROFIBUS-DP (DSP-408 profile): the
// parameter dictionary by IND/PNU (ED1/SD1 manual §4.4) with defaults, the PKW parameter channel
// with the manual's response ids and error codes (§4.6), the PZD process data (§4.5: control
// word → device state machine §4.2.2, status word, set value, actual value), the hardware enable
// input and fault injection (§4.8.1 error codes, reaction FAULT). The motion is Dsp408Drive's
// first-order actuator. Behaviour and assumptions: docs/SIMULATOR-WANDFLUH.md.
// Owner: whoever builds the simulator (attach it to a SimClock); single-threaded. The Dictionary
// must outlive the device.
#pragma once

#include "dsp408/pkw.h"
#include "dsp408/pzd.h"
#include "sim/dsp408_drive.h"
#include "sim/dsp408_param_store.h"
#include "sim/sim_clock.h"

#include <cstdint>
#include <optional>

namespace vt::dev::sim {

// ED1/SD1 manual §4.8.1 db_ErrorCode values (reaction FAULT for all).
namespace dsp408_error {
inline constexpr std::uint16_t kGeneral = 0x1000;
inline constexpr std::uint16_t kSupplyTooLow = 0x3412;
inline constexpr std::uint16_t kControlVoltageTooLow = 0x3422; // set value cable break
inline constexpr std::uint16_t kTransducer = 0x5231;           // actual value cable break
inline constexpr std::uint16_t kEeprom = 0x5510;
inline constexpr std::uint16_t kCommunication = 0x8100;
} // namespace dsp408_error

class Dsp408Device : public SimModel
{
public:
    struct Options
    {
        Dsp408Drive::Options drive{};
    };

    explicit Dsp408Device(const Dictionary &ed1);
    Dsp408Device(const Dictionary &ed1, Options options);

    // One cyclic exchange as the PLC sees it: the PKW request first (type 1 only), then the PZD.
    dsp408::ResponseTelegram exchange(const dsp408::RequestTelegram &request);
    // §4.6: one PKW request → one response (AK 1/2/11 with the value, or AK 7 with an error code).
    // A write identical to the previous request is answered again without being executed again
    // (the PLC repeats the same PKW every cycle until it has the answer).
    dsp408::Pkw handlePkw(const dsp408::Pkw &request);
    // §4.5.2 / §4.5.3: control word and set value in, status word and actual value out.
    dsp408::PzdActual handlePzd(const dsp408::PzdSetpoint &request);
    // A PKW whose AK the manual does not define (4..9, 12..15): AK 7, error 18 "other errors".
    dsp408::Pkw unknownRequest(std::uint8_t ind, std::uint16_t pnu);

    // Parameter access with the device's checks, shared by the PKW and the CANopen front ends.
    // Live rows (status word, actual value, control deviation, error code) read the drive.
    std::optional<ParamErrc> read(const ParamMeta &meta, double &raw) const;
    std::optional<ParamErrc> write(const ParamMeta &meta, double raw);
    // Control word from any front end (PZD word 1, PKW, SDO 0x6040); ignored in local mode.
    void applyControlWord(std::uint16_t controlWord);
    // Set value from the bus (PZD words 2..3, PKW, SDO): clamped to the row's limits; ignored
    // unless the device mode is "preset value via bus" (§4.3.1, db_DeviceMode 1).
    void applyBusSetpoint(std::int32_t raw);

    // Local side (§4.2.1 db_Local = 1: control word and set value from the card's inputs).
    void setLocalControlWord(std::uint16_t controlWord);
    void setLocalSetpoint(std::int32_t raw);
    // "Enable" input (§3.6 DigInp 3): 1 → 0 forces TR_567.
    void setEnableInput(bool enabled) { m_drive.setEnableInput(enabled); }
    // Fault injection: db_ErrorCode = code (≠ 0) → TR_8 → FAULT; clearError() lets the master
    // leave FAULT with the "reset fault" edge (TR_10 / TR_11).
    void injectError(std::uint16_t code);
    void clearError() { injectError(0); }
    // Power cycle: volatile rows back to default, eeprom rows to what db_StoreParameter 'save'
    // stored last (ED1/SD1 manual §4.4 "Persistence", §4.8.8), state machine from NOT_READY.
    void powerCycle();

    dsp408::State state() const { return m_drive.state(); }
    std::uint16_t statusWord() const;
    std::int32_t actualValue() const { return m_drive.actual(); }
    Dsp408Drive &drive() { return m_drive; }
    const Dsp408Drive &drive() const { return m_drive; }
    Dsp408ParamStore &params() { return m_params; }
    const Dsp408ParamStore &params() const { return m_params; }
    bool local() const { return m_params.value("db_Local") != 0; }

    void step(const SimStep &step) override;

private:
    std::optional<ParamErrc> writeCommand(const ParamMeta &meta, double raw);
    void syncWindow();

    Options m_options;
    Dsp408ParamStore m_params;
    Dsp408ParamStore m_stored; // image kept by db_StoreParameter 'save'
    Dsp408Drive m_drive;
    std::int32_t m_localSetpoint = 0;
    std::optional<dsp408::Pkw> m_lastRequest;
    dsp408::Pkw m_lastResponse;
};

// ED1/SD1 manual §4.6 error code of a refusal: 0 undefined PNU, 1 not changeable, 2 value range,
// 5 data type, 18 other errors (write-only read, wrong state, invalid command word).
std::uint16_t pkwErrorCode(ParamErrc error);

} // namespace vt::dev::sim
