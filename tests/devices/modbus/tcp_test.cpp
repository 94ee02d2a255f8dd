// Modbus TCP: MBAP header (Implementation Guide §3.1.3) around the same PDUs, bounded lengths.
#include "modbus/tcp.h"
#include "modbus_vectors.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::modbus;
using namespace vt::test::modbus_vectors;

TEST(ModbusTcp, DmaSec3_7_ReadAndWriteRoundTrip)
{
    const TcpRequest q{1, 1, ReadRequest{0x0007, 1}};
    EXPECT_EQ(encodeTcp(q).value(), kTcpReadD107);
    EXPECT_EQ(decodeTcpRequest(kTcpReadD107).value(), q);
    const TcpResponse a{1, 1, ReadResponse{{0x0133}}};
    EXPECT_EQ(encodeTcp(a).value(), kTcpReadD107Response);
    EXPECT_EQ(decodeTcpResponse(kTcpReadD107Response).value(), a);
    const TcpRequest w{2, 1, WriteRequest{0x0030, 1000}};
    EXPECT_EQ(encodeTcp(w).value(), kTcpWriteC107);
    EXPECT_EQ(decodeTcpResponse(kTcpWriteC107).value(),
              (TcpResponse{2, 1, WriteResponse{0x0030, 1000}}));
    EXPECT_EQ(decodeTcpResponse(kTcpReadWrongId).value(),
              (TcpResponse{3, 1, ExceptionResponse{3, 2}}));
}

TEST(ModbusTcp, MbapChecks)
{
    auto m = decodeMbap(kTcpReadD107);
    ASSERT_TRUE(m.ok());
    EXPECT_EQ(*m, (Mbap{1, 0, 6, 1}));
    EXPECT_EQ(m->aduSize(), 12u);
    Bytes proto = kTcpReadD107;
    proto[3] = 1;
    EXPECT_EQ(decodeMbap(proto).error().code, DecodeErrc::BadValue);
    EXPECT_EQ(decodeMbap(proto).error().offset, 2u);
    for (std::uint16_t len :
         {std::uint16_t{0}, std::uint16_t{1}, std::uint16_t{255}, std::uint16_t{0xFFFF}}) {
        Bytes b = kTcpReadD107;
        b[4] = static_cast<std::uint8_t>(len >> 8);
        b[5] = static_cast<std::uint8_t>(len & 0xFF);
        auto r = decodeMbap(b);
        ASSERT_FALSE(r.ok()) << len;
        EXPECT_EQ(r.error().code, DecodeErrc::BadLength);
        EXPECT_EQ(r.error().offset, 4u);
    }
    EXPECT_EQ(decodeMbap(Bytes{0, 1, 0}).error().code, DecodeErrc::Truncated);
    EXPECT_EQ(decodeMbap(Bytes{0, 1, 0}).error().offset, 3u);
}

TEST(ModbusTcp, LengthMismatchAndPduErrorsPointIntoTheAdu)
{
    for (std::size_t n = 0; n < kTcpReadD107.size(); ++n) {
        auto r = decodeTcpRequest(std::span<const std::uint8_t>(kTcpReadD107.data(), n));
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, DecodeErrc::Truncated) << n;
        EXPECT_EQ(r.error().offset, n) << n;
    }
    Bytes longer = kTcpReadD107;
    longer.push_back(0);
    EXPECT_EQ(decodeTcpRequest(longer).error().code, DecodeErrc::TooLong);
    EXPECT_EQ(decodeTcpRequest(longer).error().offset, 12u);
    // MBAP says 7 bytes follow but the FC 3 request PDU has 5: TooLong inside the PDU at 12.
    const Bytes inner{0x00, 0x01, 0x00, 0x00, 0x00, 0x07, 0x01, 0x03, 0x00, 0x07, 0x00, 0x01, 0x00};
    EXPECT_EQ(decodeTcpRequest(inner).error().code, DecodeErrc::TooLong);
    EXPECT_EQ(decodeTcpRequest(inner).error().offset, 12u);
    // Quantity 200: BadValue at the quantity (7 + 3).
    const Bytes many{0x00, 0x01, 0x00, 0x00, 0x00, 0x06, 0x01, 0x03, 0x00, 0x07, 0x00, 0xC8};
    EXPECT_EQ(decodeTcpRequest(many).error().code, DecodeErrc::BadValue);
    EXPECT_EQ(decodeTcpRequest(many).error().offset, 10u);
    // Encode errors are shifted into the ADU too.
    EXPECT_EQ(encodeTcp(TcpRequest{1, 1, ReadRequest{0, 0}}).error().offset, 10u);
    // The largest ADU: 125 registers = 7 + 2 + 250 = 259 bytes.
    auto big = encodeTcp(TcpResponse{9, 1, ReadResponse{std::vector<std::uint16_t>(125, 1)}});
    ASSERT_TRUE(big.ok());
    EXPECT_EQ(big->size(), 259u);
    EXPECT_TRUE(decodeTcpResponse(*big).ok());
}
