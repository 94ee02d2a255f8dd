// SD7 HART responder (devices/sim/hart_device.h, hart_server.h) against the Wandfluh "HART-7
// Interface" manual: command 0 identity (§3.4, §5.1.1), addressing (§2.3), tag / long tag /
// descriptor / date persistence (§5.1.11, §5.1.16, §5.1.18, §5.1.20), configuration-changed flag
// and command 38 (§4.4.1 status byte 2, §5.1.21), device-specific commands 128..133 (§4.4.1, §5.2).
#include "hart/device_specific.h"
#include "hart/frame.h"
#include "hart/universal.h"
#include "sim/hart_device.h"
#include "sim/hart_server.h"
#include "sim/sim_clock.h"
#include "sim_dictionaries.h"

#include <gtest/gtest.h>
#include <optional>
#include <variant>

using namespace vt::dev;
using namespace vt::dev::sim;

namespace {

constexpr std::uint16_t kSd733 = 58352;

struct HartRig
{
    HartDevice device;
    HartServer server{device};
    SimClock clock;

    explicit HartRig(HartDevice::Options options = {})
        : device(test::family("wandfluh-sd7"), std::move(options))
    {
        clock.attach(device);
    }

    // One request over the byte stream; the decoded answer or nullopt when the device is silent.
    std::optional<hart::Frame> transact(const hart::Frame &request)
    {
        auto bytes = hart::encodeFrame(request);
        EXPECT_TRUE(bytes.ok());
        server.receive(*bytes);
        const auto out = server.drain();
        if (out.empty())
            return std::nullopt;
        auto frame = hart::decodeFrame(out);
        EXPECT_TRUE(frame.ok()) << describeError(frame.error()).en;
        return frame.ok() ? std::optional<hart::Frame>(*frame) : std::nullopt;
    }

    hart::Identity command0(std::uint8_t poll = 0)
    {
        auto rsp = transact(hart::makeRequest(hart::shortAddress(poll), 0));
        EXPECT_TRUE(rsp.has_value());
        if (!rsp)
            return {};
        auto id = hart::decodeUniversal(0, true, rsp->data);
        EXPECT_TRUE(id.ok());
        return std::get<hart::Identity>(*id);
    }

    std::optional<hart::Frame> longRequest(std::uint8_t command, Bytes data = {},
                                           bool primary = true)
    {
        return transact(
            hart::makeRequest(device.identity().address(primary), command, std::move(data)));
    }

    template<typename T> T payload(std::uint8_t command, const hart::Frame &rsp)
    {
        auto p = hart::decodeUniversal(command, true, rsp.data);
        EXPECT_TRUE(p.ok());
        return p.ok() ? std::get<T>(*p) : T{};
    }
};

Bytes tdd(const std::string &tag, const std::string &descriptor, hart::Date date)
{
    return hart::encodePayload(hart::TagDescriptorDate{tag, descriptor, date});
}

} // namespace

// Command 0 answers with the manual's manufacturer id 24835 (§3.4, 0x6103) and
// the SD733 device type 58352; the long address is built from them (§2.3: 14 bits of the type).
TEST(HartSimCommand0, ShortFrameAnswersManufacturerAndSd733DeviceType)
{
    HartRig rig;
    auto rsp = rig.transact(hart::makeRequest(hart::shortAddress(0), 0));
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->type, hart::FrameType::Ack);
    EXPECT_FALSE(rsp->address.isLong);
    EXPECT_EQ(rsp->address.pollAddress, 0);
    EXPECT_TRUE(rsp->address.primaryMaster);
    EXPECT_EQ(rsp->responseCode, 0);
    EXPECT_EQ(rsp->data.size(), 22u); // HART 7 layout, §5.1.1 bytes 0..21
    auto p = hart::decodeUniversal(0, true, rsp->data);
    ASSERT_TRUE(p.ok());
    const auto id = std::get<hart::Identity>(*p);
    EXPECT_EQ(id.manufacturerId, 24835);
    EXPECT_EQ(id.expandedDeviceType, kSd733);
    EXPECT_EQ(id.expansionCode, 254);
    EXPECT_EQ(id.hartRevision, 7);
    EXPECT_EQ(id.deviceId, 2412345u);
    EXPECT_EQ(id.privateLabel, 24835); // §5.1.13 remarks
    EXPECT_EQ(id.minResponsePreambles, 5);
    const hart::Address address = id.address();
    EXPECT_TRUE(address.isLong);
    EXPECT_EQ(address.expandedDeviceType, 0x23F0); // 0xE3F0 & 0x3FFF (protocol notes H2)
    EXPECT_EQ(address.deviceId, 2412345u);
    EXPECT_EQ(address, rig.device.address());
    // The response carries the device's response preambles.
    EXPECT_EQ(rsp->preambles, 5u);
}

