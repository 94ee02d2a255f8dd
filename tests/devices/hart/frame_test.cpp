// HART frames against the HART-7 manual §2.3 (telegram structure) and the worked examples of
// §4.4.1, wrapped in complete long frames to a Wandfluh SD733 (device type 0xE3F0, §3.4).
#include "hart/describe.h"
#include "hart/frame.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hart;

namespace {

Bytes withPreambles(Bytes pdu, std::size_t n = 5)
{
    pdu.insert(pdu.begin(), n, 0xFF);
    return pdu;
}

const Address kSd733 = longAddress(0xE3F0, 0x123456);

} // namespace

// §4.4.1 example 1: write "Imin solenoid 1" (IND 250, PNU 6, channel 1 → instance 0) = 450 with
// command 131; the response echoes the data with status bytes 0, 0.
TEST(HartFrame, Section441Example1Frames)
{
    const Bytes data{0xFA, 0x06, 0x00, 0x01, 0xC2};
    const Bytes request = withPreambles(
        {0x82, 0xA3, 0xF0, 0x12, 0x34, 0x56, 0x83, 0x05, 0xFA, 0x06, 0x00, 0x01, 0xC2, 0x18});
    const Bytes response = withPreambles({0x86, 0xA3, 0xF0, 0x12, 0x34, 0x56, 0x83, 0x07, 0x00,
                                          0x00, 0xFA, 0x06, 0x00, 0x01, 0xC2, 0x1E});

    const Frame req = makeRequest(kSd733, 131, data);
    EXPECT_EQ(*encodeFrame(req), request);
    auto decodedReq = decodeFrame(request);
    ASSERT_TRUE(decodedReq.ok());
    EXPECT_EQ(*decodedReq, req);

    const Frame rsp = makeResponse(kSd733, 131, 0, 0, data);
    EXPECT_EQ(*encodeFrame(rsp), response);
    auto decodedRsp = decodeFrame(response);
    ASSERT_TRUE(decodedRsp.ok());
    EXPECT_EQ(*decodedRsp, rsp);
    EXPECT_TRUE(decodedRsp->isResponse());
}

TEST(HartFrame, Section23ShortFrameCommand0)
{
    const Bytes wire = withPreambles({0x02, 0x80, 0x00, 0x00, 0x82});
    const Frame f = makeRequest(shortAddress(0), 0);
    EXPECT_EQ(*encodeFrame(f), wire);
    auto d = decodeFrame(wire);
    ASSERT_TRUE(d.ok());
    EXPECT_FALSE(d->address.isLong);
    EXPECT_TRUE(d->address.primaryMaster);
    EXPECT_EQ(d->preambles, 5u);
    // Secondary master, burst bit, poll address 15 (§2.3 address byte layout).
    Frame g = makeRequest(shortAddress(15, false), 1);
    g.address.burst = true;
    const Bytes enc = *encodeFrame(g);
    EXPECT_EQ(enc[6], 0x4F);
    EXPECT_EQ(*decodeFrame(enc), g);
}

TEST(HartFrame, Section23LongAddressBits)
{
    // The top two bits of the expanded device type give way to the master and burst bits.
    const Address a = longAddress(0xE3F0, 0xABCDEF);
    EXPECT_EQ(a.expandedDeviceType, 0x23F0);
    const Bytes enc = *encodeFrame(makeRequest(a, 0, {}));
    EXPECT_EQ(Bytes(enc.begin() + 6, enc.begin() + 11), (Bytes{0xA3, 0xF0, 0xAB, 0xCD, 0xEF}));
    Address bad = a;
    bad.expandedDeviceType = 0xE3F0;
    EXPECT_EQ(encodeFrame(makeRequest(bad, 0)).error().code, DecodeErrc::BadValue);
    bad = a;
    bad.deviceId = 0x1000000;
    EXPECT_EQ(encodeFrame(makeRequest(bad, 0)).error().code, DecodeErrc::BadValue);
    EXPECT_EQ(encodeFrame(makeRequest(shortAddress(64), 0)).error().code, DecodeErrc::BadValue);
}

TEST(HartFrame, ExpansionBytesAndPhysicalLayerRoundTrip)
{
    Frame f = makeResponse(shortAddress(3), 48, 8, 0x10, {1, 2, 3});
    f.expansion = {0xAA, 0xBB};
    f.physicalLayer = 1;
    f.preambles = 0;
    const Bytes enc = *encodeFrame(f);
    EXPECT_EQ(enc[0], 0x4E); // 0 10 01 110
    EXPECT_EQ(*decodeFrame(enc), f);
    f.expansion = {1, 2, 3, 4};
    EXPECT_FALSE(encodeFrame(f).ok());
}

