// CanopenAdapter against the simulated SDO server (devices/sim/canopen_sdo_server.h) over
// 16-byte SocketCAN images: HCS parameters at 0x2000 + ID (ARCHITECTURE.md "CAN") on a simulated
// DMA-2, the ED1's CiA 408 objects from the dictionary; expedited transfers, little-endian values
// and the abort codes of CiA 301 §7.2.4.3.
#include "access/canopen_adapter.h"
#include "adapter_rig.h"
#include "canopen/can_frame.h"
#include "dict/dictionary_loader.h"
#include "hcs_adapter_support.h"
#include "sim/canopen_dsp408_objects.h"
#include "sim/canopen_hcs_objects.h"
#include "sim/canopen_sdo_server.h"
#include "sim/dsp408_device.h"
#include "sim/node_config.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::access;
using access::test::Rig;

namespace {

constexpr int kHcsNode = 5;
constexpr int kEd1Node = 7;

struct HcsCanRig
{
    sim::SimClock clock;
    std::unique_ptr<sim::HcsNode> node = std::move(sim::makeNode(clock, "dma-pn-v51", 1)).value();
    sim::HcsModule &module = node->module(0);
    sim::HcsParamObjects objects{module.dictionary(), module.storage(), module.storage(),
                                 [this](int id) { return module.storage().meta(id); }};
    sim::CanopenSdoServer server{objects, kHcsNode};
    CanopenAdapter adapter{CanopenProfile::Hcs};
    Rig rig{adapter, server, clock};
};

struct Ed1CanRig
{
    const Dictionary &ed1 = *builtinDictionaries()->find("wandfluh-ed1");
    sim::SimClock clock;
    sim::Dsp408Device device{ed1};
    sim::Dsp408Objects objects{device};
    sim::CanopenSdoServer server{objects, kEd1Node};
    CanopenAdapter adapter{CanopenProfile::Dsp408};
    Rig rig{adapter, server, clock};

    const ParamMeta &row(const char *name) const { return *ed1.find(name); }
    Transaction readOf(const ParamMeta &r) const
    {
        return Transaction{TransactionKind::Read, kEd1Node, {&r}, {}, 0, {}, true};
    }
};

Transaction readOf(int node, const ParamMeta &row)
{
    return Transaction{TransactionKind::Read, node, {&row}, {}, 0, {}, true};
}

void expectAbort(const std::optional<Reply> &reply, std::uint32_t code)
{
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::DeviceException);
    EXPECT_EQ(static_cast<std::uint32_t>(reply->exceptionCode), code);
    EXPECT_EQ(reply->exceptionText, canopen::abortCodeText(code));
}

Bytes image(std::uint32_t id, std::initializer_list<std::uint8_t> data)
{
    const auto a = canopen::toSocketCan(canopen::makeCanFrame(id, Bytes(data)));
    return Bytes(a.begin(), a.end());
}

} // namespace

TEST(CanopenAdapter, HcsIdentifiesByVersAndE00)
{
    HcsCanRig r;
    const auto plan = r.adapter.planIdentify(kHcsNode);
    ASSERT_EQ(plan.size(), 2u);
    const auto vers = access::test::okReply(r.rig.run(plan[0]));
    const auto mode = access::test::okReply(r.rig.run(plan[1]));
    ASSERT_TRUE(vers && mode);
    EXPECT_EQ(vers->identity.versRaw, 5100);
    EXPECT_EQ(mode->identity.mode, r.module.mode());
    // Upload of 0x2000 to node 5: COB-ID 0x605, 40 00 20 00 …
    const auto request = canopen::fromSocketCan(r.adapter.encode(plan[0]));
    ASSERT_TRUE(request.ok());
    EXPECT_EQ(request->id, 0x605u);
    EXPECT_EQ(request->data[0], 0x40);
    EXPECT_EQ(request->data[1], 0x00);
    EXPECT_EQ(request->data[2], 0x20);
}

TEST(CanopenAdapter, HcsReadsEveryReadableRow)
{
    HcsCanRig r;
    const auto rows = sim::test::readableRows(r.module);
    ASSERT_GT(rows.size(), 100u);
    const auto plan = r.adapter.planRead(kHcsNode, rows);
    ASSERT_EQ(plan.size(), rows.size()); // one upload per row
    const auto values = r.rig.readAll(plan);
    ASSERT_EQ(values.size(), rows.size());
    for (const auto &[row, value] : values)
        EXPECT_EQ(rawNumber(value), access::test::storedRaw(r.module, *row)) << row->name;
}

