// Universal command payloads against the HART-7 manual §5.1 and the data encodings of §2.3.
#include "hart/data_types.h"
#include "hart/describe.h"
#include "hart/universal.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hart;

namespace {

// A Wandfluh SD733 as §3.4 / §6.4 describe it: manufacturer 24835 (0x6103), device type 58352.
Identity sd733()
{
    Identity id;
    id.expandedDeviceType = 58352;
    id.minRequestPreambles = 5;
    id.hartRevision = 7;
    id.deviceRevision = 1;
    id.softwareRevision = 2;
    id.hardwareRevisionAndSignaling = 0x08;
    id.deviceId = 0x123456;
    id.minResponsePreambles = 5;
    id.maxDeviceVariables = 4;
    id.configChangeCounter = 3;
    id.manufacturerId = 24835;
    id.privateLabel = 24835;
    id.deviceProfile = 0x85;
    return id;
}

} // namespace

// §5.1.1 command 0: bytes 0..21 of a HART 7 device.
TEST(HartUniversal, Section511Command0Identity)
{
    const Bytes data{254,  0xE3, 0xF0, 5, 7, 1, 2,    0x08, 0,    0x12, 0x34,
                     0x56, 5,    4,    0, 3, 0, 0x61, 0x03, 0x61, 0x03, 0x85};
    EXPECT_EQ(encodePayload(sd733()), data);
    auto p = decodeUniversal(0, true, data);
    ASSERT_TRUE(p.ok());
    const Identity &id = std::get<Identity>(*p);
    EXPECT_EQ(id, sd733());
    EXPECT_EQ(id.hardwareRevision(), 1);
    EXPECT_EQ(id.physicalSignaling(), 0);
    EXPECT_EQ(id.address(), longAddress(0xE3F0, 0x123456));
    // Command 0 has no request data; command 11/21 answer with the same identity.
    EXPECT_TRUE(std::holds_alternative<std::monostate>(*decodeUniversal(0, false, {})));
    EXPECT_EQ(std::get<Identity>(*decodeUniversal(11, true, data)), sd733());
}

TEST(HartUniversal, Section511Command0FromAnOlderDevice)
{
    const Bytes hart5{254, 0xE3, 0xF0, 5, 5, 1, 2, 0x08, 0, 0x12, 0x34, 0x56};
    auto p = decodeUniversal(0, true, hart5);
    ASSERT_TRUE(p.ok());
    const Identity &id = std::get<Identity>(*p);
    EXPECT_EQ(id.length, 12u);
    EXPECT_EQ(id.deviceId, 0x123456u);
    EXPECT_EQ(id.manufacturerId, 0);
    EXPECT_EQ(decodeUniversal(0, true, Bytes(11, 0)).error().code, DecodeErrc::BadLength);
}

TEST(HartUniversal, Section23PackedAscii)
{
    EXPECT_EQ(packAscii("HART", 3), (Bytes{0x20, 0x14, 0x94}));
    EXPECT_EQ(unpackAscii(Bytes{0x20, 0x14, 0x94}), "HART");
    // §6.4 delivery tag "WAGSD7xx": lowercase is upper-cased, padding is spaces.
    const Bytes tag = packAscii("wagsd733", 6);
    EXPECT_EQ(unpackAscii(tag), "WAGSD733");
    EXPECT_EQ(unpackAscii(packAscii("AB", 6)), "AB");
    EXPECT_EQ(unpackAscii(packAscii("a~b", 3)), "A?B");
}

TEST(HartUniversal, Section5111TagDescriptorDate)
{
    TagDescriptorDate t{"WAGSD733", "WAG ELECTRONIC", Date{17, 3, 124}};
    const Bytes data = encodePayload(t);
    ASSERT_EQ(data.size(), 21u);
    EXPECT_EQ(Bytes(data.end() - 3, data.end()), (Bytes{17, 3, 124}));
    auto p = decodeUniversal(13, true, data);
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(std::get<TagDescriptorDate>(*p), t);
    EXPECT_EQ(std::get<TagDescriptorDate>(*decodeUniversal(18, false, data)), t);
    EXPECT_EQ(formatDate(t.date), "2024-03-17");
}

TEST(HartUniversal, Section512To514FloatsBigEndian)
{
    const Bytes cmd1{39, 0x41, 0xA0, 0x00, 0x00}; // 20.0 mA
    const UnitValue pv = std::get<UnitValue>(*decodeUniversal(1, true, cmd1));
    EXPECT_EQ(pv.unit, 39);
    EXPECT_FLOAT_EQ(pv.value, 20.0f);
    EXPECT_EQ(encodePayload(pv), cmd1);

    DynamicVariables dv{12.0f, {{49, 250.5f}, {57, 50.0f}}};
    const Bytes enc = encodePayload(dv);
    ASSERT_EQ(enc.size(), 14u);
    EXPECT_EQ(std::get<DynamicVariables>(*decodeUniversal(3, true, enc)), dv);
    EXPECT_EQ(decodeUniversal(3, true, Bytes(8, 0)).error().code, DecodeErrc::BadLength);

    LoopCurrent lc{4.0f, 0.0f};
    EXPECT_EQ(std::get<LoopCurrent>(*decodeUniversal(2, true, encodePayload(lc))), lc);
}