TEST(HartSimCommand0, ConfiguredDeviceIdTypeAndPollAddress)
{
    HartDevice::Options o;
    o.expandedDeviceType = 58353; // SD736
    o.deviceId = 0xABCDEF;
    o.pollAddress = 7;
    HartRig rig(o);
    EXPECT_FALSE(rig.transact(hart::makeRequest(hart::shortAddress(0), 0))); // other poll address
    const hart::Identity id = rig.command0(7);
    EXPECT_EQ(id.expandedDeviceType, 58353);
    EXPECT_EQ(id.deviceId, 0xABCDEFu);
    // Long frame with the address from command 0 works too.
    auto rsp = rig.transact(hart::makeRequest(id.address(), 0));
    ASSERT_TRUE(rsp);
    EXPECT_TRUE(rsp->address.isLong);
    EXPECT_EQ(rsp->address, id.address());
}

// §2.3 / ARCHITECTURE.md: the short frame is for command 0 only; afterwards the long address.
TEST(HartSimAddressing, ShortFrameWithOtherCommandGetsNoAnswer)
{
    HartRig rig;
    EXPECT_FALSE(rig.transact(hart::makeRequest(hart::shortAddress(0), 13)));
    EXPECT_EQ(rig.server.framesIgnored(), 1u);
}

TEST(HartSimAddressing, LongFrameToWrongAddressGetsNoAnswer)
{
    HartRig rig;
    const hart::Identity id = rig.command0();
    EXPECT_FALSE(rig.transact(
        hart::makeRequest(hart::longAddress(id.expandedDeviceType, id.deviceId + 1), 13)));
    EXPECT_FALSE(rig.transact(hart::makeRequest(hart::longAddress(58353, id.deviceId), 13)));
    // The broadcast address is for commands 11 and 21 only.
    EXPECT_FALSE(rig.transact(hart::makeRequest(hart::longAddress(0, 0), 13)));
    auto rsp = rig.transact(hart::makeRequest(id.address(), 13));
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 0);
}

TEST(HartSimAddressing, MasterBitIsEchoedBurstBitClear)
{
    HartRig rig;
    hart::Address secondary = rig.device.address();
    secondary.primaryMaster = false;
    secondary.burst = true;
    auto rsp = rig.transact(hart::makeRequest(secondary, 0));
    ASSERT_TRUE(rsp);
    EXPECT_FALSE(rsp->address.primaryMaster);
    EXPECT_FALSE(rsp->address.burst);
}

TEST(HartSimAddressing, AckFramesOfOtherDevicesAreIgnored)
{
    HartRig rig;
    hart::Frame ack = hart::makeResponse(hart::shortAddress(0), 0, 0, 0);
    EXPECT_FALSE(rig.transact(ack));
}

// §2.3 "Parity": a frame with a wrong checksum is not answered; the next good frame is.
TEST(HartSimLink, BadChecksumGetsNoAnswerAndTheStreamRecovers)
{
    HartRig rig;
    auto bytes = hart::encodeFrame(hart::makeRequest(hart::shortAddress(0), 0));
    ASSERT_TRUE(bytes.ok());
    Bytes broken = *bytes;
    broken.back() ^= 0x01;
    rig.server.receive(broken);
    EXPECT_TRUE(rig.server.drain().empty());
    EXPECT_EQ(rig.server.framesRejected(), 1u);
    rig.server.receive(*bytes);
    EXPECT_FALSE(rig.server.drain().empty());
}

