// Simulated ED1/SD1 (devices/sim/dsp408_device.h, dsp408_server.h) against the Wandfluh "ED1/SD1
// PROFIBUS-DP Device-Profile" (DSP-408) manual: PKW reads and writes with the §4.6 response ids and
// error codes and the §4.6.1 worked examples, the §4.2.2 state machine walked by PZD control words,
// FAULT on an error (§4.8.1), persistence (§4.4, §4.8.8), and the actual value following the set
// value.
#include "dsp408/pkw.h"
#include "dsp408/pzd.h"
#include "sim/dsp408_device.h"
#include "sim/dsp408_server.h"
#include "sim/sim_clock.h"
#include "sim_dictionaries.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::sim;
using dsp408::Pkw;
using dsp408::State;

namespace {

struct Dsp408Rig
{
    const Dictionary &dict = test::family("wandfluh-ed1");
    Dsp408Device device{dict};
    Dsp408Server server;
    SimClock clock;
    std::uint16_t lastControlWord = 0;

    explicit Dsp408Rig(dsp408::TelegramType type = dsp408::TelegramType::PkwAndPzd)
        : server(device, layout(type))
    {
        clock.attach(device);
    }

    static dsp408::Options layout(dsp408::TelegramType type)
    {
        dsp408::Options o;
        o.telegramType = type;
        return o;
    }

    // One bus cycle with raw bytes in and out.
    Bytes cycleBytes(const Bytes &image)
    {
        server.receive(image);
        return server.drain();
    }

    dsp408::ResponseTelegram cycle(const dsp408::RequestTelegram &request)
    {
        dsp408::Options in;
        in.direction = dsp408::Direction::Request;
        auto image = dsp408::encodeTelegram(request, in);
        EXPECT_TRUE(image.ok());
        const Bytes out = cycleBytes(*image);
        dsp408::Options o;
        o.direction = dsp408::Direction::Response;
        auto rsp = dsp408::decodeResponseTelegram(out, o);
        EXPECT_TRUE(rsp.ok()) << "response of " << out.size() << " bytes";
        return rsp.ok() ? *rsp : dsp408::ResponseTelegram{};
    }

    // The PLC keeps sending its last control word while it uses the parameter channel.
    Pkw pkw(const Pkw &request, std::optional<std::uint16_t> controlWord = std::nullopt)
    {
        if (controlWord)
            lastControlWord = *controlWord;
        const auto rsp = cycle({request, {lastControlWord, 0}});
        EXPECT_TRUE(rsp.pkw.has_value());
        return rsp.pkw.value_or(Pkw{});
    }

    std::uint16_t pzd(std::uint16_t controlWord, std::int32_t setpoint = 0)
    {
        lastControlWord = controlWord;
        return cycle({std::nullopt, {controlWord, setpoint}}).pzd.statusWord;
    }

    const ParamMeta &row(const std::string &name)
    {
        const ParamMeta *meta = dict.find(name);
        EXPECT_NE(meta, nullptr) << name;
        static const ParamMeta none;
        return meta ? *meta : none;
    }

    Pkw write(const std::string &name, std::uint32_t value)
    {
        const ParamMeta &m = row(name);
        const auto length = static_cast<dsp408::ParamLength>(wireBytes(m.type));
        return pkw(dsp408::writeRequest(static_cast<std::uint8_t>(*m.ind),
                                        static_cast<std::uint16_t>(*m.pnu), length, value));
    }

    std::optional<std::uint16_t> error(const Pkw &response) { return dsp408::errorCode(response); }
};

constexpr std::uint16_t kRmhd = 0x000F;

} // namespace

