// The session engine against the built-in simulator: identify, read all in
// blocks of ≤ 8 consecutive IDs, priorities, timeouts and retries, link loss.
#include "dict/cooking.h"
#include "model/monitor/monitor_recording.h"
#include "model/monitor/monitor_scheduler.h"
#include "model/telegrams/telegram_log.h"
#include "model/telegrams/telegram_recorder.h"
#include "sim_rig.h"

#include <QSignalSpy>
#include <set>

namespace vt::test {
namespace {

using model::OutcomeStatus;
using model::Priority;

// d1.07 .. d1.13 (currents, desired/actual value, deviation, output): seven consecutive IDs, so
// one request per sample.
std::vector<const dev::ParamMeta *> displayBlockRows(const dev::Dictionary &dictionary)
{
    std::vector<const dev::ParamMeta *> rows;
    for (int id = 7; id <= 13; ++id)
        rows.push_back(dictionary.findId(id));
    return rows;
}

TEST(Session, IdentifiesEachHcsFamily)
{
    for (const char *family :
         {"opat", "dma-pn-v13", "dma-pn-v51", "dma-pb-v15", "dma-pb-v22", "dma-pb-v32"}) {
        auto c = openSim(family);
        ASSERT_TRUE(c);
        std::optional<model::IdentifyResult> result;
        c->access().identify(c->address(), [&](const model::IdentifyResult &r) { result = r; });
        ASSERT_TRUE(waitFor(result)) << family;
        EXPECT_TRUE(result->ok) << family << ": " << result->message.toStdString();
        ASSERT_TRUE(result->module.dictionary) << family;
        EXPECT_EQ(result->module.dictionary->family, family);
        EXPECT_EQ(result->module.mode, c->simModule().mode());
    }
}

TEST(Session, AnOpatNodeIsReachedModuleByModuleThroughItsGateway)
{
    auto c = openSim("opat", 3); // master SADR 0 + CAN slaves 1 and 2, Modbus TCP
    ASSERT_TRUE(c);
    EXPECT_EQ(c->simEndpoint()->spec().protocol, dev::LinkProtocol::ModbusTcp);
    for (std::size_t i = 0; i < 3; ++i) {
        std::optional<model::IdentifyResult> result;
        c->access().identify(c->address(i), [&](const model::IdentifyResult &r) { result = r; });
        ASSERT_TRUE(waitFor(result));
        EXPECT_TRUE(result->ok) << i << ": " << result->message.toStdString();
        EXPECT_EQ(result->module.versRaw / 100, std::stoi(c->simModule(i).version())) << i;
    }
}

TEST(Session, ReadAllMatchesTheSimulatorInBlocksOfAtMostEight)
{
    auto c = openSim("dma-pn-v51");
    ASSERT_TRUE(c);
    const auto rows = model::readableRows(c->dictionary(), c->simModule().version(),
                                          std::to_string(c->simModule().mode()));
    ASSERT_GT(rows.size(), 50u);

    std::vector<QByteArray> requests;
    QObject::connect(&c->session(), &model::Session::frameSent,
                     [&](const QByteArray &bytes, int, qint64) { requests.push_back(bytes); });
    int lastDone = 0, lastTotal = 0;
    std::optional<model::ReadResult> result;
    c->access().read(
        c->address(), rows, Priority::User, [&](const model::ReadResult &r) { result = r; },
        [&](int done, int total) {
            lastDone = done;
            lastTotal = total;
        });
    ASSERT_TRUE(waitFor(result));
    EXPECT_TRUE(result->complete());
    ASSERT_EQ(result->values.size(), rows.size());
    EXPECT_EQ(lastDone, lastTotal);
    EXPECT_EQ(static_cast<std::size_t>(lastTotal), requests.size());
    for (const QByteArray &request : requests) {
        ASSERT_EQ(request.size(), 8); // unit, FC 3, start, count, CRC
        EXPECT_EQ(request[1], 3);
        const int count =
            (static_cast<unsigned char>(request[4]) << 8) | static_cast<unsigned char>(request[5]);
        EXPECT_GE(count, 1);
        EXPECT_LE(count, 8); // OPAT manual §2.1 / DMA Profinet manual §3.1
    }
    for (const model::RowValue &v : result->values) {
        if (v.row->block == "d")
            continue; // live values move with the plant
        EXPECT_EQ(dev::rawNumber(v.value), storedRaw(c->simModule(), *v.row)) << v.row->name;
    }
    // No inactive or not-implemented row was asked for.
    std::set<int> asked;
    for (const QByteArray &request : requests) {
        const int start =
            (static_cast<unsigned char>(request[2]) << 8) | static_cast<unsigned char>(request[3]);
        const int count =
            (static_cast<unsigned char>(request[4]) << 8) | static_cast<unsigned char>(request[5]);
        for (int id = start; id < start + count; ++id)
            asked.insert(id);
    }
    for (const dev::ParamMeta &row : c->dictionary().params) {
        if (row.id && !row.readable()) {
            EXPECT_FALSE(asked.count(*row.id)) << row.name << " is not readable but was read";
        }
    }
}

TEST(Session, UserRequestsGoBeforeMonitorPolls)
{
    auto c = openSim("dma-pn-v13");
    ASSERT_TRUE(c);
    const dev::ParamMeta *c107 = c->dictionary().find("C1.07");
    ASSERT_TRUE(c107);
    std::vector<int> order;
    for (int i = 0; i < 3; ++i)
        c->session().submit(c->session()
                                .adapter()
                                .planRead(c->address(), std::vector<const dev::ParamMeta *>{c107})
                                .front(),
                            Priority::Monitor,
                            [&order](const model::Outcome &) { order.push_back(1); });
    c->session().submit(c->session()
                            .adapter()
                            .planRead(c->address(), std::vector<const dev::ParamMeta *>{c107})
                            .front(),
                        Priority::User, [&order](const model::Outcome &) { order.push_back(0); });
    ASSERT_TRUE(waitUntil([&] { return order.size() == 4; }, kWaitMs));
    EXPECT_EQ(order.front(), 0);
}

TEST(Session, TimesOutRetriesAndReportsWhenNobodyAnswers)
{
    link::FaultSpec silent;
    silent.rx.drop = 1.0;
    model::SessionOptions options;
    options.turnaround = std::chrono::milliseconds(20);
    options.retries = 2;
    options.backoff = std::chrono::milliseconds(1);
    auto c = openSim({"dma-pn-v13", 1, {}, silent, options});
    ASSERT_TRUE(c);
    QSignalSpy timeouts(&c->session(), &model::Session::attemptTimedOut);
    std::optional<model::Outcome> outcome;
    c->session().submit(c->session().adapter().planIdentify(c->address()).front(), Priority::User,
                        [&](const model::Outcome &o) { outcome = o; });
    ASSERT_TRUE(waitFor(outcome));
    EXPECT_EQ(outcome->status, OutcomeStatus::Timeout);
    EXPECT_EQ(outcome->attempts, 3);
    EXPECT_EQ(timeouts.count(), 3);
    EXPECT_EQ(c->session().counters().retries, 2u);
    EXPECT_EQ(c->session().counters().failures, 1u);
}

TEST(Session, TimeoutGrowsWithTheWireTime)
{
    model::SessionOptions options;
    options.turnaround = std::chrono::milliseconds(50);
    options.baudRate = 1200;
    options.bitsPerCharacter = 11;
    // 8 + 21 bytes × 11 bits at 1200 baud = 266 ms on the wire.
    EXPECT_EQ(options.timeout(8, 21).count(), 50 + 266);
    options.baudRate = 0;
    EXPECT_EQ(options.timeout(8, 21).count(), 50);
}

TEST(Session, LinkLossFailsWhatIsQueuedAndTheLinkCanReopen)
{
    auto c = openSim("dma-pn-v13");
    ASSERT_TRUE(c);
    const auto rows = model::readableRows(c->dictionary(), c->simModule().version(), "1");
    std::optional<model::ReadResult> result;
    c->access().read(c->address(), rows, Priority::User,
                     [&](const model::ReadResult &r) { result = r; });
    c->link().close();
    ASSERT_TRUE(waitFor(result));
    EXPECT_FALSE(result->complete());
    ASSERT_FALSE(result->failures.empty());
    EXPECT_EQ(result->failures.back().outcome.status, OutcomeStatus::LinkLost);

    ASSERT_TRUE(c->open());
    std::optional<model::ReadResult> again;
    c->access().read(c->address(), rows, Priority::User,
                     [&](const model::ReadResult &r) { again = r; });
    ASSERT_TRUE(waitFor(again));
    EXPECT_TRUE(again->complete());
}

TEST(Session, CancelledReadEndsWithoutTheRest)
{
    auto c = openSim("dma-pn-v51");
    ASSERT_TRUE(c);
    const auto rows = model::readableRows(c->dictionary(), c->simModule().version(), "3");
    std::optional<model::ReadResult> result;
    auto handle = c->access().read(c->address(), rows, Priority::User,
                                   [&](const model::ReadResult &r) { result = r; });
    handle->cancel();
    ASSERT_TRUE(waitFor(result));
    EXPECT_TRUE(result->cancelled);
    EXPECT_LT(result->values.size(), rows.size());
    EXPECT_LE(c->session().counters().attempts, 1u);
}

TEST(Session, MonitorPollsTheDisplayBlockAtTheRequestedRate)
{
    auto c = openSim("dma-pn-v51");
    ASSERT_TRUE(c);
    const auto rows = displayBlockRows(c->dictionary());
    ASSERT_EQ(rows.size(), 7u); // d1.07 .. d1.13 in one request
    EXPECT_EQ(rows.front()->name, "d1.07");
    EXPECT_EQ(rows.back()->name, "d1.13");
    model::MonitorScheduler monitor(c->access());
    QSignalSpy sampled(&monitor, &model::MonitorScheduler::sampled);
    QSignalSpy sent(&c->session(), &model::Session::frameSent);
    monitor.setModule(c->address(), rows, 50);
    monitor.start();
    ASSERT_TRUE(waitUntil([&] { return sampled.count() >= 40; }, kWaitMs));
    monitor.stop();
    EXPECT_EQ(sent.count(), sampled.count()); // one request per sample
    const double rate = monitor.achievedRate(c->address());
    EXPECT_GT(rate, 25.0); // a loaded CI machine may lag; the point is the upper bound
    EXPECT_LT(rate, 60.0);
    const auto sample = sampled.last().front().value<model::MonitorSample>();
    EXPECT_EQ(sample.values.size(), rows.size());
}

TEST(Session, MonitorSamplesGoToABoundedStoreInDisplayUnits)
{
    auto c = openSim("dma-pn-v51");
    ASSERT_TRUE(c);
    const auto rows = displayBlockRows(c->dictionary());
    model::SampleStore store(model::monitorChannels(rows, dev::Language::English), 10);
    ASSERT_EQ(store.channelCount(), 7);
    EXPECT_EQ(store.channels().front().id, QStringLiteral("d1.07"));
    model::MonitorScheduler monitor(c->access());
    model::recordSamples(monitor, c->address(), store);
    QSignalSpy sampled(&monitor, &model::MonitorScheduler::sampled);
    monitor.setModule(c->address(), rows, 0);
    monitor.start();
    ASSERT_TRUE(waitUntil([&] { return sampled.count() >= 25; }, kWaitMs));
    monitor.stop();
    EXPECT_EQ(store.size(), 10); // bounded: the newest 10 of 25+
    const auto last = sampled.last().front().value<model::MonitorSample>();
    EXPECT_DOUBLE_EQ(store.lastTime(), last.seconds);
    // The store keeps single precision (a bounded store of many samples): the commissioned
    // simulator's live values (currents, the held position) match to float precision.
    for (int ch = 0; ch < 7; ++ch) {
        EXPECT_FLOAT_EQ(static_cast<float>(store.valueAt(ch, store.size() - 1)),
                        static_cast<float>(dev::toDisplay(
                            *rows[static_cast<std::size_t>(ch)],
                            dev::rawNumber(last.values[static_cast<std::size_t>(ch)]))))
            << ch;
    }
}

TEST(Session, EveryFrameInAndOutGoesToTheTelegramLog)
{
    link::FaultSpec faults;
    faults.rx.drop = 0.1;
    faults.rx.corrupt = 0.2;
    faults.seed = 3;
    model::SessionOptions options;
    options.turnaround = std::chrono::milliseconds(30);
    options.retries = 8;
    auto c = openSim({"dma-pn-v13", 1, {}, faults, options});
    ASSERT_TRUE(c);
    model::TelegramLog log;
    model::TelegramRecorder recorder(c->session(), log);
    const auto rows = model::readableRows(c->dictionary(), c->simModule().version(), "1");
    std::optional<model::ReadResult> result;
    c->access().read(c->address(), rows, Priority::User,
                     [&](const model::ReadResult &r) { result = r; });
    ASSERT_TRUE(waitFor(result, 60'000));
    EXPECT_TRUE(result->complete());
    std::map<model::TelegramRecord::Status, int> byStatus;
    int requests = 0;
    for (auto it = log.begin(); it != log.end(); ++it) {
        if (it->direction == dev::Direction::Request) {
            ++requests;
            EXPECT_EQ(it->protocol, QStringLiteral("modbus-rtu"));
            EXPECT_EQ(it->link, c->link().description());
            EXPECT_EQ(it->module, c->address());
        } else {
            ++byStatus[it->status];
        }
    }
    EXPECT_EQ(static_cast<quint64>(requests), c->session().counters().attempts);
    EXPECT_EQ(static_cast<quint64>(byStatus[model::TelegramRecord::Status::Timeout]),
              c->session().counters().timeouts);
    EXPECT_GT(byStatus[model::TelegramRecord::Status::Timeout], 0);
    EXPECT_GT(byStatus[model::TelegramRecord::Status::ChecksumError], 0);
    EXPECT_EQ(byStatus[model::TelegramRecord::Status::Ok],
              static_cast<int>(c->session().counters().requests));
}

} // namespace
} // namespace vt::test
