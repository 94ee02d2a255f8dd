// SimLink with a tiny echo ByteServer (the simulator is just
// another link; answers arrive asynchronously and, when asked, after serial wire time).
#include "qt_printers.h"
#include "test_wait.h"
#include "transports/sim_link.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <core/byte_server.h>
#include <gtest/gtest.h>
#include <memory>

namespace {

using namespace std::chrono_literals;
using vt::link::LinkState;
using vt::link::SimLink;
using vt::test::waitForCount;
using vt::test::waitForState;

class EchoServer : public vt::dev::ByteServer
{
public:
    void receive(std::span<const std::uint8_t> bytes) override
    {
        m_out.insert(m_out.end(), bytes.begin(), bytes.end());
        ++chunks;
    }
    std::vector<std::uint8_t> drain() override { return std::exchange(m_out, {}); }
    void say(std::string_view text) { m_out.insert(m_out.end(), text.begin(), text.end()); }

    int chunks = 0;

private:
    std::vector<std::uint8_t> m_out;
};

struct Fixture
{
    std::shared_ptr<EchoServer> server = std::make_shared<EchoServer>();
    SimLink link{server, QStringLiteral("echo")};
};

TEST(SimLink, EchoRoundTripIsDeliveredLaterNotInsideSend)
{
    Fixture f;
    EXPECT_EQ(f.link.description(), QStringLiteral("sim echo"));
    QSignalSpy received(&f.link, &SimLink::received);
    f.link.open();
    EXPECT_EQ(f.link.state(), LinkState::Opening);
    ASSERT_TRUE(waitForState(f.link, LinkState::Open));

    bool insideSend = false;
    bool deliveredInsideSend = false;
    QObject::connect(&f.link, &SimLink::received, [&] { deliveredInsideSend |= insideSend; });
    insideSend = true;
    f.link.send(QByteArrayLiteral("\x01\x03\x00\x00"));
    insideSend = false;
    EXPECT_EQ(f.server->chunks, 1); // the server has the request already...
    EXPECT_EQ(received.count(), 0); // ...but the answer comes from the event loop
    ASSERT_TRUE(waitForCount(received, 1));
    EXPECT_FALSE(deliveredInsideSend);
    EXPECT_EQ(received.first().value(0).toByteArray(), QByteArrayLiteral("\x01\x03\x00\x00"));
}

TEST(SimLink, WireTimeDelaysAnswersAndKeepsTheirOrder)
{
    Fixture f;
    // 9600 baud, 10 bits per character: 1.0417 ms per byte.
    f.link.setWireTiming(9600, 10);
    EXPECT_EQ(f.link.wireTime(48), std::chrono::nanoseconds(50'000'000));
    QSignalSpy received(&f.link, &SimLink::received);
    f.link.open();
    ASSERT_TRUE(waitForState(f.link, LinkState::Open));

    QElapsedTimer clock;
    std::vector<qint64> arrivals;
    QObject::connect(&f.link, &SimLink::received,
                     [&] { arrivals.push_back(clock.nsecsElapsed()); });
    clock.start();
    const QByteArray a(48, 'a'); // 50 ms out, 50 ms back: answer complete at 100 ms
    const QByteArray b(24, 'b'); // out 50..75 ms; back after a's answer: 100..125 ms
    f.link.send(a);
    f.link.send(b);
    ASSERT_TRUE(waitForCount(received, 2));
    EXPECT_EQ(received.at(0).value(0).toByteArray(), a);
    EXPECT_EQ(received.at(1).value(0).toByteArray(), b);
    ASSERT_EQ(arrivals.size(), 2u);
    EXPECT_GE(arrivals[0], 100'000'000);
    EXPECT_GE(arrivals[1], 125'000'000);
    EXPECT_LT(arrivals[1], 2'000'000'000); // generous: only guards against a hang
}

TEST(SimLink, UntimedLinkAnswersOnTheNextLoopTurn)
{
    Fixture f;
    QSignalSpy received(&f.link, &SimLink::received);
    f.link.open();
    ASSERT_TRUE(waitForState(f.link, LinkState::Open));
    for (int i = 0; i < 100; ++i)
        f.link.send(QByteArray(1, static_cast<char>(i)));
    ASSERT_TRUE(waitForCount(received, 100));
    for (int i = 0; i < 100; ++i)
        EXPECT_EQ(received.at(i).value(0).toByteArray(), QByteArray(1, static_cast<char>(i)));
}

TEST(SimLink, CloseDiscardsAnswersOnTheWire)
{
    Fixture f;
    f.link.setWireTiming(9600, 11);
    QSignalSpy received(&f.link, &SimLink::received);
    f.link.open();
    ASSERT_TRUE(waitForState(f.link, LinkState::Open));
    f.link.send(QByteArray(10, 'x')); // ~23 ms round trip
    f.link.close();
    EXPECT_EQ(f.link.state(), LinkState::Closed);
    EXPECT_FALSE(received.wait(100));         // four round trips: the answer would have come
    f.link.send(QByteArrayLiteral("closed")); // logged no-op
    EXPECT_EQ(f.server->chunks, 1);
}

TEST(SimLink, PumpDeliversUnsolicitedOutput)
{
    Fixture f;
    QSignalSpy received(&f.link, &SimLink::received);
    f.link.open();
    ASSERT_TRUE(waitForState(f.link, LinkState::Open));
    f.server->say("cyclic");
    f.link.pump();
    EXPECT_EQ(received.count(), 0);
    ASSERT_TRUE(waitForCount(received, 1));
    EXPECT_EQ(received.first().value(0).toByteArray(), QByteArrayLiteral("cyclic"));
}

TEST(SimLink, WithoutAServerFailsInsteadOfCrashing)
{
    SimLink link(nullptr, QStringLiteral("none"));
    QSignalSpy failed(&link, &SimLink::failed);
    link.open();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
}

} // namespace
