// NodeImageAdapter against the simulated node's image front end (devices/sim/node_image_server.h):
// CMD 3 / 6 in fixed-length images (DMA Profinet manual §4.5.4 "IN/OUT 42 byte"), TADR toggled
// per request because the node answers only changed requests (OPAT manual §1.5, DMA Profinet
// manual §1.4), exceptions with their texts (§3.3 / §3.6), chunking and lost alignment.
#include "access/node_image_adapter.h"
#include "adapter_rig.h"
#include "hcs/exceptions.h"
#include "hcs_adapter_support.h"
#include "sim/hcs_codes.h"
#include "sim/node_config.h"
#include "sim/node_image_server.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::access;
using access::test::Rig;

namespace {

struct NodeImageRig
{
    sim::SimClock clock;
    std::unique_ptr<sim::HcsNode> node;
    std::unique_ptr<sim::NodeImageServer> server;
    NodeImageAdapter adapter;
    Rig rig;

    explicit NodeImageRig(const char *family = "dma-pn-v51", hcs::Family f = hcs::Family::Dma)
        : node(std::move(sim::makeNode(clock, family, 3)).value()),
          server(std::make_unique<sim::NodeImageServer>(clock, *node)),
          adapter(f), rig{adapter, *server, clock}
    {
    }

    Transaction readOf(int module, std::vector<const ParamMeta *> rows)
    {
        return Transaction{TransactionKind::Read, module, std::move(rows), {}, 0, {}, true};
    }
};

} // namespace

TEST(NodeImageAdapter, IdentifiesEveryModuleByVersAndE00)
{
    NodeImageRig r;
    for (std::size_t i = 0; i < r.node->moduleCount(); ++i) {
        const sim::HcsModule &m = r.node->module(i);
        const auto plan = r.adapter.planIdentify(m.address());
        ASSERT_EQ(plan.size(), 2u);
        const auto vers = access::test::okReply(r.rig.run(plan[0]));
        const auto mode = access::test::okReply(r.rig.run(plan[1]));
        ASSERT_TRUE(vers && mode);
        EXPECT_EQ(vers->identity.versRaw, 5100);
        EXPECT_EQ(mode->identity.mode, m.mode());
    }
}

TEST(NodeImageAdapter, OpatMasterAnswersInA43ByteImage)
{
    NodeImageRig r("opat", hcs::Family::Opat);
    EXPECT_EQ(r.adapter.layout().inputBytes, 43u);
    const auto plan = r.adapter.planIdentify(0); // the OPAT master is SADR 0 (OPAT manual §1.4)
    const auto vers = access::test::okReply(r.rig.run(plan[0]));
    ASSERT_TRUE(vers);
    EXPECT_EQ(vers->identity.versRaw, 3400);
    EXPECT_EQ(vers->frame.size(), 43u);
}

TEST(NodeImageAdapter, ReadsEveryReadableRowInBlocksOfEight)
{
    NodeImageRig r;
    const sim::HcsModule &m = r.node->module(1);
    const auto rows = sim::test::readableRows(m);
    ASSERT_GT(rows.size(), 100u);
    const auto plan = r.adapter.planRead(m.address(), rows);
    for (const Transaction &t : plan) {
        ASSERT_LE(t.rows.size(), 8u);
        for (std::size_t i = 1; i < t.rows.size(); ++i)
            EXPECT_EQ(*t.rows[i]->id, *t.rows[i - 1]->id + 1);
    }
    const auto values = r.rig.readAll(plan);
    ASSERT_EQ(values.size(), rows.size());
    for (const auto &[row, value] : values)
        EXPECT_EQ(rawNumber(value), access::test::storedRaw(m, *row)) << row->name;
}

TEST(NodeImageAdapter, WritesAndReadsBack)
{
    NodeImageRig r;
    sim::HcsModule &m = r.node->module(2);
    const ParamMeta *row = access::test::writableRow(m);
    ASSERT_NE(row, nullptr);
    const double value = access::test::otherValue(m, *row);
    const auto written =
        access::test::okReply(r.rig.run(r.adapter.planWrite(m.address(), *row, value)));
    ASSERT_TRUE(written);
    EXPECT_EQ(written->values, std::vector<RawValue>{value});
    EXPECT_EQ(access::test::storedRaw(m, *row), value);
    r.clock.advance(30'000); // DMA Profinet manual §3.4.1: ≥ 30 ms between EEPROM writes
    const auto back = access::test::okReply(r.rig.run(r.readOf(m.address(), {row})));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->values, std::vector<RawValue>{value});
}

TEST(NodeImageAdapter, RefusalsComeBackAsDeviceExceptionsWithTheirTexts)
{
    NodeImageRig r;
    const sim::HcsModule &m = r.node->module(0);
    const ParamMeta *bounded = access::test::boundedRow(m);
    ASSERT_NE(bounded, nullptr);
    auto reply = r.rig.run(r.adapter.planWrite(m.address(), *bounded, bounded->max + 1));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::DeviceException);
    EXPECT_EQ(reply->exceptionCode, sim::exce::kWrongData);
    EXPECT_EQ(reply->exceptionText, hcs::exceptionTextOrUnknown(hcs::Family::Dma, 6, 3));

    const ParamMeta *vers = m.storage().meta(0); // read only
    reply = r.rig.run(r.adapter.planWrite(m.address(), *vers, 1234.0));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::DeviceException);
    EXPECT_EQ(reply->exceptionCode, sim::exce::kWrongId);

    // No module at SADR 9: the node answers 5 (DMA Profinet manual §3.3).
    reply = r.rig.run(r.readOf(9, {vers}));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::DeviceException);
    EXPECT_EQ(reply->exceptionCode, sim::exce::kSlaveTimeout);
    EXPECT_EQ(reply->exceptionText, hcs::exceptionTextOrUnknown(hcs::Family::Dma, 3, 5));
}

