// DelayLine: the in-order timed FIFO behind SimLink's wire time and FaultLink's delay.
#include "qt_printers.h"
#include "test_wait.h"
#include "transports/delay_line.h"

#include <gtest/gtest.h>

namespace {

using namespace std::chrono_literals;
using vt::link::DelayLine;

TEST(DelayLine, DeliversInPushOrderEvenWhenLaterChunksAreDueEarlier)
{
    std::vector<QByteArray> got;
    DelayLine line([&](const QByteArray &b) { got.push_back(b); });
    const auto now = DelayLine::Clock::now();
    line.push("first", now + 40ms);
    const auto due = line.push("second", now + 5ms);
    EXPECT_GE(due, now + 40ms); // clamped behind "first"
    EXPECT_TRUE(got.empty());   // never delivered from push()
    ASSERT_TRUE(vt::test::waitUntil([&] { return got.size() == 2; }, vt::test::kWaitMs));
    EXPECT_EQ(got[0], QByteArray("first"));
    EXPECT_EQ(got[1], QByteArray("second"));
    EXPECT_GE(DelayLine::Clock::now(), now + 40ms);
}

TEST(DelayLine, ClearDropsPendingChunks)
{
    int delivered = 0;
    DelayLine line([&](const QByteArray &) { ++delivered; });
    line.push("x", DelayLine::Clock::now());
    line.push("y", DelayLine::Clock::now() + 10ms);
    line.clear();
    EXPECT_TRUE(line.isEmpty());
    line.push("z", DelayLine::Clock::now());
    ASSERT_TRUE(vt::test::waitUntil([&] { return delivered == 1; }, vt::test::kWaitMs));
    EXPECT_FALSE(vt::test::waitUntil([&] { return delivered > 1; }, 50));
}

TEST(DelayLine, AReceiverThatClearsStopsTheBatch)
{
    std::vector<QByteArray> got;
    DelayLine *self = nullptr;
    DelayLine line([&](const QByteArray &b) {
        got.push_back(b);
        self->clear(); // e.g. the session closes the link on the first answer
    });
    self = &line;
    const auto now = DelayLine::Clock::now();
    line.push("a", now);
    line.push("b", now);
    ASSERT_TRUE(vt::test::waitUntil([&] { return !got.empty(); }, vt::test::kWaitMs));
    EXPECT_FALSE(vt::test::waitUntil([&] { return got.size() > 1; }, 50));
    EXPECT_EQ(got.size(), 1u);
}

} // namespace
