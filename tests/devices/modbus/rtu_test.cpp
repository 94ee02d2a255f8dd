// Modbus RTU: CRC-16/MODBUS, FC 3 / FC 6 ADUs for the HCS worked examples, exceptions, and typed
// errors at the right offset.
#include "modbus/crc.h"
#include "modbus/exceptions.h"
#include "modbus/rtu.h"
#include "modbus_vectors.h"

#include <gtest/gtest.h>
#include <string_view>

using namespace vt::dev;
using namespace vt::dev::modbus;
using namespace vt::test::modbus_vectors;

TEST(ModbusCrc, CheckValueAndReferenceFrames)
{
    constexpr std::string_view check = "123456789";
    const Bytes b(check.begin(), check.end());
    EXPECT_EQ(crc16(b), 0x4B37); // CRC-16/MODBUS check value
    static_assert(crc16(std::span<const std::uint8_t>{}) == 0xFFFF);
    EXPECT_TRUE(rtuCrcOk(kClassicRead10));
    EXPECT_TRUE(rtuCrcOk(kSerialLineSpecRead));
    EXPECT_FALSE(rtuCrcOk(Bytes{0x01, 0x03}));
}

TEST(ModbusRtu, SerialLineSpecExampleRoundTrips)
{
    const RtuRequest q{0x11, ReadRequest{0x006B, 3}};
    auto bytes = encodeRtu(q);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(*bytes, kSerialLineSpecRead);
    auto back = decodeRtuRequest(kSerialLineSpecRead);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back, q);
}

TEST(ModbusRtu, DmaSec3_7_ReadD107AsFc3)
{
    const RtuRequest q{1, ReadRequest{0x0007, 1}};
    EXPECT_EQ(encodeRtu(q).value(), kRtuReadD107);
    EXPECT_EQ(decodeRtuRequest(kRtuReadD107).value(), q);
    const RtuResponse a{1, ReadResponse{{0x0133}}};
    EXPECT_EQ(encodeRtu(a).value(), kRtuReadD107Response);
    EXPECT_EQ(decodeRtuResponse(kRtuReadD107Response).value(), a);
}

TEST(ModbusRtu, DmaSec3_7_Sec3_8_WritesAsFc6)
{
    const RtuRequest q{1, WriteRequest{0x0030, 1000}};
    EXPECT_EQ(encodeRtu(q).value(), kRtuWriteC107);
    EXPECT_EQ(decodeRtuRequest(kRtuWriteC107).value(), q);
    const RtuResponse echo{1, WriteResponse{0x0030, 1000}};
    EXPECT_EQ(encodeRtu(echo).value(), kRtuWriteC107);
    EXPECT_EQ(decodeRtuResponse(kRtuWriteC107).value(), echo);
    const RtuRequest minus{1, WriteRequest{0x0027, 0xD8F1}};
    EXPECT_EQ(encodeRtu(minus).value(), kRtuWriteMinus9999);
}

TEST(ModbusRtu, ExceptionsCarryTheHcsMeaning)
{
    const RtuResponse wrongId{1, ExceptionResponse{3, 2}};
    EXPECT_EQ(encodeRtu(wrongId).value(), kRtuReadWrongId);
    EXPECT_EQ(decodeRtuResponse(kRtuReadWrongId).value(), wrongId);
    EXPECT_EQ(decodeRtuResponse(kRtuWriteWrongData).value(),
              (RtuResponse{1, ExceptionResponse{6, 3}}));
    // ARCHITECTURE.md: FC|0x80 + code = the HCS EXCE for CMD = FC.
    EXPECT_EQ(hcsMeaning(3, 2, hcs::Family::Dma)->en, "wrong ID");
    EXPECT_EQ(hcsMeaning(3, 3, hcs::Family::Dma)->en, "CNT == 0 or CNT > 16 (0x10)");
    EXPECT_EQ(hcsMeaning(6, 3, hcs::Family::Dma)->en, "wrong data value");
    EXPECT_EQ(hcsMeaning(6, 6, hcs::Family::Dma)->en, "internal checksum error (Modbus)");
    EXPECT_EQ(hcsMeaning(3, 6, hcs::Family::Opat)->en, "internal checksum error (CAN connection)");
    EXPECT_FALSE(hcsMeaning(3, 7, hcs::Family::Dma));
    EXPECT_EQ(exceptionName(2)->en, "illegal data address");
    EXPECT_EQ(exceptionText(3, 2, hcs::Family::Dma).en, "illegal data address — HCS: wrong ID");
    EXPECT_EQ(exceptionText(3, 2, hcs::Family::Dma).de,
              "unzulässige Datenadresse — HCS: Falsche ID");
    EXPECT_FALSE(exceptionName(7));
    EXPECT_EQ(exceptionText(3, 99, hcs::Family::Dma).en, "exception 99 (not a standard code)");
}