TEST(CanopenAdapter, HcsWritesReadsBackAndRefuses)
{
    HcsCanRig r;
    const ParamMeta *row = access::test::writableRow(r.module);
    ASSERT_NE(row, nullptr);
    const double value = access::test::otherValue(r.module, *row);
    const auto written =
        access::test::okReply(r.rig.run(r.adapter.planWrite(kHcsNode, *row, value)));
    ASSERT_TRUE(written);
    EXPECT_EQ(written->values, std::vector<RawValue>{value});
    EXPECT_EQ(access::test::storedRaw(r.module, *row), value);
    const auto back = access::test::okReply(r.rig.run(readOf(kHcsNode, *row)));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->values, std::vector<RawValue>{value});

    const ParamMeta *bounded = access::test::boundedRow(r.module);
    ASSERT_NE(bounded, nullptr);
    expectAbort(r.rig.run(r.adapter.planWrite(kHcsNode, *bounded, bounded->max + 1)), 0x06090031);
    expectAbort(r.rig.run(r.adapter.planWrite(kHcsNode, *r.module.storage().meta(0), 1.0)),
                0x06010002);
    ParamMeta missing;
    missing.id = 0x3FF;
    expectAbort(r.rig.run(readOf(kHcsNode, missing)), 0x06020000);
    // What the adapter cannot send: no node 0 or 128, no object, a value outside int16.
    EXPECT_TRUE(r.adapter.encode(readOf(0, *row)).empty());
    EXPECT_TRUE(r.adapter.encode(readOf(128, *row)).empty());
    EXPECT_TRUE(r.adapter.encode(readOf(kHcsNode, ParamMeta{})).empty());
    EXPECT_TRUE(r.adapter.encode(r.adapter.planWrite(kHcsNode, *row, 65535.0)).empty());
}

TEST(CanopenAdapter, Ed1IdentifiesByDeviceTypeAndReadsItsObjects)
{
    Ed1CanRig r;
    const auto plan = r.adapter.planIdentify(kEd1Node);
    ASSERT_EQ(plan.size(), 2u);
    const auto id = access::test::okReply(r.rig.run(plan.front()));
    ASSERT_TRUE(id);
    EXPECT_EQ(id->values, std::vector<RawValue>{408.0}); // CiA 301 0x1000: profile 408
    EXPECT_EQ(id->identity.deviceProfile, 408);
    EXPECT_NE(id->identity.text.en.find("profile 408"), std::string::npos);
    // The simulated card has no capability object 0x605F (the manual names none): the abort is
    // no failure, the step answers without a capability.
    const auto capability = access::test::okReply(r.rig.run(plan.back()));
    ASSERT_TRUE(capability);
    EXPECT_EQ(capability->identity.capability, 0u);
    EXPECT_NE(capability->identity.text.en.find("0x605F"), std::string::npos);

    std::vector<const ParamMeta *> rows;
    for (const ParamMeta &p : r.ed1.params)
        rows.push_back(&p);
    const auto reads = r.adapter.planRead(kEd1Node, rows);
    std::vector<std::string> names;
    for (const Transaction &t : reads)
        names.push_back(t.rows.front()->name);
    // The readable rows with an object (0x6040 control word is write-only).
    EXPECT_EQ(names, (std::vector<std::string>{"db_StatusWord", "db_DeviceMode", "db_ControlMode",
                                               "db_Local", "dpc_SetpointVal", "dpc_ActualVal"}));
    for (const auto &[row, value] : r.rig.readAll(reads)) {
        double raw = 0;
        ASSERT_FALSE(r.device.read(*row, raw).has_value()) << row->name;
        EXPECT_EQ(rawNumber(value), raw) << row->name;
    }
}

