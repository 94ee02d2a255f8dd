// FaultLink: seeded, reproducible fault injection. Most tests
// drive a synchronous RecordingLink so every frame's fate can be checked; one runs over SimLink.
#include "fault_test_links.h"
#include "qt_printers.h"
#include "test_wait.h"
#include "transports/fault_link.h"
#include "transports/sim_link.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <core/byte_server.h>
#include <gtest/gtest.h>
#include <set>

namespace {

using vt::link::FaultCounters;
using vt::link::FaultKind;
using vt::link::FaultLink;
using vt::link::FaultSpec;
using vt::link::LinkState;
using vt::test::RecordingLink;
using vt::test::waitForCount;

FaultSpec spec(const char16_t *text)
{
    auto parsed = vt::link::parseFaultSpec(text);
    EXPECT_TRUE(parsed) << parsed.error().text().toStdString();
    return parsed.valueOr(FaultSpec{});
}

// A distinct 8-byte frame per index, so drops and corruptions can be told apart.
QByteArray frame(int index)
{
    QByteArray f(8, '\0');
    for (int i = 0; i < 4; ++i)
        f[i] = static_cast<char>((index >> (8 * i)) & 0xFF);
    f[4] = 'V';
    f[5] = 'T';
    return f;
}

struct Rig
{
    explicit Rig(const FaultSpec &s)
    {
        auto inner = std::make_unique<RecordingLink>();
        fake = inner.get();
        link = std::make_unique<FaultLink>(std::move(inner), s);
        link->open();
    }
    RecordingLink *fake = nullptr;
    std::unique_ptr<FaultLink> link;
};

TEST(FaultLink, SameSeedSamePatternOtherSeedOtherPattern)
{
    auto run = [](const char16_t *text) {
        Rig rig(spec(text));
        for (int i = 0; i < 1000; ++i)
            rig.link->send(frame(i));
        return rig.fake->sent;
    };
    const auto a = run(u"drop=0.1,corrupt=0.1,seed=42");
    const auto b = run(u"drop=0.1,corrupt=0.1,seed=42");
    const auto c = run(u"drop=0.1,corrupt=0.1,seed=43");
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

TEST(FaultLink, DirectionsDrawIndependentlyOfInterleaving)
{
    // The tx pattern must not depend on how many rx frames came in between.
    auto txPattern = [](int rxPerTx) {
        Rig rig(spec(u"drop=0.3,seed=9"));
        for (int i = 0; i < 200; ++i) {
            rig.link->send(frame(i));
            for (int k = 0; k < rxPerTx; ++k)
                rig.fake->inject(frame(1000 + k));
        }
        return rig.fake->sent;
    };
    EXPECT_EQ(txPattern(0), txPattern(3));
}

TEST(FaultLink, DropAndCorruptRatesOverTenThousandFrames)
{
    constexpr int kFrames = 10'000;
    Rig rig(spec(u"drop=0.02,corrupt=0.005,seed=7"));
    std::set<quint64> dropped;
    std::set<quint64> corruptedEvents;
    QObject::connect(rig.link.get(), &FaultLink::faultInjected,
                     [&](FaultKind kind, vt::link::FaultDirection, quint64 index) {
                         (kind == FaultKind::Drop ? dropped : corruptedEvents).insert(index);
                     });
    for (int i = 0; i < kFrames; ++i)
        rig.link->send(frame(i));

    const FaultCounters &n = rig.link->counters();
    EXPECT_EQ(n.txFrames, static_cast<quint64>(kFrames));
    EXPECT_EQ(n.txDropped, dropped.size());
    EXPECT_EQ(n.txCorrupted, corruptedEvents.size());
    ASSERT_EQ(rig.fake->sent.size(), kFrames - n.txDropped);

    // Binomial: 200 ± 14 expected drops, 49 ± 7 corruptions among the survivors; ±5 sigma.
    EXPECT_NEAR(static_cast<double>(n.txDropped), 200.0, 70.0);
    EXPECT_NEAR(static_cast<double>(n.txCorrupted), 49.0, 35.0);

    // The survivors are the originals minus the dropped ones, in order; exactly the reported
    // frames differ, each in exactly one byte.
    std::size_t next = 0;
    for (int i = 0; i < kFrames; ++i) {
        const auto index = static_cast<quint64>(i);
        if (dropped.count(index))
            continue;
        const QByteArray &sent = rig.fake->sent.at(next++);
        const QByteArray original = frame(i);
        ASSERT_EQ(sent.size(), original.size());
        int diff = 0;
        for (qsizetype k = 0; k < sent.size(); ++k)
            diff += sent[k] != original[k] ? 1 : 0;
        EXPECT_EQ(diff, corruptedEvents.count(index) ? 1 : 0) << "frame " << i;
    }
    EXPECT_EQ(n.rxFrames, 0u);
}

TEST(FaultLink, ReceiveDirectionOnly)
{
    Rig rig(spec(u"rx.drop=0.5,seed=3"));
    QSignalSpy received(rig.link.get(), &FaultLink::received);
    for (int i = 0; i < 1000; ++i) {
        rig.link->send(frame(i));
        rig.fake->inject(frame(i));
    }
    EXPECT_EQ(rig.fake->sent.size(), 1000u); // tx untouched
    const FaultCounters &n = rig.link->counters();
    EXPECT_EQ(static_cast<quint64>(received.count()), 1000 - n.rxDropped);
    EXPECT_NEAR(static_cast<double>(n.rxDropped), 500.0, 80.0);
    EXPECT_EQ(n.txDropped, 0u);
}

TEST(FaultLink, CutAfterNFramesFailsOnceAndReopenWorks)
{
    Rig rig(spec(u"cut=5"));
    QSignalSpy failed(rig.link.get(), &FaultLink::failed);
    QSignalSpy injected(rig.link.get(), &FaultLink::faultInjected);
    rig.link->send(frame(0));
    rig.fake->inject(frame(1));
    rig.link->send(frame(2));
    rig.link->send(frame(3));
    rig.fake->inject(frame(4));
    EXPECT_EQ(failed.count(), 0);
    rig.link->send(frame(5)); // frame index 5: the cut
    ASSERT_EQ(failed.count(), 1);
    EXPECT_EQ(rig.link->state(), LinkState::Failed);
    EXPECT_EQ(rig.fake->state(), LinkState::Closed);
    EXPECT_TRUE(rig.link->counters().cut);
    EXPECT_EQ(rig.fake->sent.size(), 3u);
    ASSERT_EQ(injected.count(), 1);
    EXPECT_EQ(injected.first().value(0).value<FaultKind>(), FaultKind::Cut);
    EXPECT_EQ(injected.first().value(2).toULongLong(), 5u);

    rig.link->send(frame(6)); // failed: logged no-op
    EXPECT_EQ(rig.fake->sent.size(), 3u);

    rig.link->open();
    EXPECT_EQ(rig.link->state(), LinkState::Open);
    for (int i = 0; i < 20; ++i)
        rig.link->send(frame(i));
    EXPECT_EQ(rig.fake->sent.size(), 23u); // the cut happens once
    EXPECT_EQ(failed.count(), 1);
}

TEST(FaultLink, DelayHoldsFramesBackInOrder)
{
    Rig rig(spec(u"rx.delay=30"));
    QSignalSpy received(rig.link.get(), &FaultLink::received);
    QElapsedTimer clock;
    clock.start();
    rig.fake->inject(frame(1));
    rig.fake->inject(frame(2));
    EXPECT_EQ(received.count(), 0);
    ASSERT_TRUE(waitForCount(received, 2));
    EXPECT_GE(clock.elapsed(), 30);
    EXPECT_EQ(received.at(0).value(0).toByteArray(), frame(1));
    EXPECT_EQ(received.at(1).value(0).toByteArray(), frame(2));
    EXPECT_EQ(rig.link->counters().rxDelayed, 2u);
    rig.link->send(frame(3)); // tx not delayed
    EXPECT_EQ(rig.fake->sent.size(), 1u);
}

TEST(FaultLink, MirrorsTheInnerLinksFailure)
{
    Rig rig(FaultSpec{});
    QSignalSpy failed(rig.link.get(), &FaultLink::failed);
    rig.fake->breakDown(QStringLiteral("cable pulled"));
    ASSERT_EQ(failed.count(), 1);
    EXPECT_EQ(failed.first().value(0).toString(), QStringLiteral("cable pulled"));
    EXPECT_EQ(rig.link->state(), LinkState::Failed);
}

TEST(FaultLink, DescriptionNamesInnerLinkAndSpec)
{
    Rig rig(spec(u"drop=0.02,seed=7"));
    EXPECT_EQ(rig.link->description(), QStringLiteral("fake [fault drop=0.02,seed=7]"));
}

class Echo : public vt::dev::ByteServer
{
public:
    void receive(std::span<const std::uint8_t> bytes) override
    {
        m_out.insert(m_out.end(), bytes.begin(), bytes.end());
    }
    std::vector<std::uint8_t> drain() override { return std::exchange(m_out, {}); }

private:
    std::vector<std::uint8_t> m_out;
};

TEST(FaultLink, OverASimLinkEndToEnd)
{
    auto sim =
        std::make_unique<vt::link::SimLink>(std::make_shared<Echo>(), QStringLiteral("echo"));
    FaultLink link(std::move(sim), spec(u"rx.corrupt=1,seed=5"));
    QSignalSpy received(&link, &FaultLink::received);
    link.open();
    ASSERT_TRUE(vt::test::waitForState(link, LinkState::Open));
    link.send(QByteArrayLiteral("hello"));
    ASSERT_TRUE(waitForCount(received, 1));
    const QByteArray got = received.first().value(0).toByteArray();
    ASSERT_EQ(got.size(), 5);
    EXPECT_NE(got, QByteArrayLiteral("hello")); // corrupt=1: always one byte changed
    EXPECT_EQ(link.counters().rxCorrupted, 1u);
}

} // namespace
