// TelegramRecorder's request times: a link that reports when a frame went to the line (a serial
// link after its t3.5 wait) has the request stamped with that time; until then the request is
// held back, and goes in with its hand-over time when the link's report does not come first.
#include "model/session/adapter_factory.h"
#include "model/session/session.h"
#include "model/telegrams/telegram_log.h"
#include "model/telegrams/telegram_recorder.h"
#include "test_wait.h"

#include <chrono>
#include <gtest/gtest.h>
#include <vector>

namespace vt::test {
namespace {

qint64 steadyNs()
{
    using namespace std::chrono;
    return duration_cast<nanoseconds>(steady_clock::now().time_since_epoch()).count();
}

// Opens at once, records what is sent; the test says when a frame went to the line.
class WireLink : public link::Link
{
public:
    explicit WireLink(bool reports) : m_reports(reports) {}
    void open() override { setState(link::LinkState::Open); }
    void close() override { setState(link::LinkState::Closed); }
    void send(const QByteArray &bytes) override { sent.push_back(bytes); }
    QString description() const override { return QStringLiteral("wire test"); }
    bool reportsWireTime() const override { return m_reports; }

    void wentOut(qint64 ns) { emit frameOnWire(ns); }
    void breakDown()
    {
        setState(link::LinkState::Failed);
        emit failed(QStringLiteral("unplugged"));
    }

    std::vector<QByteArray> sent;

private:
    bool m_reports;
};

class TelegramRecorderTimes : public ::testing::Test
{
protected:
    void start(bool reports)
    {
        m_link = std::make_unique<WireLink>(reports);
        m_session = std::make_unique<model::Session>(
            m_link.get(), model::makeAdapter(dev::LinkProtocol::ModbusRtu, "dma-pn-v51"));
        m_recorder = std::make_unique<model::TelegramRecorder>(*m_session, m_log);
        m_link->open();
    }

    // Sends one frame that awaits no answer; the log's clock and the steady clock before and
    // after the hand-over.
    void sendOne()
    {
        m_handedFromLog = m_log.elapsedNs();
        m_handedFrom = steadyNs();
        std::optional<model::Outcome> done;
        m_session->submit(dev::access::Transaction::rawFrame(1, {0x01, 0x03, 0x00, 0x00}, false),
                          model::Priority::User, [&](const model::Outcome &o) { done = o; });
        ASSERT_TRUE(waitFor(done));
        ASSERT_EQ(m_link->sent.size(), 1u);
        m_handedToLog = m_log.elapsedNs();
        m_handedTo = steadyNs();
    }

    model::TelegramLog m_log;
    std::unique_ptr<WireLink> m_link;
    std::unique_ptr<model::Session> m_session;
    std::unique_ptr<model::TelegramRecorder> m_recorder;
    qint64 m_handedFromLog = 0, m_handedToLog = 0, m_handedFrom = 0, m_handedTo = 0;
};

TEST_F(TelegramRecorderTimes, ARequestIsStampedWhenTheLinkSaysItWentToTheLine)
{
    start(true);
    sendOne();
    EXPECT_EQ(m_log.size(), 0); // held until the link says
    spinFor(30);
    const qint64 onWire = m_handedTo + 10'000'000; // 10 ms after the hand-over, in the past now
    m_link->wentOut(m_handedFrom - 1'000'000);     // before the hand-over: an earlier frame's
    EXPECT_EQ(m_log.size(), 0);
    const qint64 logBefore = m_log.elapsedNs();
    const qint64 steadyBefore = steadyNs();
    m_link->wentOut(onWire);
    const qint64 steadyAfter = steadyNs();
    const qint64 logAfter = m_log.elapsedNs();
    ASSERT_EQ(m_log.size(), 1);
    const model::TelegramRecord &r = m_log.at(0);
    EXPECT_EQ(r.direction, dev::Direction::Request);
    EXPECT_EQ(r.link, QStringLiteral("wire test"));
    EXPECT_EQ(r.protocol, QStringLiteral("modbus-rtu"));
    EXPECT_EQ(r.bytes, m_link->sent.front());
    EXPECT_GE(r.monotonicNs, logBefore - (steadyAfter - onWire));
    EXPECT_LE(r.monotonicNs, logAfter - (steadyBefore - onWire));
    EXPECT_GE(r.monotonicNs, m_handedToLog + 5'000'000); // not the hand-over
}

TEST_F(TelegramRecorderTimes, WithoutTheLinksWordTheRequestGoesInAtItsHandOverTime)
{
    start(true);
    sendOne();
    spinFor(20);
    m_link->breakDown(); // the frame never went out
    ASSERT_EQ(m_log.size(), 1);
    EXPECT_GE(m_log.at(0).monotonicNs, m_handedFromLog);
    EXPECT_LE(m_log.at(0).monotonicNs, m_handedToLog);
}

TEST_F(TelegramRecorderTimes, ALinkThatSendsWithinTheHandOverIsStampedThen)
{
    start(false);
    sendOne();
    ASSERT_EQ(m_log.size(), 1);
    EXPECT_GE(m_log.at(0).monotonicNs, m_handedFromLog);
    EXPECT_LE(m_log.at(0).monotonicNs, m_handedToLog);
    m_link->wentOut(steadyNs()); // ignored: nothing is held
    EXPECT_EQ(m_log.size(), 1);
}

TEST_F(TelegramRecorderTimes, TheRecordersEndPutsInWhatItHeld)
{
    start(true);
    sendOne();
    m_recorder.reset();
    EXPECT_EQ(m_log.size(), 1);
}

} // namespace
} // namespace vt::test