TEST(HartSimLink, FrameSplitIntoSingleBytesIsAnsweredOnce)
{
    HartRig rig;
    auto bytes = hart::encodeFrame(hart::makeRequest(hart::shortAddress(0), 0));
    ASSERT_TRUE(bytes.ok());
    Bytes out;
    for (const std::uint8_t b : *bytes) {
        rig.server.receive(std::span<const std::uint8_t>(&b, 1));
        const auto chunk = rig.server.drain();
        out.insert(out.end(), chunk.begin(), chunk.end());
    }
    auto rsp = hart::decodeFrame(out);
    ASSERT_TRUE(rsp.ok());
    EXPECT_EQ(rsp->command, 0);
    EXPECT_EQ(rig.server.framesAnswered(), 1u);
}

TEST(HartSimLink, UnsupportedCommandAndShortDataGetTheirResponseCodes)
{
    HartRig rig;
    auto rsp = rig.longRequest(35); // not in §5.1: HART "command not implemented"
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 64);
    EXPECT_TRUE(rsp->data.empty());
    rsp = rig.longRequest(18, Bytes{1, 2, 3}); // §4.4.1 "5 wrong byte count"
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 5);
    rsp = rig.longRequest(131, Bytes{250, 6}); // IND, PNU without instance and value
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 5);
}

// Tag writes persist (command 18 then 13).
TEST(HartSimTag, WriteTagDescriptorDateThenReadBack)
{
    HartRig rig;
    const hart::Date date{24, 12, 125};
    auto rsp = rig.longRequest(18, tdd("valve 01", "pressure line a", date));
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 0);
    const auto echoed = rig.payload<hart::TagDescriptorDate>(18, *rsp);
    EXPECT_EQ(echoed.tag, "VALVE 01"); // packed ASCII is upper case (protocol notes H13)
    rsp = rig.longRequest(13);
    ASSERT_TRUE(rsp);
    const auto read = rig.payload<hart::TagDescriptorDate>(13, *rsp);
    EXPECT_EQ(read.tag, "VALVE 01");
    EXPECT_EQ(read.descriptor, "PRESSURE LINE A");
    EXPECT_EQ(read.date, date);
    EXPECT_EQ(rig.device.tag(), "VALVE 01");
    // Command 11 finds the device by its new tag on the broadcast address, not by the old one.
    auto found = rig.transact(
        hart::makeRequest(hart::longAddress(0, 0), 11, hart::encodePayload(hart::Tag{"VALVE 01"})));
    ASSERT_TRUE(found);
    EXPECT_EQ(rig.payload<hart::Identity>(11, *found).manufacturerId, 24835);
    EXPECT_FALSE(rig.transact(hart::makeRequest(hart::longAddress(0, 0), 11,
                                                hart::encodePayload(hart::Tag{"WAGSD733"}))));
}

TEST(HartSimTag, DeliveryStateAndInvalidDate)
{
    HartRig rig;
    auto rsp = rig.longRequest(13);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rig.payload<hart::TagDescriptorDate>(13, *rsp).tag, "WAGSD733"); // §6.4 "WAGSD7xx"
    rsp = rig.longRequest(18, tdd("X", "Y", hart::Date{0, 13, 100}));
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 9); // HART cmd 18: invalid date code
    EXPECT_EQ(rig.device.tag(), "WAGSD733");
}

TEST(HartSimTag, LongTagMessageAndFinalAssemblyPersist)
{
    HartRig rig;
    auto rsp = rig.longRequest(20);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rig.payload<hart::LongTag>(20, *rsp).text, "Wandfluh AG - SD733");
    ASSERT_TRUE(rig.longRequest(22, hart::encodePayload(hart::LongTag{"Presse 3 – Zylinder B"})));
    rsp = rig.longRequest(20);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rig.payload<hart::LongTag>(20, *rsp).text,
              "Presse 3 ? Zylinder B"); // en dash not Latin-1
    auto found = rig.transact(hart::makeRequest(
        hart::longAddress(0, 0), 21, hart::encodePayload(hart::LongTag{"Presse 3 ? Zylinder B"})));
    ASSERT_TRUE(found);

    ASSERT_TRUE(rig.longRequest(17, hart::encodePayload(hart::Message{"check seals 2026"})));
    rsp = rig.longRequest(12);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rig.payload<hart::Message>(12, *rsp).text, "CHECK SEALS 2026");

    ASSERT_TRUE(rig.longRequest(19, hart::encodePayload(hart::FinalAssemblyNumber{123456})));
    rsp = rig.longRequest(16);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rig.payload<hart::FinalAssemblyNumber>(16, *rsp).number, 123456u);
}