// Every readable row of the dictionary answers its default through PKW, with the response id of
// its length (§4.6: 1 word, 2 double word, 11 byte). Nothing has run yet (NOT_READY, status 0).
TEST(WandfluhSimPkw, ReadOfEveryReadableParameterReturnsTheDictionaryDefault)
{
    Dsp408Rig rig;
    int checked = 0;
    for (const ParamMeta &meta : rig.dict.params) {
        if (!meta.readable())
            continue;
        const auto length = static_cast<dsp408::ParamLength>(wireBytes(meta.type));
        const Pkw rsp = rig.pkw(dsp408::readRequest(static_cast<std::uint8_t>(*meta.ind),
                                                    static_cast<std::uint16_t>(*meta.pnu)));
        ASSERT_FALSE(rig.error(rsp)) << meta.name << " error " << *rig.error(rsp);
        EXPECT_EQ(rsp.ak, dsp408::valueResponseId(length)) << meta.name;
        EXPECT_EQ(rsp.ind, *meta.ind);
        EXPECT_EQ(rsp.pnu, *meta.pnu);
        ASSERT_TRUE(meta.defaultValue) << meta.name;
        EXPECT_EQ(fromWireBits(meta, dsp408::pweValue(rsp.pwe, length)), *meta.defaultValue)
            << meta.name;
        ++checked;
    }
    EXPECT_GE(checked, 40); // 47 rows, 3 of them write-only
}

// §4.6.1 example 1 on the simulator, byte for byte: write 450 to dop_drivePos_AsideVal (IND 3,
// PNU 73). Its limit is dop_drivePos_AsideMaxVal (default 393 raw), so the example's 450 needs a
// larger maximum first; with the default maximum the device answers error 2 (value range).
TEST(WandfluhSimPkw, Section461Example1WriteWord)
{
    Dsp408Rig rig;
    const Bytes request{0x20, 0x49, 0x03, 0x00, 0x00, 0x00, 0x01, 0xC2, 0, 0, 0, 0, 0, 0};
    Bytes rsp = rig.cycleBytes(request);
    ASSERT_EQ(rsp.size(), dsp408::kTelegram1Size);
    EXPECT_EQ(Bytes(rsp.begin(), rsp.begin() + 8),
              (Bytes{0x70, 0x49, 0x03, 0x00, 0x00, 0x00, 0x00, 0x02}));

    EXPECT_FALSE(rig.error(rig.write("dop_drivePos_AsideMaxVal", 1011)));
    rsp = rig.cycleBytes(request);
    EXPECT_EQ(Bytes(rsp.begin(), rsp.begin() + 8),
              (Bytes{0x10, 0x49, 0x03, 0x00, 0x00, 0x00, 0x01, 0xC2}));
    EXPECT_EQ(rig.device.params().value("dop_drivePos_AsideVal"), 450);
}

// §4.6.1 example 2 reads PNU 98 (62h) of IND 3 and gets 100 with AK 11 (Bh): PNU 98 is
// dop_dither_FreqVal (the example's name dop_dither_AmplVal is PNU 101), default 100 Hz.
TEST(WandfluhSimPkw, Section461Example2ReadByte)
{
    Dsp408Rig rig;
    const Bytes rsp =
        rig.cycleBytes({0x10, 0x62, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0, 0, 0, 0, 0, 0});
    ASSERT_EQ(rsp.size(), dsp408::kTelegram1Size);
    EXPECT_EQ(Bytes(rsp.begin(), rsp.begin() + 8),
              (Bytes{0xB0, 0x62, 0x03, 0x00, 0x00, 0x00, 0x00, 0x64}));
}

