// Protocol auto-detection of the decode box: checksums and
// headers decide, structure decides only alone, and ambiguity is reported instead of guessed.
#include "hcs/worked_examples.h"
#include "inspect/auto_detect.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::inspect;

namespace {

std::optional<FrameFormat> chosen(const Bytes &b, std::optional<std::uint32_t> cob = std::nullopt)
{
    const Detection d = detectProtocol(b, cob);
    return d.choice() ? std::optional<FrameFormat>(d.choice()->protocol) : std::nullopt;
}

bool offers(const Detection &d, FrameFormat p)
{
    return std::any_of(d.candidates.begin(), d.candidates.end(),
                       [p](const Candidate &c) { return c.protocol == p; });
}

} // namespace

TEST(AutoDetect, ModbusRtuByCrc)
{
    // Modbus over Serial Line §2.5.1.2: FC 3 read of ID 7 at unit 1, CRC 0xCB35 low byte first.
    const Bytes rtu{0x01, 0x03, 0x00, 0x07, 0x00, 0x01, 0x35, 0xCB};
    EXPECT_EQ(chosen(rtu), FrameFormat::ModbusRtu);
    EXPECT_FALSE(detectProtocol(rtu).choice()->badCrc);
}

TEST(AutoDetect, ModbusRtuWithAWrongCrcIsNamedSo)
{
    // The same read with its CRC damaged: eight bytes that are also a PKW telegram and an SDO,
    // but the RTU header announces exactly eight bytes — a damaged RTU frame, said so.
    Bytes bad{0x01, 0x03, 0x00, 0x07, 0x00, 0x01, 0x35, 0x34};
    const Detection d = detectProtocol(bad);
    ASSERT_NE(d.choice(), nullptr);
    EXPECT_EQ(d.choice()->protocol, FrameFormat::ModbusRtu);
    EXPECT_TRUE(d.choice()->badCrc);
    EXPECT_EQ(d.choice()->directions, std::vector<Direction>{Direction::Request});
    // A write (FC 6) echoes its request: either direction.
    const Bytes write{0x02, 0x06, 0x00, 0x1C, 0x03, 0xE8, 0x00, 0x00};
    ASSERT_NE(detectProtocol(write).choice(), nullptr);
    EXPECT_TRUE(detectProtocol(write).choice()->badCrc);
    EXPECT_EQ(detectProtocol(write).choice()->directions.size(), 2u);
    // Zero padding after "01 03" asks for no register: no Modbus request, no guess made up.
    const Bytes zeros{0x10, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
    const Detection z = detectProtocol(zeros);
    EXPECT_TRUE(!z.choice() || z.choice()->protocol != FrameFormat::ModbusRtu);
    // A checksum that confirms another protocol wins over a damaged-looking RTU header.
    const Bytes tcp{0x00, 0x01, 0x00, 0x00, 0x00, 0x06, 0x01, 0x03, 0x00, 0x07, 0x00, 0x01};
    EXPECT_EQ(chosen(tcp), FrameFormat::ModbusTcp);
}

TEST(AutoDetect, ModbusTcpByMbap)
{
    const Bytes tcp{0x00, 0x01, 0x00, 0x00, 0x00, 0x06, 0x01, 0x03, 0x00, 0x07, 0x00, 0x01};
    EXPECT_EQ(chosen(tcp), FrameFormat::ModbusTcp);
    Bytes wrongLength = tcp;
    wrongLength[5] = 0x07; // the MBAP length no longer matches
    EXPECT_NE(chosen(wrongLength), FrameFormat::ModbusTcp);
}

TEST(AutoDetect, HartByPreambleAndChecksum)
{
    // HART-7 manual §4.4.1 example 1 in a long frame to an SD733.
    const Bytes hart{0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x82, 0xA3, 0xF0, 0x12, 0x34,
                     0x56, 0x83, 0x05, 0xFA, 0x06, 0x00, 0x01, 0xC2, 0x18};
    const Detection d = detectProtocol(hart);
    ASSERT_NE(d.choice(), nullptr);
    EXPECT_EQ(d.choice()->protocol, FrameFormat::Hart);
    EXPECT_TRUE(d.choice()->strong);
    Bytes bad = hart;
    bad.back() ^= 0x01; // XOR checksum broken
    EXPECT_NE(chosen(bad), FrameFormat::Hart);
}

TEST(AutoDetect, GatewayTelegramsByStructure)
{
    using namespace vt::test::hcs_examples;
    EXPECT_EQ(chosen(kOpat27Write), FrameFormat::Gateway);     // OPAT manual §2.7
    EXPECT_EQ(chosen(kOpat342Request), FrameFormat::Gateway);  // §3.4.2 CMD 15, SNUM 2
    EXPECT_EQ(chosen(kDma442Response3), FrameFormat::Gateway); // DMA Profinet manual §4.4.2
    // A PLC's 42-byte process image: the telegram plus padding.
    Bytes image = kDma37Write;
    image.resize(42, 0);
    EXPECT_EQ(chosen(image), FrameFormat::Gateway);
    const Detection d =
        detectProtocol(kOpat27ReadResponse); // a CMD 3 answer decodes only as a response
    ASSERT_NE(d.choice(), nullptr);
    EXPECT_EQ(d.choice()->directions, std::vector<Direction>{Direction::Response});
}

TEST(AutoDetect, ProfidriveMixedImage)
{
    // OPAT manual §5.6: STW1 + NSOLL_A followed by CMD 15 for master and slave.
    const Bytes request{0x04, 0x7F, 0x07, 0x00, 0x12, 0x01, 0x0F, 0x00, 0x18,
                        0x00, 0x00, 0x00, 0x00, 0x18, 0x00, 0x00, 0x00};
    EXPECT_EQ(chosen(request), FrameFormat::Profidrive);
}

TEST(AutoDetect, CandumpIsCanopenAndEightBytesAreAmbiguous)
{
    const Bytes sdo{0x40, 0x41, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00};
    EXPECT_EQ(chosen(sdo, 0x605u), FrameFormat::Canopen);
    // ED1/SD1 manual §4.6.1 example 1 — eight bytes that are also a valid SDO: no guess.
    const Bytes pkw{0x20, 0x49, 0x03, 0x00, 0x00, 0x00, 0x01, 0xC2};
    const Detection d = detectProtocol(pkw);
    EXPECT_EQ(d.choice(), nullptr);
    EXPECT_TRUE(offers(d, FrameFormat::Pkw));
    EXPECT_TRUE(offers(d, FrameFormat::Canopen));
}

TEST(AutoDetect, NothingForGarbageOrEmpty)
{
    EXPECT_TRUE(detectProtocol(Bytes{}).candidates.empty());
    const Detection d = detectProtocol(Bytes{0x99, 0x98, 0x97, 0x96, 0x95, 0x94, 0x93});
    EXPECT_EQ(d.choice(), nullptr);
}