// §4.4.1 status byte 2 bit 6 "configuration changed", set by a write; §5.1.21 command 38 resets it.
TEST(HartSimConfigChanged, SetByWriteResetByCommand38)
{
    HartRig rig;
    auto rsp = rig.longRequest(13);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->deviceStatus & hart_status::kColdStart, hart_status::kColdStart); // first answer
    EXPECT_EQ(rsp->deviceStatus & hart_status::kConfigChanged, 0);
    rsp = rig.longRequest(13);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->deviceStatus, 0); // cold start reported once

    const std::uint16_t before = rig.command0().configChangeCounter;
    rsp = rig.longRequest(18, tdd("NEWTAG", "D", hart::Date{1, 1, 126}));
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->deviceStatus & hart_status::kConfigChanged, hart_status::kConfigChanged);
    const std::uint16_t counter = rig.command0().configChangeCounter;
    EXPECT_EQ(counter, before + 1);

    // A wrong counter does not reset the flag (HART 7 command 38 response code 9).
    rsp = rig.longRequest(
        38, hart::encodePayload(hart::ConfigChangeCounter{std::uint16_t(counter + 5)}));
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 9);
    EXPECT_TRUE(rig.device.configChanged(true));

    rsp = rig.longRequest(38, hart::encodePayload(hart::ConfigChangeCounter{counter}));
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 0);
    EXPECT_EQ(rig.payload<hart::ConfigChangeCounter>(38, *rsp).counter, counter);
    EXPECT_EQ(rsp->deviceStatus & hart_status::kConfigChanged, 0);
    rsp = rig.longRequest(13);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->deviceStatus & hart_status::kConfigChanged, 0);
    // The secondary master's flag is its own and still set.
    EXPECT_TRUE(rig.device.configChanged(false));
    // A HART 5 master's command 38 without counter resets it as well.
    rsp = rig.longRequest(38, {}, false);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 0);
    EXPECT_FALSE(rig.device.configChanged(false));
}

TEST(HartSimPollAddress, Command6MovesTheShortAddress)
{
    HartRig rig;
    auto rsp = rig.longRequest(6, Bytes{5, 1});
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 0);
    EXPECT_FALSE(rig.transact(hart::makeRequest(hart::shortAddress(0), 0)));
    EXPECT_EQ(rig.command0(5).manufacturerId, 24835);
    rsp = rig.longRequest(7);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rig.payload<hart::LoopConfiguration>(7, *rsp), (hart::LoopConfiguration{5, 1}));
    rsp = rig.longRequest(6, Bytes{16, 1}); // §3.4 "0 … 15"
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 2);
}

// §4.4.1 example 1 on the simulator: "Imin solenoid 1" (IND 250, PNU 6, instance 0) = 450,
// command 131; read back with command 130.
TEST(HartSimDeviceSpecific, WriteAndReadBackByIndPnuInstance)
{
    HartRig rig;
    const hart::ParamRef imin{250, 6, 0};
    auto data = hart::encodeParamAccess(hart::writeParam(hart::ValueType::Int16, imin, 450), false);
    ASSERT_TRUE(data.ok());
    auto rsp = rig.longRequest(131, *data);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 0);
    EXPECT_EQ(rsp->data, (Bytes{0xFA, 0x06, 0x00, 0x01, 0xC2}));
    EXPECT_EQ(rsp->deviceStatus & hart_status::kConfigChanged, hart_status::kConfigChanged);

    rsp = rig.longRequest(
        130, *hart::encodeParamAccess(hart::readParam(hart::ValueType::Int16, imin), false));
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 0);
    auto read = hart::decodeParamAccess(130, true, rsp->data);
    ASSERT_TRUE(read.ok());
    EXPECT_EQ(read->ref, imin);
    EXPECT_EQ(read->raw, 450u);
    EXPECT_EQ(rig.device.params().value("sol1_Imin"), 450);
}

