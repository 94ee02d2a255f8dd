// Device-specific commands 128..133 against the HART-7 manual §4.4.1 and its examples.
#include "hart/device_specific.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hart;

// §4.4.1 example 1: "Imin solenoid 1" UINT16 → command 131; IND 250, PNU 6, instance 0, 450.
TEST(HartDeviceSpecific, Section441Example1WriteUint16)
{
    const Bytes data{0xFA, 0x06, 0x00, 0x01, 0xC2};
    const ParamAccess write = writeParam(ValueType::UInt16, {250, 6, 0}, 450);
    EXPECT_EQ(write.command, 131);
    EXPECT_EQ(*encodeParamAccess(write, false), data);
    EXPECT_EQ(*encodeParamAccess(write, true), data); // the response echoes the request
    auto req = decodeParamAccess(131, false, data);
    ASSERT_TRUE(req.ok());
    EXPECT_EQ(*req, write);
    auto rsp = decodeParamAccess(131, true, data);
    ASSERT_TRUE(rsp.ok());
    EXPECT_EQ(rsp->raw, 450u);
}

// §4.4.1 example 2: "Fixed command value 3" INT32 → command 132; IND 238, PNU 8, instance 0;
// value 80 (0x50). The manual's response table shows only "0x50 0x00" under "data bytes 4 ... 25",
// which cannot hold an INT32 (4 bytes, big-endian per §2.3): the OCR/table lost two columns and
// the value bytes are 00 00 00 50.
TEST(HartDeviceSpecific, Section441Example2ReadInt32)
{
    const ParamAccess read = readParam(ValueType::Int32, {238, 8, 0});
    EXPECT_EQ(read.command, 132);
    EXPECT_EQ(*encodeParamAccess(read, false), (Bytes{0xEE, 0x08, 0x00}));
    const Bytes response{0xEE, 0x08, 0x00, 0x00, 0x00, 0x00, 0x50};
    auto rsp = decodeParamAccess(132, true, response);
    ASSERT_TRUE(rsp.ok());
    EXPECT_EQ(rsp->ref, (ParamRef{238, 8, 0}));
    EXPECT_EQ(asSigned(*rsp->raw, 4), 80);
    ParamAccess answer = read;
    answer.raw = 80;
    EXPECT_EQ(*encodeParamAccess(answer, true), response);
}

TEST(HartDeviceSpecific, Section441CommandNumbersByDataType)
{
    EXPECT_EQ(readCommand(ValueType::Int8), 128);
    EXPECT_EQ(writeCommand(ValueType::UInt8), 129);
    EXPECT_EQ(readCommand(ValueType::Int16), 130);
    EXPECT_EQ(writeCommand(ValueType::UInt16), 131);
    EXPECT_EQ(readCommand(ValueType::Float), 132);
    EXPECT_EQ(writeCommand(ValueType::UInt32), 133);
    EXPECT_EQ(valueWidth(std::uint8_t{127}), 0u);
    EXPECT_TRUE(isWriteCommand(133));
    EXPECT_FALSE(isWriteCommand(132));
}

TEST(HartDeviceSpecific, SignedAndFloatValues)
{
    const ParamAccess w = writeParam(ValueType::Int8, {245, 0, 1}, rawFromSigned(-1, 1));
    EXPECT_EQ(*encodeParamAccess(w, false), (Bytes{245, 0, 1, 0xFF}));
    EXPECT_EQ(asSigned(0xFF, 1), -1);
    EXPECT_EQ(asSigned(0xFFFE, 2), -2);
    EXPECT_FLOAT_EQ(asFloat(0x3FC00000), 1.5f);
}

TEST(HartDeviceSpecific, LengthErrors)
{
    EXPECT_EQ(decodeParamAccess(130, false, Bytes{1, 2}).error().code, DecodeErrc::BadLength);
    EXPECT_EQ(decodeParamAccess(130, true, Bytes{1, 2, 3, 4}).error().code, DecodeErrc::BadLength);
    EXPECT_EQ(decodeParamAccess(130, false, Bytes{1, 2, 3, 4}).error().code, DecodeErrc::TooLong);
    EXPECT_EQ(decodeParamAccess(12, false, Bytes{1, 2, 3}).error().code,
              DecodeErrc::UnexpectedCommand);
    ParamAccess noValue{131, {1, 2, 3}, std::nullopt};
    EXPECT_EQ(encodeParamAccess(noValue, false).error().code, DecodeErrc::BadValue);
}
