// ModbusRtuAdapter / ModbusTcpAdapter (devices/access/modbus_adapter.h) against the
// simulated node's Modbus front ends (devices/sim/modbus_rtu_server.h, modbus_tcp_server.h):
// CMD 3 = FC 3 in blocks of ≤ 8, CMD 6 = FC 6, exceptions with the HCS meaning (ARCHITECTURE.md
// "Protocol decisions"), CRC, MBAP transaction numbers, chunking.
#include "access/modbus_adapter.h"
#include "adapter_rig.h"
#include "hcs_adapter_support.h"
#include "modbus/exceptions.h"
#include "sim/hcs_codes.h"
#include "sim/modbus_rtu_server.h"
#include "sim/modbus_tcp_server.h"
#include "sim/node_config.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::access;
using access::test::Rig;

namespace {

template<typename Server, typename Adapter> struct ModbusRig
{
    sim::SimClock clock;
    std::unique_ptr<sim::HcsNode> node;
    Server server;
    Adapter adapter;
    Rig rig;

    explicit ModbusRig(const char *family = "dma-pn-v51", hcs::Family f = hcs::Family::Dma)
        : node(std::move(sim::makeNode(clock, family, 3)).value()), server(clock, *node),
          adapter(f), rig{adapter, server, clock}
    {
    }

    Transaction readOf(int unit, const ParamMeta &row)
    {
        return Transaction{TransactionKind::Read, unit, {&row}, {}, 0, {}, true};
    }

    void identifyAndReadAll(std::size_t index)
    {
        const sim::HcsModule &m = node->module(index);
        const auto plan = adapter.planIdentify(m.address());
        ASSERT_EQ(plan.size(), 2u);
        const auto vers = access::test::okReply(rig.run(plan[0]));
        const auto mode = access::test::okReply(rig.run(plan[1]));
        ASSERT_TRUE(vers && mode);
        EXPECT_EQ(vers->identity.versRaw, std::stoi(m.version()) * 100);
        EXPECT_EQ(mode->identity.mode, m.mode());
        const auto rows = sim::test::readableRows(m);
        ASSERT_GT(rows.size(), 50u);
        const auto values = rig.readAll(adapter.planRead(m.address(), rows));
        ASSERT_EQ(values.size(), rows.size());
        for (const auto &[row, value] : values)
            EXPECT_EQ(rawNumber(value), access::test::storedRaw(m, *row)) << row->name;
    }

    void writeReadBackAndRefuse()
    {
        sim::HcsModule &m = node->module(1);
        const ParamMeta *row = access::test::writableRow(m);
        ASSERT_NE(row, nullptr);
        const double value = access::test::otherValue(m, *row);
        const auto written =
            access::test::okReply(rig.run(adapter.planWrite(m.address(), *row, value)));
        ASSERT_TRUE(written);
        EXPECT_EQ(written->values, std::vector<RawValue>{value});
        EXPECT_EQ(access::test::storedRaw(m, *row), value);
        clock.advance(30'000); // DMA Profinet manual §3.4.1: ≥ 30 ms between EEPROM writes
        const auto back = access::test::okReply(rig.run(readOf(m.address(), *row)));
        ASSERT_TRUE(back);
        EXPECT_EQ(back->values, std::vector<RawValue>{value});

        const ParamMeta *bounded = access::test::boundedRow(m);
        ASSERT_NE(bounded, nullptr);
        auto reply = rig.run(adapter.planWrite(m.address(), *bounded, bounded->max + 1));
        ASSERT_TRUE(reply);
        EXPECT_EQ(reply->status, ReplyStatus::DeviceException);
        EXPECT_EQ(reply->exceptionCode, sim::exce::kWrongData);
        EXPECT_EQ(reply->exceptionText, modbus::exceptionText(6, 3, hcs::Family::Dma));
        reply = rig.run(adapter.planWrite(m.address(), *m.storage().meta(0), 1.0)); // Vers: r
        ASSERT_TRUE(reply);
        EXPECT_EQ(reply->status, ReplyStatus::DeviceException);
        EXPECT_EQ(reply->exceptionCode, sim::exce::kWrongId);
    }
};

using RtuRig = ModbusRig<sim::ModbusRtuServer, ModbusRtuAdapter>;
using TcpRig = ModbusRig<sim::ModbusTcpServer, ModbusTcpAdapter>;

} // namespace

TEST(ModbusRtuAdapter, IdentifiesAndReadsEveryRowOfEachUnit)
{
    RtuRig r;
    for (std::size_t i = 0; i < r.node->moduleCount(); ++i)
        r.identifyAndReadAll(i);
}

TEST(ModbusRtuAdapter, WritesReadsBackAndRefuses)
{
    RtuRig r;
    r.writeReadBackAndRefuse();
}

TEST(ModbusRtuAdapter, AnAbsentUnitIsSilent)
{
    RtuRig r;
    EXPECT_FALSE(r.rig.run(r.adapter.planIdentify(9).front(), 1));
}

TEST(ModbusRtuAdapter, EveryChangedByteFailsTheCrc)
{
    RtuRig r;
    const sim::HcsModule &m = r.node->module(0);
    const auto [t, answer, truth] = access::test::firstReadBlock(r.rig, m);
    for (std::uint8_t mask : {std::uint8_t{0x01}, std::uint8_t{0x80}, std::uint8_t{0xFF}})
        access::test::expectCorruptionRejected(
            r.adapter, answer, t, truth, [](std::size_t) { return true; }, {}, mask);
}

TEST(ModbusRtuAdapter, SplitAndMergedFrames)
{
    RtuRig r;
    const sim::HcsModule &m1 = r.node->module(0);
    const ParamMeta *row = access::test::writableRow(m1);
    ASSERT_NE(row, nullptr);
    r.rig.chunk = 1;
    EXPECT_EQ(access::test::okReply(r.rig.run(r.readOf(1, *row)))->values.front(),
              RawValue{access::test::storedRaw(m1, *row)});
    // Noise, unit 2's answer and unit 1's answer in one read: only unit 1's answers.
    const Bytes other = r.rig.ask(r.adapter.encode(r.readOf(2, *row)));
    const Bytes answer = r.rig.ask(r.adapter.encode(r.readOf(1, *row)));
    Bytes merged{0x00, 0x55};
    merged.insert(merged.end(), other.begin(), other.end());
    merged.insert(merged.end(), answer.begin(), answer.end());
    const auto reply = access::test::okReply(r.adapter.feed(merged, r.readOf(1, *row)));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->frame, answer);
    EXPECT_EQ(reply->values, std::vector<RawValue>{access::test::storedRaw(m1, *row)});
}