TEST(HartUniversal, Section518Command9Slots)
{
    EXPECT_EQ(std::get<DeviceVariableCodes>(*decodeUniversal(9, false, Bytes{0, 1, 2})).codes,
              (Bytes{0, 1, 2}));
    DeviceVariables dv;
    dv.extendedStatus = 0x02;
    dv.variableSlots = {{0, 64, 49, 12.5f, 0xC0}, {1, 0, 57, 99.0f, 0xC0}};
    dv.timestamp = 0x01020304;
    const Bytes enc = encodePayload(dv);
    EXPECT_EQ(enc.size(), 1u + 16u + 4u);
    EXPECT_EQ(std::get<DeviceVariables>(*decodeUniversal(9, true, enc)), dv);
}

TEST(HartUniversal, Section515To522OtherCommands)
{
    LoopConfiguration lc{3, 0};
    EXPECT_EQ(encodePayload(lc), (Bytes{3, 0}));
    EXPECT_EQ(std::get<LoopConfiguration>(*decodeUniversal(6, false, Bytes{3, 0})), lc);
    EXPECT_EQ(std::get<LoopConfiguration>(*decodeUniversal(6, false, Bytes{3})).loopCurrentMode, 1);
    EXPECT_EQ(
        std::get<VariableClassifications>(*decodeUniversal(8, true, Bytes{64, 0, 0, 0})).codes[0],
        64);
    EXPECT_EQ(
        std::get<Message>(*decodeUniversal(12, true, encodePayload(Message{"HELLO WORLD"}))).text,
        "HELLO WORLD");
    EXPECT_EQ(
        std::get<FinalAssemblyNumber>(*decodeUniversal(16, true, Bytes{0x01, 0x02, 0x03})).number,
        0x010203u);
    const LongTag lt{"Wandfluh AG – Ölventil"}; // '–' is not Latin-1 → '?'
    const Bytes ltBytes = encodePayload(lt);
    ASSERT_EQ(ltBytes.size(), 32u);
    EXPECT_EQ(std::get<LongTag>(*decodeUniversal(22, true, ltBytes)).text,
              "Wandfluh AG ? Ölventil");
    EXPECT_EQ(std::get<ConfigChangeCounter>(*decodeUniversal(38, false, Bytes{})).counter,
              std::nullopt);
    EXPECT_EQ(std::get<ConfigChangeCounter>(*decodeUniversal(38, true, Bytes{0, 7})).counter, 7);
    EXPECT_EQ(decodeUniversal(38, true, Bytes{0}).error().code, DecodeErrc::BadLength);
    const AdditionalStatus st =
        std::get<AdditionalStatus>(*decodeUniversal(48, true, Bytes(9, 0x01)));
    EXPECT_EQ(st.bytes.size(), 9u);
    EXPECT_EQ(st.operatingMode(), 1);
    EXPECT_EQ(decodeUniversal(4, false, {}).error().code, DecodeErrc::UnexpectedCommand);
    EXPECT_TRUE(isUniversal(48));
    EXPECT_FALSE(isUniversal(128));
    DeviceInfo di;
    di.upperRange = 500.0f;
    EXPECT_EQ(std::get<DeviceInfo>(*decodeUniversal(15, true, encodePayload(di))), di);
    TransducerInfo ti{0x00ABCDEF, 49, 500.0f, 0.0f, 1.0f};
    EXPECT_EQ(std::get<TransducerInfo>(*decodeUniversal(14, true, encodePayload(ti))), ti);
}

TEST(HartUniversal, DescribeCommand0Response)
{
    const Frame f = makeResponse(shortAddress(0), 0, 0, 0, encodePayload(sd733()));
    const Description d = describeFrame(*encodeFrame(f));
    ASSERT_TRUE(d.ok()) << d.summary.en;
    const FieldSpan *mfr = d.field("hart.cmd0.manufacturer_id");
    ASSERT_NE(mfr, nullptr);
    EXPECT_EQ(mfr->value, "24835");
    EXPECT_EQ(mfr->offset, 5u + 6u + 17u); // preambles, header + status, byte 17 of the data
    EXPECT_EQ(d.field("hart.cmd0.device_id")->value, std::to_string(0x123456));
    EXPECT_EQ(d.field("hart.cmd0.expanded_device_type")->value, "0xE3F0");
    for (const FieldSpan &fs : d.fields)
        EXPECT_TRUE(fs.text.complete()) << fs.key;
    // A truncated identity is an error, shown as far as it goes.
    const Description t =
        describeFrame(*encodeFrame(makeResponse(shortAddress(0), 0, 0, 0, Bytes(5, 1))));
    EXPECT_FALSE(t.ok());
    EXPECT_NE(t.field("hart.cmd0.min_request_preambles"), nullptr);
}
