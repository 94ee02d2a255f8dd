// The DSP-408 device state machine against the transition table of the ED1/SD1 PROFIBUS-DP
// manual §4.2.2 (and the HART-7 manual §4.2.2 variant without FAULT_HOLD).
#include "dsp408/pzd.h"
#include "dsp408/state_machine.h"

#include <gtest/gtest.h>

using namespace vt::dev::dsp408;

namespace {

constexpr std::uint16_t D = control::kDisable;
constexpr std::uint16_t H = control::kHoldEnable;
constexpr std::uint16_t M = control::kDeviceModeActive;
constexpr std::uint16_t R = control::kResetFault;

Step run(State s, std::uint16_t cw, Inputs in = {}, std::uint16_t previous = 0)
{
    return step(s, cw, previous, in);
}

} // namespace

TEST(Dsp408StateMachine, Section422Tr0PowerOn)
{
    EXPECT_EQ(powerOn(), (Step{State::NotReady, Transition::Tr0}));
}

TEST(Dsp408StateMachine, Section422Tr1InitialisationDone)
{
    Inputs busy;
    busy.initialised = false;
    EXPECT_EQ(run(State::NotReady, D | H | M, busy), (Step{State::NotReady, Transition::None}));
    EXPECT_EQ(run(State::NotReady, 0), (Step{State::Init, Transition::Tr1}));
}

TEST(Dsp408StateMachine, Section422Tr2DisableBit)
{
    EXPECT_EQ(run(State::Init, D), (Step{State::Disabled, Transition::Tr2}));
    EXPECT_EQ(run(State::Init, H | M), (Step{State::Init, Transition::None}));
    Inputs off;
    off.enable = false;
    EXPECT_EQ(run(State::Init, D, off), (Step{State::Init, Transition::None}));
}

TEST(Dsp408StateMachine, Section422Tr3HoldEnableBit)
{
    EXPECT_EQ(run(State::Disabled, D | H), (Step{State::Hold, Transition::Tr3}));
    EXPECT_EQ(run(State::Disabled, D), (Step{State::Disabled, Transition::None}));
}

TEST(Dsp408StateMachine, Section422Tr4DeviceModeActiveBit)
{
    EXPECT_EQ(run(State::Hold, D | H | M), (Step{State::DeviceModeActive, Transition::Tr4}));
    EXPECT_EQ(run(State::Hold, D | H), (Step{State::Hold, Transition::None}));
}

TEST(Dsp408StateMachine, Section422Tr5DeviceModeActiveCleared)
{
    EXPECT_EQ(run(State::DeviceModeActive, D | H), (Step{State::Hold, Transition::Tr5}));
    EXPECT_EQ(run(State::DeviceModeActive, D | H | M),
              (Step{State::DeviceModeActive, Transition::None}));
}

TEST(Dsp408StateMachine, Section422Tr6HoldEnableCleared)
{
    EXPECT_EQ(run(State::Hold, D), (Step{State::Disabled, Transition::Tr6}));
    EXPECT_EQ(run(State::Hold, D | M), (Step{State::Hold, Transition::None})); // needs M = H = 0
}

TEST(Dsp408StateMachine, Section422Tr7DisableCleared)
{
    EXPECT_EQ(run(State::Disabled, 0), (Step{State::Init, Transition::Tr7}));
    EXPECT_EQ(run(State::Disabled, M), (Step{State::Disabled, Transition::None}));
}

TEST(Dsp408StateMachine, Section422Tr8ErrorPresent)
{
    Inputs error;
    error.errorPresent = true;
    for (State s : {State::Init, State::Disabled, State::Hold, State::DeviceModeActive})
        EXPECT_EQ(run(s, D | H | M, error), (Step{State::FaultReaction, Transition::Tr8}))
            << stateName(s);
}

TEST(Dsp408StateMachine, Section422Tr9ErrorReactionHold)
{
    Inputs in;
    in.reaction = FaultReaction::Hold;
    EXPECT_EQ(run(State::FaultReaction, 0, in), (Step{State::FaultHold, Transition::Tr9}));
    in.faultReactionDone = false;
    EXPECT_EQ(run(State::FaultReaction, 0, in), (Step{State::FaultReaction, Transition::None}));
}

