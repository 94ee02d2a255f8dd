// A session destroyed with requests pending completes every one of them (session.h): queued,
// on the wire and already decided, each exactly once, inside the destructor, while whoever holds
// the session is still whole; objects that die before the session guard their completions.
#include "model/monitor/monitor_scheduler.h"
#include "sim_rig.h"

#include <QSignalSpy>
#include <string>
#include <vector>

namespace vt::test {
namespace {

using model::Outcome;
using model::OutcomeStatus;
using model::Priority;

// A node that never answers: the first request stays on the wire until the rig goes.
std::unique_ptr<SimRig> silentNode()
{
    link::FaultSpec silent;
    silent.rx.drop = 1.0;
    model::SessionOptions options;
    options.turnaround = std::chrono::milliseconds(60'000);
    return openSim({"dma-pn-v51", 1, {}, silent, options});
}

// Reads every readable row of the rig's module into `result`; true once a request is on the wire.
bool startReadingEverything(SimRig &rig, std::optional<model::ReadResult> &result)
{
    const auto rows = model::readableRows(rig.dictionary(), rig.simModule().version(), "3");
    rig.access().read(rig.address(), rows, Priority::User,
                      [&result](const model::ReadResult &r) { result = r; });
    return waitUntil([&] { return rig.session().isBusy(); });
}

struct Ended
{
    std::string name;
    Outcome outcome;
};

TEST(SessionEnd, EveryPendingRequestCompletesCancelledInOrder)
{
    auto rig = silentNode();
    ASSERT_TRUE(rig);
    model::Session &session = rig->session();
    const auto identify = session.adapter().planIdentify(rig->address()).front();
    std::vector<Ended> ended;
    auto record = [&ended](std::string name) {
        return [&ended, name = std::move(name)](const Outcome &o) { ended.push_back({name, o}); };
    };
    session.submit(identify, Priority::User, record("wire"));
    session.submit(identify, Priority::Monitor, record("monitor"));
    session.submit(identify, Priority::User, record("user"));
    const auto decided = session.submit(identify, Priority::User, record("decided"));
    ASSERT_TRUE(waitUntil([&] { return session.isBusy(); }));
    session.cancel(decided); // decided now, delivered from the event loop: none turns here
    ASSERT_TRUE(ended.empty());

    rig->connection.reset();

    ASSERT_EQ(ended.size(), 4u);
    EXPECT_EQ(ended[0].name, "decided");
    EXPECT_EQ(ended[1].name, "wire");
    EXPECT_EQ(ended[2].name, "user");
    EXPECT_EQ(ended[3].name, "monitor");
    for (const Ended &e : ended)
        EXPECT_EQ(e.outcome.status, OutcomeStatus::Cancelled) << e.name;
    EXPECT_TRUE(ended[1].outcome.sent);
    EXPECT_EQ(ended[1].outcome.attempts, 1);
    EXPECT_FALSE(ended[2].outcome.sent);
    EXPECT_FALSE(ended[2].outcome.reason.isEmpty());
}

TEST(SessionEnd, WhatACompletionSubmitsWhileTheSessionEndsIsCancelledToo)
{
    auto rig = silentNode();
    ASSERT_TRUE(rig);
    model::Session &session = rig->session();
    const auto identify = session.adapter().planIdentify(rig->address()).front();
    int retried = 0;
    std::optional<OutcomeStatus> again;
    session.submit(identify, Priority::User, [&](const Outcome &) {
        ++retried;
        session.submit(identify, Priority::User, [&](const Outcome &o) { again = o.status; });
    });
    ASSERT_TRUE(waitUntil([&] { return session.isBusy(); }));
    rig->connection.reset();
    EXPECT_EQ(retried, 1);
    EXPECT_EQ(again, OutcomeStatus::Cancelled);
}

// The documented contract: completions run inside ~Session(); an owner that holds the session
// destroys it before what its completions use, so they see the owner whole.
struct Owner
{
    std::vector<OutcomeStatus> seen; // destroyed after the rig (declared before it)
    std::unique_ptr<SimRig> rig;
    ~Owner() { rig.reset(); }
};

TEST(SessionEnd, CompletionsRunWhileTheOwnerHoldingTheSessionIsWhole)
{
    auto owner = std::make_unique<Owner>();
    owner->rig = silentNode();
    ASSERT_TRUE(owner->rig);
    model::Session &session = owner->rig->session();
    const auto identify = session.adapter().planIdentify(owner->rig->address()).front();
    std::vector<OutcomeStatus> copied;
    for (int i = 0; i < 3; ++i) {
        session.submit(identify, Priority::User, [o = owner.get(), &copied](const Outcome &x) {
            o->seen.push_back(x.status); // touches the owner: must still be whole
            copied = o->seen;
        });
    }
    ASSERT_TRUE(waitUntil([&] { return session.isBusy(); }));
    owner.reset();
    EXPECT_EQ(copied, std::vector<OutcomeStatus>(3, OutcomeStatus::Cancelled));
}

TEST(SessionEnd, AReadPendingWhenTheConnectionGoesEndsCancelledNotFailed)
{
    auto rig = silentNode();
    ASSERT_TRUE(rig);
    std::optional<model::ReadResult> result;
    ASSERT_TRUE(startReadingEverything(*rig, result));
    rig->connection.reset();
    ASSERT_TRUE(result);
    EXPECT_TRUE(result->cancelled);
    EXPECT_TRUE(result->failures.empty());
    EXPECT_TRUE(result->values.empty());
}

TEST(SessionEnd, CompletionsDecidedByALostLinkAreDeliveredWhenTheSessionGoesAtOnce)
{
    // The GUI closes the connection and destroys it in one go: the link loss decides every
    // request, the destructor delivers what the event loop had not yet.
    auto rig = silentNode();
    ASSERT_TRUE(rig);
    std::optional<model::ReadResult> result;
    ASSERT_TRUE(startReadingEverything(*rig, result));
    rig->connection->close();
    EXPECT_FALSE(result);
    rig->connection.reset();
    ASSERT_TRUE(result);
    EXPECT_FALSE(result->complete());
    ASSERT_FALSE(result->failures.empty());
    EXPECT_EQ(result->failures.front().outcome.status, OutcomeStatus::LinkLost);
}

TEST(SessionEnd, AMonitorSchedulerMayOutliveTheConnectionOrGoBeforeIt)
{
    for (const bool schedulerFirst : {false, true}) {
        SCOPED_TRACE(schedulerFirst ? "scheduler first" : "connection first");
        auto rig = openSim("dma-pn-v51");
        ASSERT_TRUE(rig);
        const int address = rig->address();
        auto scheduler = std::make_unique<model::MonitorScheduler>(rig->access());
        QSignalSpy sampled(scheduler.get(), &model::MonitorScheduler::sampled);
        QSignalSpy failed(scheduler.get(), &model::MonitorScheduler::pollFailed);
        const auto rows = model::defaultMonitorRows(rig->dictionary(), "3");
        ASSERT_FALSE(rows.empty());
        scheduler->setModule(address, rows, 0); // back to back: a poll is always out
        scheduler->start();
        ASSERT_TRUE(waitForCount(sampled, 3));
        // Ends the one or the other at a moment a poll is on the wire (checked from the loop:
        // back to back, the session is idle only between an answer and the next poll).
        qsizetype before = 0;
        bool ended = false;
        ASSERT_TRUE(waitUntil([&] {
            if (ended)
                return true;
            if (!rig->session().isBusy())
                return false;
            ended = true;
            before = sampled.count();
            if (schedulerFirst)
                scheduler.reset(); // its poll on the wire completes later, guarded
            else
                rig.reset(); // the scheduler's poll completes cancelled; it polls no more
            return true;
        }));
        if (schedulerFirst) {
            ASSERT_TRUE(waitUntil([&] { return !rig->session().isBusy(); }));
            rig.reset();
        } else {
            EXPECT_EQ(sampled.count(), before);
            EXPECT_EQ(failed.count(), 0);
            EXPECT_EQ(scheduler->failed(address), 0u);
            scheduler.reset();
        }
    }
}

} // namespace
} // namespace vt::test