TEST(ModbusRtu, CodecAcceptsModbusLimitHcsLimitIsSeparate)
{
    const RtuRequest nine{1, ReadRequest{0, 9}};
    ASSERT_TRUE(encodeRtu(nine).ok());
    EXPECT_FALSE(withinHcsReadLimit(std::get<ReadRequest>(nine.pdu)));
    EXPECT_TRUE(withinHcsReadLimit(ReadRequest{7, 7}));
    ASSERT_TRUE(encodeRtu(RtuRequest{1, ReadRequest{0, 125}}).ok());
    auto tooMany = encodeRtu(RtuRequest{1, ReadRequest{0, 126}});
    ASSERT_FALSE(tooMany.ok());
    EXPECT_EQ(tooMany.error().code, DecodeErrc::BadValue);
    EXPECT_EQ(tooMany.error().offset, 4u);
    EXPECT_FALSE(encodeRtu(RtuRequest{1, ReadRequest{0, 0}}).ok());
    // The longest FC 3 answer: 125 registers = 255-byte ADU (≤ 256, Modbus over Serial Line
    // §2.5.1).
    const RtuResponse big{1, ReadResponse{std::vector<std::uint16_t>(125, 0xBEEF)}};
    auto bytes = encodeRtu(big);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(bytes->size(), 255u);
    EXPECT_EQ(decodeRtuResponse(*bytes).value(), big);
    EXPECT_FALSE(encodeRtu(RtuResponse{1, ReadResponse{std::vector<std::uint16_t>(126)}}).ok());
    EXPECT_FALSE(encodeRtu(RtuResponse{1, ReadResponse{}}).ok());
    EXPECT_FALSE(encodeRtu(RtuResponse{1, ExceptionResponse{0x83, 1}}).ok());
}

TEST(ModbusRtu, TypedErrorsAtTheRightOffset)
{
    // Every prefix: Truncated at its length.
    for (std::size_t n = 0; n < kRtuReadD107Response.size(); ++n) {
        auto r = decodeRtuResponse(std::span<const std::uint8_t>(kRtuReadD107Response.data(), n));
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, DecodeErrc::Truncated) << n;
        EXPECT_EQ(r.error().offset, n) << n;
    }
    Bytes bad = kRtuReadD107;
    bad[4] ^= 0x01;
    auto crc = decodeRtuRequest(bad);
    ASSERT_FALSE(crc.ok());
    EXPECT_EQ(crc.error().code, DecodeErrc::BadChecksum);
    EXPECT_EQ(crc.error().offset, 6u);
    Bytes longer = kRtuReadD107;
    longer.push_back(0);
    EXPECT_EQ(decodeRtuRequest(longer).error().code, DecodeErrc::TooLong);
    EXPECT_EQ(decodeRtuRequest(longer).error().offset, 8u);
    const Bytes fc16{0x01, 0x10, 0x00, 0x00};
    EXPECT_EQ(decodeRtuRequest(fc16).error().code, DecodeErrc::UnexpectedCommand);
    EXPECT_EQ(decodeRtuRequest(fc16).error().offset, 1u);
    // An exception is not a request.
    EXPECT_EQ(decodeRtuRequest(kRtuReadWrongId).error().code, DecodeErrc::UnexpectedCommand);
    // Quantity 0 with a valid CRC: BadValue at the quantity (byte 4).
    const Bytes zero =
        encodeRtu(RtuRequest{1, WriteRequest{0, 0}}).value(); // borrow a valid frame …
    Bytes q0{0x01, 0x03, 0x00, 0x07, 0x00, 0x00};
    const std::uint16_t c = crc16(q0);
    q0.push_back(static_cast<std::uint8_t>(c & 0xFF));
    q0.push_back(static_cast<std::uint8_t>(c >> 8));
    EXPECT_EQ(decodeRtuRequest(q0).error().code, DecodeErrc::BadValue);
    EXPECT_EQ(decodeRtuRequest(q0).error().offset, 4u);
    EXPECT_TRUE(decodeRtuRequest(zero).ok());
    // An odd byte count with a valid CRC: BadLength at the byte count (byte 2).
    Bytes odd{0x01, 0x03, 0x03, 0x01, 0x33, 0x00};
    const std::uint16_t c2 = crc16(odd);
    odd.push_back(static_cast<std::uint8_t>(c2 & 0xFF));
    odd.push_back(static_cast<std::uint8_t>(c2 >> 8));
    EXPECT_EQ(decodeRtuResponse(odd).error().code, DecodeErrc::BadLength);
    EXPECT_EQ(decodeRtuResponse(odd).error().offset, 2u);
}
