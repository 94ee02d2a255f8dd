// The DSP-408 device state machine (ED1/SD1 PROFIBUS-DP manual §4.2.2) as a pure function, shared
// by the simulator (which owns the state) and the UI (which predicts and explains transitions).
#pragma once

#include "core/local_text.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace vt::dev::dsp408 {

// ED1/SD1 manual §4.2.2 state table.
enum class State : std::uint8_t {
    NotReady,
    Init,
    Disabled,
    Hold,
    DeviceModeActive,
    FaultReaction,
    FaultHold, // ED1/SD1 only; HART-7 manual §4.2.2: "not present on the WANDFLUH Electronics"
    Fault,
};

// ED1/SD1 manual §4.2.2 transition table. Tr567 is the forced fall-back to INIT.
enum class Transition : std::uint8_t {
    None,
    Tr0,
    Tr1,
    Tr2,
    Tr3,
    Tr4,
    Tr5,
    Tr6,
    Tr7,
    Tr8,
    Tr9,
    Tr10,
    Tr11,
    Tr12,
    Tr567,
};

// Where FAULTREACTION ends: TR_9 → FAULT_HOLD or TR_12 → FAULT. SD7 (HART) devices have no
// FAULT_HOLD and always use Disable.
enum class FaultReaction : std::uint8_t { Hold, Disable };

// Everything besides the control word that moves the machine.
struct Inputs
{
    bool initialised = true;          // TR_1: self test and initialisation completed
    bool enable = true;               // "Enable" input (ED1/SD1 §3.6 DigInp 3); 0 forces TR_567
    bool communicationForced = false; // communication state machine forces TR_567 (C9, C10, C11)
    bool errorPresent = false;        // TR_8; also blocks the error reset TR_10/TR_11
    bool faultReactionDone = true;    // FAULTREACTION finished (TR_9 / TR_12)
    FaultReaction reaction = FaultReaction::Disable;
};

struct Step
{
    State state = State::NotReady;
    Transition transition = Transition::None;
    bool operator==(const Step &) const = default;
};

// TR_0: switching on the supply voltage enters NOT_READY.
Step powerOn();

// One transition at most from `current`. `previousControlWord` is the control word of the last
// cycle: TR_10/TR_11 need the "reset fault" bit to change from 0 to 1 (§4.2.2).
Step step(State current, std::uint16_t controlWord, std::uint16_t previousControlWord,
          const Inputs &inputs);

// Repeats step() until nothing changes (at most `maxSteps`), as a device does within one cycle:
// control word 0x0007 in INIT runs TR_2, TR_3, TR_4. The reset edge counts for the first step only.
struct Settled
{
    State state = State::NotReady;
    std::vector<Transition> transitions;
};
Settled settle(State current, std::uint16_t controlWord, std::uint16_t previousControlWord,
               const Inputs &inputs, std::size_t maxSteps = 8);

// Status word bits R, M, H, D (bits 3..0) that report `state`. The manual's state diagram (which
// carries them) is lost in the OCR; the values are the CiA 408 / DSP-408 ones: INIT 1000,
// DISABLED 1001, HOLD 1011, DEVICE_MODE_ACTIVE 1111, FAULT_HOLD 0011, FAULTREACTION 0111,
// FAULT 0001, NOT_READY 0000.
std::uint16_t statusBits(State state);
// The state a status word reports (its bits R M H D, as statusBits() gives them); nullopt for a
// pattern no state has. Bits 4.. (local, warning, target window) do not matter.
std::optional<State> stateOfStatusWord(std::uint16_t statusWord);

// ED1/SD1 manual §4.2.2 transition table / §4.8.2: the control word that leads to a state from
// its neighbour (D, H, M; "reset fault" is the separate edge kResetFault).
inline constexpr std::uint16_t kControlInit = 0x0000;
inline constexpr std::uint16_t kControlDisabled = 0x0001;
inline constexpr std::uint16_t kControlHold = 0x0003;
inline constexpr std::uint16_t kControlActive = 0x0007;

// The control word that commands `state` (INIT, DISABLED, HOLD, DEVICE_MODE_ACTIVE); nullopt for
// the states only the device enters (NOT_READY, the fault states).
std::optional<std::uint16_t> controlWordFor(State state);
// The state named as stateName() gives it ("DEVICE_MODE_ACTIVE"); nullopt for any other text.
std::optional<State> stateFromName(std::string_view name);

// Texts (texts.cpp).
const char *stateName(State state); // "DEVICE_MODE_ACTIVE"
LocalText stateText(State state);
const char *transitionName(Transition transition); // "TR_4"
LocalText transitionText(Transition transition);

} // namespace vt::dev::dsp408
