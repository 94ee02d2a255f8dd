// An answer that reaches the PC in two bursts with a pause longer than t3.5 between them (a USB
// adapter's latency timer, a busy machine) — the whole stack: Session over SerialLink with the
// Modbus RTU line timing on, the test playing the device on a pseudo-terminal. The link reports
// the pause as the line going quiet; the adapter keeps the start of the answer it awaits and the
// CRC completes it in the first attempt. Bytes before a quiet that are not that answer's start
// are dropped as Modbus over Serial Line §2.5.1.1 says, so the rest alone is no answer.
#include "../../transports/pty_pair.h"
#include "model/session/adapter_factory.h"
#include "model/session/session.h"
#include "test_wait.h"
#include "transports/serial_link.h"

#include <QSignalSpy>
#include <QTimer>
#include <gtest/gtest.h>

namespace vt::test {
namespace {

// FC 3, register 0 ("Vers"), count 1, unit 1 — the first step of identifying module 1.
const QByteArray kRequest = QByteArray::fromHex("010300000001840a");
// Its answer, version 51.00 (raw 5100 = 0x13EC), in two bursts split after the byte count.
const QByteArray kStart = QByteArray::fromHex("010302");
const QByteArray kRest = QByteArray::fromHex("13ecb4f9");

class SessionSplitAnswer : public ::testing::Test
{
protected:
    void SetUp() override
    {
        ASSERT_TRUE(m_pty.ok()) << m_pty.error().toStdString();
        link::SerialSettings settings = link::SerialSettings::hcsDefault(m_pty.slavePath());
        ASSERT_TRUE(settings.frameEndBySilence); // the shipped default for Modbus RTU
        m_link = std::make_unique<link::SerialLink>(settings);
        model::SessionOptions options;
        options.baudRate = settings.baudRate;
        options.retries = 0; // a lost answer shows as a timeout, not a retry
        m_session = std::make_unique<model::Session>(
            m_link.get(), model::makeAdapter(dev::LinkProtocol::ModbusRtu, "dma-pn-v51"), options);
        m_link->open();
        ASSERT_TRUE(waitForState(*m_link, link::LinkState::Open));
        m_pty.startReading();
    }

    // Sends the identify step, answers it with `start`, then `rest` once the link has reported
    // the line quiet; returns the outcome.
    std::optional<model::Outcome> exchange(const QByteArray &start, const QByteArray &rest)
    {
        const auto plan = m_session->adapter().planIdentify(1);
        std::optional<model::Outcome> outcome;
        m_session->submit(plan.front(), model::Priority::User,
                          [&](const model::Outcome &o) { outcome = o; });
        EXPECT_TRUE(waitUntil([&] { return m_pty.received().size() >= kRequest.size(); }));
        EXPECT_EQ(m_pty.received(), kRequest);
        QSignalSpy quiet(m_link.get(), &link::Link::lineQuiet);
        EXPECT_TRUE(m_pty.write(start));
        EXPECT_TRUE(waitForCount(quiet, 1)); // the pause is longer than t3.5 (2.0 ms here)
        EXPECT_TRUE(m_pty.write(rest));
        EXPECT_TRUE(waitFor(outcome));
        return outcome;
    }

    PtyPair m_pty;
    std::unique_ptr<link::SerialLink> m_link;
    std::unique_ptr<model::Session> m_session;
};

TEST_F(SessionSplitAnswer, TheAwaitedAnswerSplitByAPauseCompletesInTheFirstAttempt)
{
    const auto outcome = exchange(kStart, kRest);
    ASSERT_TRUE(outcome);
    EXPECT_EQ(outcome->status, model::OutcomeStatus::Ok) << outcome->reason.toStdString();
    EXPECT_EQ(outcome->attempts, 1);
    EXPECT_EQ(outcome->reply.identity.versRaw, 5100);
    EXPECT_EQ(m_session->counters().timeouts, 0u);
}

TEST_F(SessionSplitAnswer, BytesBeforeAQuietThatAreNotTheAwaitedAnswerAreDropped)
{
    // Unit 2's header: not the start of the answer awaited from unit 1. After the quiet the rest
    // of unit 1's answer alone is no frame, so the attempt times out.
    const auto outcome = exchange(QByteArray::fromHex("020302"), kRest);
    ASSERT_TRUE(outcome);
    EXPECT_EQ(outcome->status, model::OutcomeStatus::Timeout);
    EXPECT_EQ(m_session->counters().timeouts, 1u);
}

} // namespace
} // namespace vt::test