// A quiet inside the awaited answer (a USB adapter's latency timer, a busy PC) keeps its start;
// the rest completes it. A quiet after anything else drops it (Modbus over Serial Line §2.5.1.1).
TEST(ModbusRtuAdapter, AQuietKeepsOnlyTheStartOfTheAwaitedAnswer)
{
    RtuRig r;
    const sim::HcsModule &m = r.node->module(0);
    const auto [t, answer, truth] = access::test::firstReadBlock(r.rig, m);
    ASSERT_EQ(answer.size(), r.adapter.expectedReplyBytes(t));
    for (std::size_t split = 1; split < answer.size(); ++split) {
        r.adapter.resetFraming();
        const std::span<const std::uint8_t> bytes(answer);
        EXPECT_FALSE(r.adapter.feed(bytes.first(split), t));
        r.adapter.lineQuiet(&t);
        const auto reply = access::test::okReply(r.adapter.feed(bytes.subspan(split), t));
        ASSERT_TRUE(reply) << "split after byte " << split;
        EXPECT_EQ(reply->frame, answer);
    }
    // Without a transaction on the wire, or for another unit's request, the start is dropped and
    // the rest alone is no frame.
    Transaction otherUnit = t;
    otherUnit.module = 2;
    for (const Transaction *awaited : {static_cast<const Transaction *>(nullptr),
                                       static_cast<const Transaction *>(&otherUnit)}) {
        r.adapter.resetFraming();
        const std::span<const std::uint8_t> bytes(answer);
        EXPECT_FALSE(r.adapter.feed(bytes.first(5), t));
        r.adapter.lineQuiet(awaited);
        EXPECT_FALSE(r.adapter.feed(bytes.subspan(5), t));
    }
    // The start of an answer with another byte count is not the awaited one.
    Transaction shorter = t;
    shorter.rows.pop_back();
    r.adapter.resetFraming();
    EXPECT_FALSE(r.adapter.feed(std::span<const std::uint8_t>(answer).first(5), t));
    r.adapter.lineQuiet(&shorter);
    EXPECT_FALSE(r.adapter.feed(std::span<const std::uint8_t>(answer).subspan(5), t));
    // An exception's start is kept like an answer's.
    const Bytes exception{0x01, 0x83, 0x02, 0xC0, 0xF1};
    r.adapter.resetFraming();
    EXPECT_FALSE(r.adapter.feed(std::span<const std::uint8_t>(exception).first(2), t));
    r.adapter.lineQuiet(&t);
    const auto refused = r.adapter.feed(std::span<const std::uint8_t>(exception).subspan(2), t);
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->status, ReplyStatus::DeviceException);
}

TEST(ModbusTcpAdapter, IdentifiesAndReadsEveryRowOfEachUnit)
{
    TcpRig r;
    for (std::size_t i = 0; i < r.node->moduleCount(); ++i)
        r.identifyAndReadAll(i);
}

TEST(ModbusTcpAdapter, ReachesTheOpatMasterAsUnit0)
{
    TcpRig r("opat", hcs::Family::Opat);
    r.identifyAndReadAll(0);
    r.identifyAndReadAll(2);
}