TEST(HartSimDeviceSpecific, ReadsDefaultsOfSignedRows)
{
    HartRig rig;
    // fcv_Value3, §4.4.1 example 2 (INT32, command 132): default 0.
    auto rsp = rig.longRequest(132, Bytes{238, 8, 0});
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->data, (Bytes{238, 8, 0, 0, 0, 0, 0}));
    // cv_MinInterfaceFieldbus (IND 232, PNU 9, int32) default -16384 travels as two's complement.
    rsp = rig.longRequest(132, Bytes{232, 9, 0});
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->data, (Bytes{232, 9, 0, 0xFF, 0xFF, 0xC0, 0x00}));
}

// Refusals answer "6 device specific error" (§4.4.1) and leave the value as it was.
TEST(HartSimDeviceSpecific, RefusalsAnswerDeviceSpecificError)
{
    HartRig rig;
    // dcol_CommandValue (IND 11, PNU 21) is limited by cv_MaxInterfaceFieldbus (16383).
    auto rsp = rig.longRequest(133, Bytes{11, 21, 0, 0x00, 0x00, 0x4E, 0x20}); // 20000
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 6);
    EXPECT_TRUE(rsp->data.empty());
    EXPECT_EQ(rig.device.params().value("dcol_CommandValue"), 0);
    rsp = rig.longRequest(133, Bytes{11, 21, 0, 0x00, 0x00, 0x3F, 0xFF}); // 16383 fits
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->responseCode, 0);

    EXPECT_EQ(rig.longRequest(130, Bytes{99, 99, 0})->responseCode, 6);      // no such IND/PNU
    EXPECT_EQ(rig.longRequest(130, Bytes{250, 6, 1})->responseCode, 6);      // no instance 1
    EXPECT_EQ(rig.longRequest(129, Bytes{250, 6, 0, 1})->responseCode, 6);   // 1 byte to an int16
    EXPECT_EQ(rig.longRequest(131, Bytes{0, 38, 0, 0, 1})->responseCode, 6); // status word is r
    EXPECT_EQ(rig.longRequest(130, Bytes{0, 37, 0})->responseCode, 6);       // control word is w
    EXPECT_EQ(rig.device.configChangeCounter(), 1); // only the accepted write counted
}

TEST(HartSimDeviceSpecific, CommonResponseCodesOption)
{
    HartDevice::Options o;
    o.commonResponseCodes = true;
    HartRig rig(o);
    EXPECT_EQ(rig.longRequest(133, Bytes{11, 21, 0, 0x00, 0x00, 0x4E, 0x20})->responseCode, 3);
    EXPECT_EQ(rig.longRequest(133, Bytes{11, 21, 0, 0xFF, 0xFF, 0x00, 0x00})->responseCode, 4);
    EXPECT_EQ(rig.longRequest(130, Bytes{99, 99, 0})->responseCode, 2);
    EXPECT_EQ(rig.longRequest(131, Bytes{0, 38, 0, 0, 1})->responseCode, 16);
}

// HART-7 manual §4.2: the SD7 runs the same device state machine; in bus mode ("Device local" = 0)
// the control word written with command 131 moves it, the status word reads the state.
TEST(HartSimDeviceSpecific, ControlWordDrivesTheStateMachine)
{
    HartRig rig;
    rig.clock.advance(100'000);                                           // self test done: INIT
    EXPECT_EQ(rig.longRequest(129, Bytes{0, 41, 0, 0})->responseCode, 0); // db_Local = 0 (bus)
    EXPECT_EQ(rig.longRequest(131, Bytes{0, 37, 0, 0x00, 0x07})->responseCode, 0);
    auto rsp = rig.longRequest(130, Bytes{0, 38, 0});
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->data, (Bytes{0, 38, 0, 0x00, 0x0F})); // R M H D = DEVICE_MODE_ACTIVE
    // Modes are refused outside INIT / DISABLED.
    EXPECT_EQ(rig.longRequest(129, Bytes{0, 41, 0, 1})->responseCode, 6);
    // An error: FAULT, "device malfunction" and "more status available" in status byte 2.
    rig.device.injectError(0x1000);
    rsp = rig.longRequest(48);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rsp->deviceStatus & hart_status::kMalfunction, hart_status::kMalfunction);
    EXPECT_EQ(rsp->deviceStatus & hart_status::kMoreStatus, hart_status::kMoreStatus);
    const auto status = rig.payload<hart::AdditionalStatus>(48, *rsp);
    EXPECT_EQ(status.at(0), 0x10);
    EXPECT_EQ(status.at(1), 0x00);
}

