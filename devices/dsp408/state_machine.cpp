#include "dsp408/state_machine.h"

#include "dsp408/pzd.h"

namespace vt::dev::dsp408 {
namespace {

bool has(std::uint16_t word, std::uint16_t bit)
{
    return (word & bit) != 0;
}

constexpr State kStates[] = {
    State::NotReady,         State::Init,          State::Disabled,  State::Hold,
    State::DeviceModeActive, State::FaultReaction, State::FaultHold, State::Fault};

} // namespace

Step powerOn()
{
    return {State::NotReady, Transition::Tr0};
}

Step step(State current, std::uint16_t cw, std::uint16_t previousCw, const Inputs &in)
{
    const bool d = has(cw, control::kDisable);
    const bool h = has(cw, control::kHoldEnable);
    const bool m = has(cw, control::kDeviceModeActive);
    const bool resetEdge = has(cw, control::kResetFault) && !has(previousCw, control::kResetFault);

    switch (current) {
    case State::NotReady:
        if (in.initialised)
            return {State::Init, Transition::Tr1};
        return {current, Transition::None};
    case State::FaultReaction:
        if (!in.faultReactionDone)
            return {current, Transition::None};
        if (in.reaction == FaultReaction::Hold)
            return {State::FaultHold, Transition::Tr9};
        return {State::Fault, Transition::Tr12};
    case State::Fault:
    case State::FaultHold:
        // §4.2.2 TR_10 / TR_11 differ only in H; both need the 0 → 1 edge of "reset fault".
        if (!resetEdge || in.errorPresent)
            return {current, Transition::None};
        if (h)
            return {State::Hold, Transition::Tr11};
        return {State::Disabled, Transition::Tr10};
    case State::Init:
    case State::Disabled:
    case State::Hold:
    case State::DeviceModeActive: break;
    }

    // Operational states. TR_8 wins over everything the control word asks for.
    if (in.errorPresent)
        return {State::FaultReaction, Transition::Tr8};
    if (current != State::Init && (!in.enable || in.communicationForced))
        return {State::Init, Transition::Tr567};

    switch (current) {
    case State::Init:
        if (d && in.enable && !in.communicationForced)
            return {State::Disabled, Transition::Tr2};
        break;
    case State::Disabled:
        if (d && h)
            return {State::Hold, Transition::Tr3};
        if (!d && !h && !m)
            return {State::Init, Transition::Tr7};
        break;
    case State::Hold:
        if (d && h && m)
            return {State::DeviceModeActive, Transition::Tr4};
        if (!h && !m)
            return {State::Disabled, Transition::Tr6};
        break;
    case State::DeviceModeActive:
        if (!m)
            return {State::Hold, Transition::Tr5};
        break;
    default: break;
    }
    return {current, Transition::None};
}

Settled settle(State current, std::uint16_t cw, std::uint16_t previousCw, const Inputs &inputs,
               std::size_t maxSteps)
{
    Settled out{current, {}};
    std::uint16_t previous = previousCw;
    for (std::size_t i = 0; i < maxSteps; ++i) {
        const Step s = step(out.state, cw, previous, inputs);
        if (s.transition == Transition::None)
            break;
        out.state = s.state;
        out.transitions.push_back(s.transition);
        previous = cw; // the reset edge is consumed by the first step
    }
    return out;
}

std::uint16_t statusBits(State state)
{
    using namespace status;
    switch (state) {
    case State::NotReady: return 0;
    case State::Init: return kReady;
    case State::Disabled: return kReady | kDisable;
    case State::Hold: return kReady | kHoldEnable | kDisable;
    case State::DeviceModeActive: return kReady | kDeviceModeActive | kHoldEnable | kDisable;
    case State::FaultReaction: return kDeviceModeActive | kHoldEnable | kDisable;
    case State::FaultHold: return kHoldEnable | kDisable;
    case State::Fault: return kDisable;
    }
    return 0;
}

std::optional<State> stateOfStatusWord(std::uint16_t statusWord)
{
    for (State state : kStates)
        if (statusBits(state) == (statusWord & 0x0Fu))
            return state;
    return std::nullopt;
}

std::optional<std::uint16_t> controlWordFor(State state)
{
    switch (state) {
    case State::Init: return kControlInit;
    case State::Disabled: return kControlDisabled;
    case State::Hold: return kControlHold;
    case State::DeviceModeActive: return kControlActive;
    default: return std::nullopt;
    }
}

std::optional<State> stateFromName(std::string_view name)
{
    for (State state : kStates)
        if (name == stateName(state))
            return state;
    return std::nullopt;
}

} // namespace vt::dev::dsp408