TEST(ModbusTcpAdapter, WritesReadsBackAndRefuses)
{
    TcpRig r;
    r.writeReadBackAndRefuse();
    // A gateway answers for a missing unit: 5 (SIMULATOR.md "Front ends").
    const auto reply = r.rig.run(r.adapter.planIdentify(9).front());
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::DeviceException);
    EXPECT_EQ(reply->exceptionCode, sim::exce::kSlaveTimeout);
    EXPECT_EQ(reply->exceptionText, modbus::exceptionText(3, 5, hcs::Family::Dma));
}

TEST(ModbusTcpAdapter, ALateAnswerToAnEarlierAttemptIsIgnored)
{
    TcpRig r;
    const Transaction t = r.adapter.planIdentify(1).front();
    const Bytes late = r.rig.ask(r.adapter.encode(t));
    const Bytes answer = r.rig.ask(r.adapter.encode(t));
    ASSERT_NE(late, answer); // the transaction number differs
    const auto mismatch = r.adapter.feed(late, t);
    ASSERT_TRUE(mismatch);
    EXPECT_EQ(mismatch->status, ReplyStatus::Mismatch);
    Bytes merged = late;
    merged.insert(merged.end(), answer.begin(), answer.end());
    r.adapter.resetFraming();
    for (std::size_t chunk : {std::size_t{1}, std::size_t{4}, access::test::kWhole}) {
        const auto reply =
            access::test::okReply(access::test::feedChunks(r.adapter, merged, t, chunk));
        ASSERT_TRUE(reply);
        EXPECT_EQ(reply->frame, answer);
        EXPECT_EQ(reply->identity.versRaw, 5100);
    }
}

TEST(ModbusTcpAdapter, ChangedHeaderBytesAreNeverAccepted)
{
    TcpRig r;
    const sim::HcsModule &m = r.node->module(2);
    const auto [t, answer, truth] = access::test::firstReadBlock(r.rig, m);
    // MBAP (0..6), function code and byte count are checked; the values have no checksum.
    access::test::expectCorruptionRejected(
        r.adapter, answer, t, truth, [](std::size_t i) { return i < 9; },
        [](std::size_t i) { return i >= 9; });
}

// 65535 written to an int16 row would arrive as 0xFFFF = -1; on a row whose range includes -1 (on
// a DMA V51 mode 3 module the last such row is C2.29, -9999..9999 V) the module would take it.
// The value is checked against the row's type before it becomes a register (hcsWordOf).
TEST(ModbusRtuAdapter, AValueOutsideTheRowsTypeIsNotSent)
{
    RtuRig r;
    sim::HcsModule &m = r.node->module(0);
    const ParamMeta *row = nullptr;
    for (const ParamMeta *candidate : sim::test::readableRows(m))
        if (candidate->writable() && candidate->type == RawType::Int16 && candidate->min <= -1 &&
            candidate->max >= -1)
            row = candidate;
    ASSERT_NE(row, nullptr);
    const Transaction write = r.adapter.planWrite(m.address(), *row, 65535.0);
    const Bytes request = r.adapter.encode(write);
    EXPECT_TRUE(request.empty()) << row->name << " = 65535 goes out as 0xFFFF";
    if (request.empty())
        return;
    const auto reply = r.adapter.feed(r.rig.ask(request), write);
    EXPECT_FALSE(reply && reply->status == ReplyStatus::Ok)
        << "taken as " << rawNumber(reply->values.at(0));
    EXPECT_NE(access::test::storedRaw(m, *row), -1.0);
}

// ARCHITECTURE.md "Protocol decisions": the RTU unit id is "configurable on point-to-point links
// (default 1)". The OPAT master is module 0 (SADR 0): addressed as unit 0, the Modbus broadcast,
// a read would never be answered and a write would reach every module on the line.
TEST(ModbusRtuAdapter, WithoutAPointToPointUnitModuleZeroIsNotSentAsBroadcast)
{
    ModbusRtuAdapter adapter(hcs::Family::Opat);
    EXPECT_TRUE(adapter.encode(adapter.planIdentify(0).front()).empty());
    EXPECT_FALSE(adapter.encode(adapter.planIdentify(1).front()).empty());
}

TEST(ModbusRtuAdapter, TheOpatMasterIsReachedThroughThePointToPointUnit)
{
    sim::SimClock clock;
    auto node = std::move(sim::makeNode(clock, "opat", 1)).value();
    sim::ModbusUnitOptions pointToPoint;
    pointToPoint.pointToPointUnit = 1;
    sim::ModbusRtuServer server(clock, *node, pointToPoint);
    ModbusRtuAdapter adapter(hcs::Family::Opat, std::uint8_t{1});
    Rig rig{adapter, server, clock};
    const Bytes request = adapter.encode(adapter.planIdentify(0).front());
    ASSERT_FALSE(request.empty());
    EXPECT_NE(request.front(), 0) << "unit 0 is the broadcast address";
    EXPECT_TRUE(rig.run(adapter.planIdentify(0).front(), 1).has_value());
}
