// The moving part of a simulated Wandfluh device: the shared DSP-408 device state machine
// (dsp408/state_machine.h, ED1/SD1 PROFIBUS-DP manual §4.2.2, HART-7 manual §4.2.2) driven by the
// control word, the hardware enable input and errors, plus a first-order actuator whose actual
// value follows the set value while the state lets the device drive.
//
// Assumptions (the manuals describe the profile, not the axis; docs/SIMULATOR-WANDFLUH.md):
// - NOT_READY lasts `selfTestUs` of simulated time, then TR_1 (self test passed) runs.
// - DEVICE_MODE_ACTIVE drives towards the set value; HOLD towards the set value present when HOLD
//   was entered (§4.2.2 "the last set-point value present is maintained active"); every other
//   state leaves the solenoids off and the axis where it is. Control word bit 14 "Stop" (§4.8.2)
//   holds the present position while it is set.
// - The actuator is x' = (target − x) / τ, integrated exactly per fixed SimClock step, so the
//   trajectory never depends on how time is chunked.
// Owner: the simulated device; single-threaded.
#pragma once

#include "dsp408/state_machine.h"
#include "sim/sim_clock.h"

#include <cstdint>
#include <vector>

namespace vt::dev::sim {

class Dsp408Drive : public SimModel
{
public:
    struct Options
    {
        // ED1/SD1 manual §4.8.1: every error's reaction is FAULT (TR_12); the SD7 has no
        // FAULT_HOLD at all (HART-7 manual §4.2.2).
        dsp408::FaultReaction reaction = dsp408::FaultReaction::Disable;
        std::int64_t selfTestUs = 50'000; // NOT_READY → INIT
        double timeConstantS = 0.1;       // actuator τ
    };

    Dsp408Drive();
    explicit Dsp408Drive(Options options);

    // TR_0: NOT_READY, actual value and control word history kept / cleared as after power-up.
    void powerOn();

    // A control word from the master (PZD, PKW, SDO, HART): the machine settles at once, as the
    // device does within one cycle (dsp408::settle()). The previous word supplies the reset edge.
    void applyControlWord(std::uint16_t controlWord);
    std::uint16_t controlWord() const { return m_controlWord; }

    void setSetpoint(std::int32_t raw) { m_setpoint = raw; }
    std::int32_t setpoint() const { return m_setpoint; }
    // The actual value rounded to the raw step; actualExact() for checks on the trajectory.
    std::int32_t actual() const;
    double actualExact() const { return m_actual; }
    void setActual(double raw) { m_actual = raw; }

    // "Enable" input (ED1/SD1 §3.6 DigInp 3); 1 → 0 forces TR_567 to INIT.
    void setEnableInput(bool enabled);
    bool enableInput() const { return m_inputs.enable; }
    // An error present (fault injection, cable break, …): TR_8 and on into FAULT.
    void setErrorPresent(bool present);
    bool errorPresent() const { return m_inputs.errorPresent; }

    // Target window of §4.8.3 bit 12, raw steps of the actual value. Without a window (the
    // default) bit 12 stays 0.
    void setTargetWindow(std::int32_t threshold, std::int32_t hysteresis);

    dsp408::State state() const { return m_state; }
    // The device configuration (modes, local) may change: NOT_READY, INIT or DISABLED (ED1/SD1
    // manual §4.2.2: "In this state, the different device modes … can be set").
    bool configurable() const;
    // FAULTREACTION, FAULT_HOLD or FAULT.
    bool faulted() const;
    // statusBits(state) plus "actual value reached target window" (bit 12).
    std::uint16_t statusWord() const;
    bool inTargetWindow() const { return m_inWindow; }
    // Every transition since power-on, in order (for tests and the telegram inspector).
    const std::vector<dsp408::Transition> &history() const { return m_history; }

    void step(const SimStep &step) override;

private:
    void settle(std::uint16_t previousControlWord);
    double target() const;
    void updateWindow();

    Options m_options;
    dsp408::State m_state = dsp408::State::NotReady;
    dsp408::Inputs m_inputs;
    std::uint16_t m_controlWord = 0;
    std::int32_t m_setpoint = 0;
    std::int32_t m_holdSetpoint = 0;
    double m_actual = 0;
    std::int64_t m_sincePowerOnUs = 0;
    std::int32_t m_windowThreshold = 0;
    std::int32_t m_windowHysteresis = 0;
    bool m_windowEnabled = false;
    bool m_inWindow = false;
    std::vector<dsp408::Transition> m_history;
};

} // namespace vt::dev::sim