TEST(HartSimProcessValues, LoopCurrentAndDynamicVariables)
{
    HartRig rig;
    rig.device.setLoopCurrent(12.0f);
    auto rsp = rig.longRequest(2);
    ASSERT_TRUE(rsp);
    const auto loop = rig.payload<hart::LoopCurrent>(2, *rsp);
    EXPECT_FLOAT_EQ(loop.currentMa, 12.0f);
    EXPECT_FLOAT_EQ(loop.percentOfRange, 50.0f);
    rsp = rig.longRequest(1);
    ASSERT_TRUE(rsp);
    EXPECT_FLOAT_EQ(rig.payload<hart::UnitValue>(1, *rsp).value, 0.0f); // §5.1.2: open loop → 0
    rsp = rig.longRequest(3);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rig.payload<hart::DynamicVariables>(3, *rsp).variables.size(), 4u);
    rsp = rig.longRequest(9, Bytes{0, 1, 246});
    ASSERT_TRUE(rsp);
    const auto vars = rig.payload<hart::DeviceVariables>(9, *rsp);
    ASSERT_EQ(vars.variableSlots.size(), 3u);
    EXPECT_FLOAT_EQ(vars.variableSlots[1].value, 50.0f);
    EXPECT_TRUE(vars.timestamp.has_value());
    EXPECT_EQ(rig.longRequest(9, Bytes{7})->responseCode, 2);
    rsp = rig.longRequest(15);
    ASSERT_TRUE(rsp);
    EXPECT_EQ(rig.payload<hart::DeviceInfo>(15, *rsp).writeProtect, 251); // §5.1.13 remarks
    for (const std::uint8_t cmd : {std::uint8_t{8}, std::uint8_t{14}})
        EXPECT_EQ(rig.longRequest(cmd)->responseCode, 0) << int(cmd);
}

// A set value moves the actual value (docs/SIMULATOR.md "Commissioned preset": the SD7 needs no
// preset): switched to the bus and to position control (dpc) in INIT, enabled with the control
// word, dpc_ActualValue follows dpc_CommandValue written over HART.
TEST(HartSimProcessValues, BusCommandValueMovesTheActualValue)
{
    HartRig rig;
    rig.clock.advance(100'000);                                           // self test done: INIT
    EXPECT_EQ(rig.longRequest(129, Bytes{0, 41, 0, 0})->responseCode, 0); // db_Local = 0 (bus)
    EXPECT_EQ(rig.longRequest(129, Bytes{0, 40, 0, 9})->responseCode, 0); // db_ControlMode dpc
    EXPECT_EQ(rig.longRequest(131, Bytes{0, 37, 0, 0x00, 0x07})->responseCode, 0); // enable
    // dpc_CommandValue (IND 12, PNU 21) = 8000 of the internal resolution 16384.
    EXPECT_EQ(rig.longRequest(133, Bytes{12, 21, 0, 0x00, 0x00, 0x1F, 0x40})->responseCode, 0);
    const auto actual = [&rig] {
        const auto rsp = rig.longRequest(132, Bytes{12, 100, 0}); // dpc_ActualValue
        EXPECT_TRUE(rsp && rsp->data.size() == 7);
        if (!rsp || rsp->data.size() != 7)
            return std::int32_t{-1};
        return static_cast<std::int32_t>(
            (std::uint32_t{rsp->data[3]} << 24) | (std::uint32_t{rsp->data[4]} << 16) |
            (std::uint32_t{rsp->data[5]} << 8) | std::uint32_t{rsp->data[6]});
    };
    const std::int32_t before = actual();
    rig.clock.advance(1'000'000); // ten time constants of the actuator
    EXPECT_LT(before, 8000);
    EXPECT_NEAR(actual(), 8000, 1);
}
