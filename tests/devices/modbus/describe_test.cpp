// modbus::describeRtu / describeTcp: fields named for the inspector, registers as HCS parameter
// IDs, exception codes with their HCS meaning, in both languages.
#include "modbus/describe.h"
#include "modbus_vectors.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::modbus;
using namespace vt::test::modbus_vectors;

namespace {

bool contains(const std::string &text, const std::string &part)
{
    return text.find(part) != std::string::npos;
}

DescribeOptions opts(Direction direction)
{
    DescribeOptions o;
    o.direction = direction;
    return o;
}

} // namespace

TEST(ModbusDescribe, RtuReadRequest)
{
    const Description d = describeRtu(kRtuReadD107, opts(Direction::Request));
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d.protocol, "modbus-rtu");
    EXPECT_EQ(d.field("unit")->value, "1");
    EXPECT_EQ(d.field("pdu.function")->value, "0x03");
    EXPECT_TRUE(contains(d.field("pdu.function")->text.en, "HCS CMD 3"));
    EXPECT_EQ(d.field("pdu.start")->value, "0x0007");
    EXPECT_TRUE(contains(d.field("pdu.start")->text.en, "parameter ID 0x0007"));
    EXPECT_EQ(d.field("pdu.count")->value, "1");
    const FieldSpan *crc = d.field("crc");
    ASSERT_NE(crc, nullptr);
    EXPECT_EQ(crc->offset, 6u);
    EXPECT_EQ(crc->value, "0xCB35"); // sent low byte first: 35 CB
    EXPECT_TRUE(contains(crc->text.en, "correct"));
    EXPECT_EQ(d.field("note"), nullptr);
    EXPECT_TRUE(contains(d.summary.en, "FC 3 read 1 register(s) from 0x0007 (unit 1)"));
}

TEST(ModbusDescribe, RtuResponseNamesRegistersByTheRequestStart)
{
    DescribeOptions o = opts(Direction::Response);
    o.requestStart = 0x0007;
    o.parameters.name = [](std::uint16_t id) -> std::optional<LocalText> {
        if (id == 7)
            return LocalText{"d1.07 current A", "d1.07 Strom A"};
        return std::nullopt;
    };
    const Description d = describeRtu(kRtuReadD107Response, o);
    ASSERT_TRUE(d.ok());
    const FieldSpan *r1 = d.field("pdu.register1");
    ASSERT_NE(r1, nullptr);
    EXPECT_EQ(r1->offset, 3u);
    EXPECT_EQ(r1->value, "307");
    EXPECT_TRUE(contains(r1->text.en, "d1.07 current A"));
    EXPECT_TRUE(contains(r1->text.de, "d1.07 Strom A"));
}

TEST(ModbusDescribe, ExceptionWithHcsMeaning)
{
    DescribeOptions o = opts(Direction::Response);
    const Description d = describeRtu(kRtuReadWrongId, o);
    ASSERT_TRUE(d.ok());
    EXPECT_TRUE(contains(d.field("pdu.function")->text.en, "exception response to function 3"));
    EXPECT_TRUE(
        contains(d.field("pdu.exception")->text.en, "illegal data address — HCS: wrong ID"));
    o.family = hcs::Family::Opat;
    const Description w = describeRtu(kRtuWriteWrongData, o);
    EXPECT_TRUE(contains(w.field("pdu.exception")->text.de, "HCS: Falscher Datenwert"));
}

TEST(ModbusDescribe, BadCrcIsShownWithTheExpectedValue)
{
    Bytes bad = kRtuWriteC107;
    bad[6] = 0;
    const Description d = describeRtu(bad, opts(Direction::Request));
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error->code, DecodeErrc::BadChecksum);
    EXPECT_TRUE(contains(d.field("crc")->text.en, "wrong, expected 0x7B89"));
    EXPECT_EQ(d.field("pdu.value")->value, "1000"); // the PDU is still explained
}

TEST(ModbusDescribe, MoreThanEightRegistersGetsTheHcsNote)
{
    const Description d = describeRtu(kClassicRead10, opts(Direction::Request));
    ASSERT_TRUE(d.ok());
    ASSERT_NE(d.field("note"), nullptr);
    EXPECT_TRUE(contains(d.field("note")->text.en, "exception 3"));
}

TEST(ModbusDescribe, TcpHeaderFields)
{
    const Description d = describeTcp(kTcpWriteC107, opts(Direction::Request));
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d.protocol, "modbus-tcp");
    EXPECT_EQ(d.field("mbap.transaction")->value, "2");
    EXPECT_EQ(d.field("mbap.protocol")->value, "0");
    EXPECT_EQ(d.field("mbap.length")->value, "6");
    EXPECT_EQ(d.field("mbap.unit")->value, "1");
    EXPECT_EQ(d.field("pdu.address")->offset, 8u);
    EXPECT_EQ(d.field("pdu.value")->value, "1000");
}

TEST(ModbusDescribe, TruncatedTcpDescribesTheHeader)
{
    const Description d =
        describeTcp(std::span<const std::uint8_t>(kTcpReadD107).first(9), opts(Direction::Request));
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error->code, DecodeErrc::Truncated);
    EXPECT_EQ(d.error->offset, 9u);
    EXPECT_NE(d.field("mbap.unit"), nullptr);
    EXPECT_NE(d.field("pdu.function"), nullptr);
    EXPECT_EQ(d.field("pdu.start"), nullptr); // only 1 of its 2 bytes is there
}

TEST(ModbusDescribe, AllVectorsCompleteInBothLanguagesAndTileTheFrame)
{
    auto check = [](const Description &d, std::size_t size, const std::string &name) {
        EXPECT_TRUE(d.ok()) << name;
        EXPECT_TRUE(d.summary.complete()) << name;
        std::size_t covered = 0;
        for (const FieldSpan &f : d.fields) {
            EXPECT_TRUE(f.text.complete()) << name << " " << f.key;
            covered += f.depth == 0 ? f.length : 0;
        }
        EXPECT_EQ(covered, size) << name;
    };
    for (const Vector &v : rtuVectors())
        check(describeRtu(v.bytes, opts(v.direction)), v.bytes.size(), v.name);
    for (const Vector &v : tcpVectors())
        check(describeTcp(v.bytes, opts(v.direction)), v.bytes.size(), v.name);
}