TEST(Dsp408StateMachine, Section422Tr10ErrorResetToDisabled)
{
    // "reset fault" must change from 0 to 1 with H = 0.
    EXPECT_EQ(run(State::Fault, R | D, {}, D), (Step{State::Disabled, Transition::Tr10}));
    EXPECT_EQ(run(State::FaultHold, R, {}, 0), (Step{State::Disabled, Transition::Tr10}));
    EXPECT_EQ(run(State::Fault, R | D, {}, R | D),
              (Step{State::Fault, Transition::None})); // no edge
    Inputs error;
    error.errorPresent = true;
    EXPECT_EQ(run(State::Fault, R, error, 0), (Step{State::Fault, Transition::None}));
}

TEST(Dsp408StateMachine, Section422Tr11ErrorResetToHold)
{
    EXPECT_EQ(run(State::FaultHold, R | H | D, {}, H | D), (Step{State::Hold, Transition::Tr11}));
    // HART-7 manual §4.2.2 keeps TR_11 without FAULT_HOLD: FAULT → HOLD.
    EXPECT_EQ(run(State::Fault, R | H, {}, H), (Step{State::Hold, Transition::Tr11}));
}

TEST(Dsp408StateMachine, Section422Tr12ErrorReactionDisable)
{
    EXPECT_EQ(run(State::FaultReaction, D | H | M), (Step{State::Fault, Transition::Tr12}));
}

TEST(Dsp408StateMachine, Section422Tr567ForcedByEnableOrCommunication)
{
    Inputs off;
    off.enable = false;
    for (State s : {State::Disabled, State::Hold, State::DeviceModeActive})
        EXPECT_EQ(run(s, D | H | M, off), (Step{State::Init, Transition::Tr567})) << stateName(s);
    Inputs comm;
    comm.communicationForced = true;
    EXPECT_EQ(run(State::DeviceModeActive, D | H | M, comm),
              (Step{State::Init, Transition::Tr567}));
}

// ED1/SD1 manual §5.5: set D, H and M in INIT and the device becomes active.
TEST(Dsp408StateMachine, Section55SettleRunsTheStartSequence)
{
    const Settled up = settle(State::Init, D | H | M, 0, {});
    EXPECT_EQ(up.state, State::DeviceModeActive);
    EXPECT_EQ(up.transitions,
              (std::vector<Transition>{Transition::Tr2, Transition::Tr3, Transition::Tr4}));
    const Settled down = settle(State::DeviceModeActive, 0, D | H | M, {});
    EXPECT_EQ(down.state, State::Init);
    EXPECT_EQ(down.transitions,
              (std::vector<Transition>{Transition::Tr5, Transition::Tr6, Transition::Tr7}));
    // §5.6 start after an error: reset fault with D, H, M set → HOLD, then active.
    const Settled restart = settle(State::Fault, R | D | H | M, D | H | M, {});
    EXPECT_EQ(restart.state, State::DeviceModeActive);
    EXPECT_EQ(restart.transitions, (std::vector<Transition>{Transition::Tr11, Transition::Tr4}));
}

TEST(Dsp408StateMachine, StatusBitsAndTexts)
{
    EXPECT_EQ(statusBits(State::Init), status::kReady);
    EXPECT_EQ(statusBits(State::DeviceModeActive), 0x000Fu);
    EXPECT_EQ(statusBits(State::Fault) & status::kReady, 0u);
    for (int s = 0; s <= static_cast<int>(State::Fault); ++s)
        EXPECT_TRUE(stateText(static_cast<State>(s)).complete());
    for (int t = 0; t <= static_cast<int>(Transition::Tr567); ++t)
        EXPECT_TRUE(transitionText(static_cast<Transition>(t)).complete());
    EXPECT_STREQ(transitionName(Transition::Tr10), "TR_10");
}