TEST(CanopenAdapter, Ed1WritesLittleEndianAndMapsAborts)
{
    Ed1CanRig r;
    // 32-bit values: little-endian both ways.
    const ParamMeta &setpoint = r.row("dpc_SetpointVal");
    const auto ok =
        access::test::okReply(r.rig.run(r.adapter.planWrite(kEd1Node, setpoint, 1000.0)));
    ASSERT_TRUE(ok);
    EXPECT_EQ(access::test::okReply(r.rig.run(r.readOf(setpoint)))->values,
              std::vector<RawValue>{1000.0});
    const ParamMeta &mode = r.row("db_DeviceMode");
    const Transaction write = r.adapter.planWrite(kEd1Node, mode, 2.0);
    const auto request = canopen::fromSocketCan(r.adapter.encode(write));
    ASSERT_TRUE(request.ok());
    EXPECT_EQ(request->id, 0x607u);
    // Expedited download of 1 byte with size: 2F 42 60 00 02 (CiA 301: index little-endian).
    EXPECT_EQ(Bytes(request->data.begin(), request->data.begin() + 5),
              (Bytes{0x2F, 0x42, 0x60, 0x00, 0x02}));
    EXPECT_EQ(access::test::okReply(r.rig.run(write))->values, std::vector<RawValue>{2.0});
    EXPECT_EQ(access::test::okReply(r.rig.run(r.readOf(mode)))->values, std::vector<RawValue>{2.0});

    expectAbort(r.rig.run(r.adapter.planWrite(kEd1Node, mode, 3.0)), 0x06090031);
    expectAbort(r.rig.run(r.adapter.planWrite(kEd1Node, r.row("db_StatusWord"), 1.0)), 0x06010002);
    expectAbort(r.rig.run(r.readOf(r.row("db_ControlWord"))), 0x06010001); // write-only
    EXPECT_TRUE(
        r.adapter.encode(r.adapter.planWrite(kEd1Node, mode, 200.0)).empty()); // not an int8
}

TEST(CanopenAdapter, OtherBusTrafficAndSplitImages)
{
    Ed1CanRig r;
    const ParamMeta &mode = r.row("db_DeviceMode");
    const Transaction read = r.readOf(mode);
    r.rig.chunk = 1;
    EXPECT_TRUE(access::test::okReply(r.rig.run(read)));
    r.rig.chunk = 7;
    EXPECT_TRUE(access::test::okReply(r.rig.run(read)));
    // A heartbeat of node 7, another node's SDO answer, an answer for another object of our
    // node, then ours — in one chunk.
    const Bytes answer = r.rig.ask(r.adapter.encode(read));
    Bytes merged = image(0x707, {0x05});
    const Bytes other = image(0x586, {0x4F, 0x42, 0x60, 0x00, 0x01, 0, 0, 0});
    const Bytes wrongObject = image(0x587, {0x4F, 0x43, 0x60, 0x00, 0x09, 0, 0, 0});
    for (const Bytes *b : {&other, &wrongObject, &answer})
        merged.insert(merged.end(), b->begin(), b->end());
    const auto reply = access::test::okReply(r.adapter.feed(merged, read));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->frame, answer);
    // Mismatch only, and a CAN FD length is dropped.
    Bytes fd = image(0x587, {0x4F, 0x42, 0x60, 0x00, 0x01, 0, 0, 0});
    fd[4] = 12;
    EXPECT_FALSE(r.adapter.feed(fd, read).has_value());
    const auto mismatch = r.adapter.feed(other, read);
    ASSERT_TRUE(mismatch);
    EXPECT_EQ(mismatch->status, ReplyStatus::Mismatch);
}

TEST(CanopenAdapter, ChangedFrameBytesAreNeverAccepted)
{
    HcsCanRig r;
    const ParamMeta *row = access::test::writableRow(r.module);
    ASSERT_NE(row, nullptr);
    const Transaction read = readOf(kHcsNode, *row);
    const Bytes answer = r.rig.ask(r.adapter.encode(read));
    ASSERT_EQ(answer.size(), 16u);
    // can_id (0..3), len (4), index / sub-index (9..11) are checked; bytes 5..7 are padding; a
    // changed command byte 8 may only drop the size bit; the value bytes 12..15 are covered by
    // the CAN CRC, not by the SDO.
    for (std::uint8_t mask : {std::uint8_t{0x01}, std::uint8_t{0x80}})
        access::test::expectCorruptionRejected(
            r.adapter, answer, read, {access::test::storedRaw(r.module, *row)},
            [](std::size_t i) { return i <= 4 || (i >= 9 && i <= 11); },
            [](std::size_t i) { return i >= 12; }, mask);
}
