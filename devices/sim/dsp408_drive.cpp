#include "sim/dsp408_drive.h"

#include "dsp408/pzd.h"

#include <cmath>
#include <cstdlib>
#include <limits>

namespace vt::dev::sim {

using dsp408::State;

Dsp408Drive::Dsp408Drive() : Dsp408Drive(Options{})
{
}

Dsp408Drive::Dsp408Drive(Options options) : m_options(options)
{
    powerOn();
}

void Dsp408Drive::powerOn()
{
    const dsp408::Step s = dsp408::powerOn();
    m_state = s.state;
    m_history.assign(1, s.transition);
    m_sincePowerOnUs = 0;
    m_controlWord = 0;
    m_inputs.initialised = m_options.selfTestUs <= 0;
    m_inputs.reaction = m_options.reaction;
    m_inputs.faultReactionDone = true;
    m_inWindow = false;
    settle(0);
}

void Dsp408Drive::applyControlWord(std::uint16_t controlWord)
{
    const std::uint16_t previous = m_controlWord;
    m_controlWord = controlWord;
    settle(previous);
}

void Dsp408Drive::setEnableInput(bool enabled)
{
    m_inputs.enable = enabled;
    settle(m_controlWord);
}

void Dsp408Drive::setErrorPresent(bool present)
{
    m_inputs.errorPresent = present;
    settle(m_controlWord);
}

void Dsp408Drive::setTargetWindow(std::int32_t threshold, std::int32_t hysteresis)
{
    m_windowThreshold = threshold;
    m_windowHysteresis = hysteresis;
    m_windowEnabled = true;
    updateWindow();
}

void Dsp408Drive::settle(std::uint16_t previousControlWord)
{
    const State before = m_state;
    const dsp408::Settled s = dsp408::settle(m_state, m_controlWord, previousControlWord, m_inputs);
    m_state = s.state;
    m_history.insert(m_history.end(), s.transitions.begin(), s.transitions.end());
    const bool holding = m_state == State::Hold || m_state == State::FaultHold;
    if (holding && before != m_state)
        m_holdSetpoint = m_setpoint;
    updateWindow();
}

bool Dsp408Drive::configurable() const
{
    return m_state == State::NotReady || m_state == State::Init || m_state == State::Disabled;
}

bool Dsp408Drive::faulted() const
{
    return m_state == State::FaultReaction || m_state == State::FaultHold ||
           m_state == State::Fault;
}

std::int32_t Dsp408Drive::actual() const
{
    constexpr double lo = std::numeric_limits<std::int32_t>::min();
    constexpr double hi = std::numeric_limits<std::int32_t>::max();
    const double r = std::round(m_actual);
    return static_cast<std::int32_t>(r < lo ? lo : (r > hi ? hi : r));
}

double Dsp408Drive::target() const
{
    switch (m_state) {
    case State::DeviceModeActive:
        if (m_controlWord & dsp408::control::kStop)
            return m_actual;
        return m_setpoint;
    case State::Hold:
    case State::FaultHold: return m_holdSetpoint;
    default: return m_actual; // solenoids off: the axis stays where it is
    }
}

void Dsp408Drive::updateWindow()
{
    if (!m_windowEnabled || m_state != State::DeviceModeActive) {
        m_inWindow = false;
        return;
    }
    const double deviation = std::abs(static_cast<double>(m_setpoint) - m_actual);
    if (m_inWindow)
        m_inWindow = deviation <= static_cast<double>(m_windowThreshold) + m_windowHysteresis;
    else
        m_inWindow = deviation <= static_cast<double>(m_windowThreshold);
}

std::uint16_t Dsp408Drive::statusWord() const
{
    std::uint16_t word = dsp408::statusBits(m_state);
    if (m_inWindow)
        word = static_cast<std::uint16_t>(word | dsp408::status::kInTargetWindow);
    return word;
}

void Dsp408Drive::step(const SimStep &step)
{
    m_sincePowerOnUs += step.stepUs;
    if (!m_inputs.initialised && m_sincePowerOnUs >= m_options.selfTestUs) {
        m_inputs.initialised = true;
        settle(m_controlWord);
    }
    const double tau = m_options.timeConstantS;
    const double goal = target();
    if (tau <= 0)
        m_actual = goal;
    else
        m_actual = goal + (m_actual - goal) * std::exp(-step.dt() / tau);
    updateWindow();
}

} // namespace vt::dev::sim