// §4.6 error codes: 0 undefined PNU, 1 not changeable, 2 value range, 5 data type, 18 other.
TEST(WandfluhSimPkw, RefusalsCarryTheManualsErrorCodes)
{
    Dsp408Rig rig;
    EXPECT_EQ(rig.error(rig.write("dpc_SetpointVal", 5000)), 2);      // 0 … 4096
    EXPECT_EQ(rig.error(rig.write("dop_dither_FreqVal", 10)), 2);     // 20 … 250
    EXPECT_EQ(rig.error(rig.write("dop_drivePos_AsideVal", 400)), 2); // max_param AsideMaxVal = 393
    EXPECT_FALSE(rig.error(rig.write("dop_drivePos_AsideVal", 393)));
    EXPECT_EQ(rig.error(rig.write("dop_drivePos_AsideMaxVal", 392)), 2); // min_param AsideVal = 393
    EXPECT_EQ(rig.error(rig.write("db_StatusWord", 1)), 1);
    EXPECT_EQ(rig.error(rig.write("dav_transducer_Type", 67)), 1);
    EXPECT_EQ(rig.error(rig.pkw(dsp408::readRequest(3, 74))), 0);
    EXPECT_EQ(rig.error(rig.pkw(dsp408::readRequest(99, 73))), 0);
    // A word written to a byte row: data type error.
    EXPECT_EQ(rig.error(rig.pkw(dsp408::writeRequest(3, 97, dsp408::ParamLength::Word, 1))), 5);
    // Reading a write-only command row: other error.
    EXPECT_EQ(rig.error(rig.pkw(dsp408::readRequest(0, 37))), 18);
    // db_ResetDefault accepts 0 and 'load' only.
    EXPECT_EQ(rig.error(rig.write("db_ResetDefault", 12345)), 2);
    // Each refusal left the values alone.
    EXPECT_EQ(rig.device.params().value("dpc_SetpointVal"), 0);
    EXPECT_EQ(rig.device.params().value("dop_dither_FreqVal"), 100);
    // A reserved AK (4 … 9): error 18 for the same IND / PNU.
    const Bytes rsp = rig.cycleBytes({0x40, 0x49, 0x03, 0x00, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
    EXPECT_EQ(Bytes(rsp.begin(), rsp.begin() + 8),
              (Bytes{0x70, 0x49, 0x03, 0x00, 0x00, 0x00, 0x00, 0x12}));
}

TEST(WandfluhSimPkw, SignedAndDoubleWordRows)
{
    Dsp408Rig rig;
    Pkw rsp = rig.write("dav_transducer_Offset", static_cast<std::uint32_t>(-100));
    ASSERT_FALSE(rig.error(rsp));
    EXPECT_EQ(rsp.ak, 2);
    EXPECT_EQ(rig.device.params().value("dav_transducer_Offset"), -100);
    EXPECT_EQ(rig.error(rig.write("dav_transducer_Offset", static_cast<std::uint32_t>(-3000))), 2);
    rsp = rig.write("dpc_ramp_Type", 0xFF); // int8 −1
    ASSERT_FALSE(rig.error(rsp));
    EXPECT_EQ(rig.device.params().value("dpc_ramp_Type"), -1);
    rsp = rig.pkw(dsp408::readRequest(12, 42));
    EXPECT_EQ(rsp.ak, 11);
    EXPECT_EQ(rsp.pwe, 0xFFu);
}

// The PLC repeats its PKW request every cycle until it sees the answer: a write is executed once.
TEST(WandfluhSimPkw, RepeatedWriteRequestIsExecutedOnce)
{
    Dsp408Rig rig;
    const Pkw request = dsp408::writeRequest(3, 98, dsp408::ParamLength::Byte, 50);
    EXPECT_FALSE(rig.error(rig.pkw(request)));
    rig.device.params().set("dop_dither_FreqVal", 25);              // changed locally (PASO)
    EXPECT_EQ(rig.pkw(request).pwe, 50u);                           // the same answer again …
    EXPECT_EQ(rig.device.params().value("dop_dither_FreqVal"), 25); // … without a second write
    rig.pkw(Pkw{}); // AK 0 between two equal requests
    EXPECT_FALSE(rig.error(rig.pkw(request)));
    EXPECT_EQ(rig.device.params().value("dop_dither_FreqVal"), 50);
}

TEST(WandfluhSimPkw, StoreParameterKeepsSettingsOverAPowerCycle)
{
    Dsp408Rig rig;
    EXPECT_FALSE(rig.error(rig.write("dop_dither_FreqVal", 50)));
    rig.device.powerCycle();
    EXPECT_EQ(rig.device.params().value("dop_dither_FreqVal"), 100); // not stored
    EXPECT_FALSE(rig.error(rig.write("dop_dither_FreqVal", 50)));
    EXPECT_FALSE(rig.error(rig.write("db_StoreParameter", kStoreParameterSave)));
    rig.device.powerCycle();
    EXPECT_EQ(rig.device.params().value("dop_dither_FreqVal"), 50);
    EXPECT_EQ(rig.device.state(), State::NotReady);
    EXPECT_FALSE(rig.error(rig.write("db_ResetDefault", kResetDefaultLoad)));
    EXPECT_EQ(rig.device.params().value("dop_dither_FreqVal"), 100);
}

// §4.2.2: NOT_READY → (self test) INIT → TR_2 DISABLED → TR_3 HOLD → TR_4 DEVICE_MODE_ACTIVE by
// control words in type-2 PZD telegrams; the status word reports R M H D per state.
TEST(WandfluhSimStateMachine, ControlWordsInPzdWalkToDeviceModeActive)
{
    Dsp408Rig rig(dsp408::TelegramType::PzdOnly);
    EXPECT_EQ(rig.pzd(0x0000) & kRmhd, 0x0000); // NOT_READY, self test running
    EXPECT_EQ(rig.device.state(), State::NotReady);
    rig.clock.advance(50'000);
    EXPECT_EQ(rig.pzd(0x0000) & kRmhd, 0x0008); // INIT: R
    EXPECT_EQ(rig.pzd(0x0001) & kRmhd, 0x0009); // DISABLED: R D
    EXPECT_EQ(rig.device.state(), State::Disabled);
    EXPECT_EQ(rig.pzd(0x0003) & kRmhd, 0x000B); // HOLD: R H D
    EXPECT_EQ(rig.device.state(), State::Hold);
    EXPECT_EQ(rig.pzd(0x0007) & kRmhd, 0x000F); // DEVICE_MODE_ACTIVE: R M H D
    EXPECT_EQ(rig.device.state(), State::DeviceModeActive);
    using dsp408::Transition;
    const std::vector<Transition> walked{Transition::Tr0, Transition::Tr1, Transition::Tr2,
                                         Transition::Tr3, Transition::Tr4};
    EXPECT_EQ(rig.device.drive().history(), walked);
    // And back down: 0 runs TR_5, TR_6, TR_7 within one cycle.
    EXPECT_EQ(rig.pzd(0x0000) & kRmhd, 0x0008);
    EXPECT_EQ(rig.device.state(), State::Init);
}

// §4.8.1: every error's reaction is FAULT (TR_8, TR_12); TR_10/TR_11 need the error gone and the
// "reset fault" bit's 0 → 1 edge.
TEST(WandfluhSimStateMachine, ErrorGoesToFaultAndResetNeedsTheEdge)
{
    Dsp408Rig rig(dsp408::TelegramType::PzdOnly);
    rig.clock.advance(50'000);
    rig.pzd(0x0007);
    ASSERT_EQ(rig.device.state(), State::DeviceModeActive);
    rig.device.injectError(dsp408_error::kTransducer);
    EXPECT_EQ(rig.device.state(), State::Fault);
    EXPECT_EQ(rig.pzd(0x0007) & kRmhd, 0x0001); // FAULT: D only, R off
    // db_ErrorCode reads the error over PKW.
    Dsp408Rig pkwRig;
    pkwRig.device.injectError(dsp408_error::kCommunication);
    EXPECT_EQ(pkwRig.pkw(dsp408::readRequest(0, 36)).pwe, 0x8100u);

    EXPECT_EQ(rig.pzd(0x000F) & kRmhd, 0x0001); // reset edge while the error is present: refused
    rig.device.clearError();
    EXPECT_EQ(rig.pzd(0x000F) & kRmhd, 0x0001); // bit still 1: no edge
    EXPECT_EQ(rig.pzd(0x0007) & kRmhd, 0x0001);
    EXPECT_EQ(rig.pzd(0x000F) & kRmhd, 0x000F); // edge: TR_11 to HOLD, then TR_4 (M H D set)
    EXPECT_EQ(rig.device.state(), State::DeviceModeActive);
}

TEST(WandfluhSimStateMachine, EnableInputOffForcesInit)
{
    Dsp408Rig rig(dsp408::TelegramType::PzdOnly);
    rig.clock.advance(50'000);
    rig.pzd(0x0007);
    rig.device.setEnableInput(false);
    EXPECT_EQ(rig.device.state(), State::Init); // TR_567
    EXPECT_EQ(rig.pzd(0x0007) & kRmhd, 0x0008); // TR_2 blocked while Enable is off
    rig.device.setEnableInput(true);
    EXPECT_EQ(rig.pzd(0x0007) & kRmhd, 0x000F);
}

// §4.2.1 / §4.3.1: in local mode the bus control word is ignored and the device mode becomes
// "preset value locally"; the modes change only in INIT / DISABLED.
TEST(WandfluhSimStateMachine, LocalModeAndModeChanges)
{
    Dsp408Rig rig;
    rig.clock.advance(50'000);
    rig.pkw(Pkw{}, 0x0007);
    ASSERT_EQ(rig.device.state(), State::DeviceModeActive);
    EXPECT_EQ(rig.error(rig.write("db_ControlMode", 6)), 18); // not in DEVICE_MODE_ACTIVE
    rig.pkw(Pkw{}, 0x0001);
    EXPECT_FALSE(rig.error(rig.write("db_ControlMode", 6)));
    EXPECT_FALSE(rig.error(rig.write("db_Local", 1)));
    EXPECT_EQ(rig.device.params().value("db_DeviceMode"), 2);
    EXPECT_EQ(rig.error(rig.write("db_DeviceMode", 1)), 18);
    const auto status = rig.cycle({Pkw{}, {0x0007, 0}}).pzd.statusWord;
    EXPECT_EQ(status & dsp408::status::kLocal, dsp408::status::kLocal);
    EXPECT_EQ(rig.device.state(), State::Disabled); // bus control word ignored
    rig.device.setLocalControlWord(0x0007);
    EXPECT_EQ(rig.device.state(), State::DeviceModeActive);
}

// The actual value follows the set value (first order, τ = 0.1 s) in DEVICE_MODE_ACTIVE only;
// HOLD keeps the set value present when it was entered.
TEST(WandfluhSimActuator, ActualFollowsSetValueWhenActive)
{
    Dsp408Rig rig(dsp408::TelegramType::PzdOnly);
    rig.clock.advance(50'000);
    rig.pzd(0x0001, 2000); // DISABLED: nothing moves
    rig.clock.advance(500'000);
    EXPECT_EQ(rig.device.actualValue(), 0);
    rig.pzd(0x0007, 2000);
    rig.clock.advance(100'000); // one time constant: 63 %
    EXPECT_NEAR(rig.device.drive().actualExact(), 2000 * (1 - std::exp(-1.0)), 1.0);
    EXPECT_EQ(rig.pzd(0x0007, 2000) & dsp408::status::kInTargetWindow, 0);
    rig.clock.advance(900'000);
    const auto rsp = rig.cycle({std::nullopt, {0x0007, 2000}});
    EXPECT_EQ(rsp.pzd.actualValue, 2000);
    EXPECT_EQ(rsp.pzd.statusWord & dsp408::status::kInTargetWindow,
              dsp408::status::kInTargetWindow);
    // HOLD: a new set value is not followed.
    rig.pzd(0x0003, 2000);
    rig.pzd(0x0003, 100);
    rig.clock.advance(1'000'000);
    EXPECT_EQ(rig.device.actualValue(), 2000);
    // Out-of-range PZD set values are clamped to the row's range (0 … 4096).
    rig.pzd(0x0007, 100000);
    rig.clock.advance(2'000'000);
    EXPECT_EQ(rig.device.actualValue(), 4096);
}

TEST(WandfluhSimServer, ImagesInAnyChunksAndTheSameResultForAnyClockChunking)
{
    Dsp408Rig a(dsp408::TelegramType::PzdOnly);
    Dsp408Rig b(dsp408::TelegramType::PzdOnly);
    const Bytes image{0x00, 0x07, 0x00, 0x00, 0x03, 0xE8}; // control word 7, set value 1000
    a.clock.advance(50'000);
    b.clock.advance(50'000);
    EXPECT_EQ(a.cycleBytes(image).size(), 6u);
    b.server.receive(std::span<const std::uint8_t>(image).first(4));
    EXPECT_TRUE(b.server.drain().empty());
    b.server.receive(std::span<const std::uint8_t>(image).subspan(4));
    EXPECT_EQ(b.server.drain().size(), 6u);
    a.clock.advance(333'333);
    for (int i = 0; i < 1000; ++i)
        b.clock.advance(333);
    b.clock.advance(333);
    EXPECT_EQ(a.device.drive().actualExact(), b.device.drive().actualExact());
    EXPECT_EQ(a.server.exchanges(), 1u);
}