TEST(HartFrame, Section23ByteCountAndChecksumErrors)
{
    Bytes wire = withPreambles(
        {0x82, 0xA3, 0xF0, 0x12, 0x34, 0x56, 0x83, 0x05, 0xFA, 0x06, 0x00, 0x01, 0xC2, 0x18});
    Bytes bad = wire;
    bad.back() ^= 0x01;
    EXPECT_EQ(decodeFrame(bad).error().code, DecodeErrc::BadChecksum);
    EXPECT_EQ(decodeFrame(bad).error().offset, wire.size() - 1);
    Bytes shortFrame(wire.begin(), wire.end() - 3);
    EXPECT_EQ(decodeFrame(shortFrame).error().code, DecodeErrc::Truncated);
    Bytes longer = wire;
    longer.push_back(0x00);
    EXPECT_EQ(decodeFrame(longer).error().code, DecodeErrc::TooLong);
    // A response needs the two status bytes in its byte count.
    EXPECT_EQ(decodeFrame(Bytes{0xFF, 0xFF, 0x06, 0x80, 0x00, 0x01, 0x00, 0x87}).error().code,
              DecodeErrc::BadLength);
    EXPECT_EQ(decodeFrame(Bytes{0xFF, 0xFF, 0x05, 0x80}).error().code, DecodeErrc::BadValue);
    EXPECT_EQ(decodeFrame(Bytes{0xFF, 0xFF}).error().code, DecodeErrc::Truncated);
    EXPECT_EQ(decodeFrame(Bytes{}).error().code, DecodeErrc::Truncated);
    Frame huge = makeRequest(shortAddress(0), 130, Bytes(256, 0));
    EXPECT_EQ(encodeFrame(huge).error().code, DecodeErrc::BadValue);
    Frame justFits = makeResponse(shortAddress(0), 130, 0, 0, Bytes(253, 0));
    EXPECT_TRUE(decodeFrame(*encodeFrame(justFits)).ok());
    justFits.data.push_back(0);
    EXPECT_FALSE(encodeFrame(justFits).ok());
}

TEST(HartFrame, Section441DescribeExample1Response)
{
    const Bytes response = withPreambles({0x86, 0xA3, 0xF0, 0x12, 0x34, 0x56, 0x83, 0x07, 0x00,
                                          0x00, 0xFA, 0x06, 0x00, 0x01, 0xC2, 0x1E});
    const Description d = describeFrame(response);
    ASSERT_TRUE(d.ok()) << d.summary.en;
    EXPECT_EQ(d.field("hart.preambles")->length, 5u);
    EXPECT_EQ(d.field("hart.address.device_type")->value, "0x23F0");
    EXPECT_EQ(d.field("hart.address.device_id")->value, std::to_string(0x123456));
    EXPECT_EQ(d.field("hart.command")->value, "131");
    EXPECT_EQ(d.field("hart.byte_count")->value, "7");
    EXPECT_EQ(d.field("hart.response_code")->text.de, "kein Fehler");
    EXPECT_EQ(d.field("hart.param.ind")->value, "250");
    EXPECT_EQ(d.field("hart.param.ind")->offset, 15u);
    EXPECT_EQ(d.field("hart.param.value")->value, "450 (0x01C2)");
    EXPECT_EQ(d.field("hart.checksum")->offset, 20u);
    EXPECT_EQ(d.summary.en, "ACK 0x23F0/1193046 cmd 131 Write parameter (2 bytes): no error");
    for (const FieldSpan &f : d.fields)
        EXPECT_TRUE(f.text.complete()) << f.key;
}

TEST(HartFrame, DescribeShowsStatusBitsAndErrors)
{
    // Response code 5 "wrong byte count" (§4.4.1) with cold start + more status; no data.
    Frame f = makeResponse(shortAddress(0), 131, 5, 0x30);
    const Description d = describeFrame(*encodeFrame(f));
    ASSERT_TRUE(d.ok()) << d.summary.en;
    EXPECT_EQ(d.field("hart.response_code")->text.en, "wrong byte count (too few data bytes)");
    EXPECT_EQ(d.field("hart.device_status.bit5")->text.de, "Kaltstart");
    EXPECT_NE(d.field("hart.device_status.bit4"), nullptr);
    // Communication error: bit 7 set, bits name the faults.
    f.responseCode = 0x88;
    const Description c = describeFrame(*encodeFrame(f));
    EXPECT_EQ(c.field("hart.comm_error.bit3")->text.en, "longitudinal parity error");
    // A bad checksum still shows the whole frame.
    Bytes bad = *encodeFrame(makeRequest(kSd733, 132, {0xEE, 0x08, 0x00}));
    bad.back() ^= 0xFF;
    const Description b = describeFrame(bad);
    EXPECT_FALSE(b.ok());
    EXPECT_EQ(b.error->code, DecodeErrc::BadChecksum);
    EXPECT_EQ(b.field("hart.param.pnu")->value, "8");
    EXPECT_NE(b.field("hart.checksum")->text.en.find("expected"), std::string::npos);
    // Malformed payload: command 131 with 4 data bytes.
    const Description p =
        describeFrame(*encodeFrame(makeRequest(kSd733, 131, {0xFA, 0x06, 0x00, 0x01})));
    EXPECT_FALSE(p.ok());
    EXPECT_EQ(p.error->code, DecodeErrc::BadLength);
    // Garbage and truncation never crash and say what is wrong.
    EXPECT_FALSE(describeFrame(Bytes{0xFF, 0xFF, 0x07}).ok());
    EXPECT_FALSE(describeFrame(Bytes{0xFF, 0x82, 0xA3}).ok());
    EXPECT_FALSE(describeFrame(Bytes{}).ok());
}