TEST(NodeImageAdapter, ValuesTheTelegramCannotCarryAreNotEncoded)
{
    NodeImageAdapter adapter(hcs::Family::Dma);
    ParamMeta row;
    row.id = 53;
    row.type = RawType::Int16;
    row.access = Access::ReadWrite;
    EXPECT_TRUE(adapter.encode(adapter.planWrite(1, row, 65535.0)).empty()); // would arrive as -1
    EXPECT_TRUE(adapter.encode(adapter.planWrite(1, row, 1.5)).empty());
    EXPECT_TRUE(adapter.encode(adapter.planWrite(1, row, std::string("x"))).empty());
    EXPECT_TRUE(adapter.encode(adapter.planWrite(300, row, 1.0)).empty());
    ParamMeta noId;
    EXPECT_TRUE(adapter.encode(adapter.planWrite(1, noId, 1.0)).empty());
    EXPECT_EQ(adapter.encode(adapter.planWrite(1, row, -1.0)).size(), 42u);
}

TEST(NodeImageAdapter, EveryAttemptTogglesTadrSoTheNodeAnswersARetry)
{
    NodeImageRig r;
    const auto t = r.adapter.planIdentify(1).front();
    const Bytes first = r.adapter.encode(t);
    const Bytes second = r.adapter.encode(t);
    ASSERT_EQ(first.size(), 42u);
    EXPECT_NE(first[0], second[0]);
    EXPECT_TRUE(std::equal(first.begin() + 1, first.end(), second.begin() + 1));
    r.server->receive(first);
    r.server->receive(second);
    r.server->receive(second); // unchanged: the node stays silent
    EXPECT_EQ(r.server->imagesAnswered(), 2u);
    // Only the answer to the last attempt is taken; the first is a late answer (Mismatch).
    const Bytes answers = r.server->drain();
    ASSERT_EQ(answers.size(), 84u);
    auto late = r.adapter.feed(std::span(answers).first(42), t);
    ASSERT_TRUE(late);
    EXPECT_EQ(late->status, ReplyStatus::Mismatch);
    auto reply = access::test::okReply(r.adapter.feed(std::span(answers).subspan(42), t));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->frame.at(0), second[0]);
}

TEST(NodeImageAdapter, SplitAndMergedImages)
{
    NodeImageRig r;
    const sim::HcsModule &m = r.node->module(0);
    const auto rows = sim::test::readableRows(m);
    const auto plan = r.adapter.planRead(m.address(), rows);
    for (std::size_t chunk : {std::size_t{1}, std::size_t{5}, std::size_t{41}, std::size_t{43}}) {
        r.rig.chunk = chunk;
        const auto values = r.rig.readAll({plan.front()});
        ASSERT_EQ(values.size(), plan.front().rows.size()) << chunk;
        EXPECT_EQ(rawNumber(values.front().second),
                  access::test::storedRaw(m, *values.front().first));
    }
    // An idle image, a late answer and the answer in one chunk.
    const Transaction &t = plan.front();
    const Bytes late = r.rig.ask(r.adapter.encode(t));
    const Bytes answer = r.rig.ask(r.adapter.encode(t));
    Bytes merged(42, 0);
    merged.insert(merged.end(), late.begin(), late.end());
    merged.insert(merged.end(), answer.begin(), answer.end());
    const auto reply = access::test::okReply(r.adapter.feed(merged, t));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->frame, answer);
}

TEST(NodeImageAdapter, ChangedHeaderBytesAreNeverAccepted)
{
    NodeImageRig r;
    const sim::HcsModule &m = r.node->module(1);
    const auto [t, answer, truth] = access::test::firstReadBlock(r.rig, m);
    const std::size_t cnt = 2 * t.rows.size();
    // TADR SADR CMD CNT are checked; the values have no checksum (TCP has one).
    access::test::expectCorruptionRejected(
        r.adapter, answer, t, truth, [](std::size_t i) { return i < 4; },
        [cnt](std::size_t i) { return i >= 4 && i < 4 + cnt; });
}

TEST(NodeImageAdapter, FindsTheAnswerAgainAfterATimeoutCutAnImage)
{
    NodeImageRig r;
    const auto t = r.adapter.planIdentify(2).front();
    // Every TADR value and cut position: the rest of the cut image arrives after the reset, in
    // the same chunk as the retry's answer.
    for (std::size_t k = 0; k < 300; ++k) {
        const Bytes first = r.rig.ask(r.adapter.encode(t));
        ASSERT_EQ(first.size(), 42u);
        const std::size_t cut = 1 + k % 41;
        EXPECT_FALSE(r.adapter.feed(std::span(first).first(cut), t).has_value());
        r.adapter.resetFraming();
        const Bytes retry = r.rig.ask(r.adapter.encode(t));
        Bytes chunk(first.begin() + static_cast<std::ptrdiff_t>(cut), first.end());
        chunk.insert(chunk.end(), retry.begin(), retry.end());
        const auto reply = r.adapter.feed(chunk, t);
        ASSERT_TRUE(reply) << "k " << k;
        ASSERT_EQ(reply->status, ReplyStatus::Ok) << "k " << k;
        EXPECT_EQ(reply->identity.versRaw, 5100);
        EXPECT_EQ(reply->frame, retry);
    }
}
