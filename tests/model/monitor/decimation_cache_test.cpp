// DecimationCache (issue #21, GUI latency): a live plot's min/max slices kept between redraws on
// a fixed grid of the time axis. What the cache returns must be what reading every row gives;
// following the newest samples it must read only the rows that arrived since the last redraw.
#include "model/monitor/decimation_cache.h"
#include "sample_store_checks.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <map>
#include <random>

using vt::model::DecimationCache;
using vt::model::MinMaxBucket;
using vt::model::SampleChannel;
using vt::model::SampleStore;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

QList<SampleChannel> channels(int n)
{
    return vt::test::storeChannels(n);
}

// Times and widths in these tests are binary fractions, so the division is exact and there is
// no doubt which slice a row is in.
std::vector<MinMaxBucket> everyRow(const SampleStore &s, int channel, double width, qint64 first,
                                   qint64 last)
{
    return vt::test::gridByEveryRow(s, channel, width, first, last);
}

} // namespace

// The grid slicing itself, sparse (a few rows per slice) and dense (whole blocks of 32 rows from
// their summaries), on a wrapped ring with ties, NaN runs and equal times; and stopping at the
// first row after the last slice asked for.
TEST(SampleStoreGrid, SlicesOnTheGridAreWhatEveryRowGives)
{
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> level(-2, 2);
    std::uniform_int_distribution<int> percent(0, 99);
    SampleStore s(channels(2), 20'003);
    double t = 0;
    for (int i = 0; i < 50'000; ++i) {
        t += (percent(rng) < 10 ? 0 : 1) / 1024.0;
        const double v = percent(rng) < 3 ? kNaN : level(rng);
        s.append(t, std::vector<double>{v, 2 * v});
    }
    for (const double width : {1.0 / 256, 1.0, 8.0, 64.0}) { // 4 to 65 536 rows a slice
        SCOPED_TRACE(testing::Message() << "width " << width);
        const auto first = static_cast<qint64>(std::floor(s.firstTime() / width));
        const auto last = static_cast<qint64>(std::floor(s.lastTime() / width));
        for (int channel : {0, 1}) {
            std::vector<MinMaxBucket> out;
            std::vector<qint64> indices;
            EXPECT_EQ(s.decimateOnGrid(channel, 0, width, last, out, indices), s.size());
            vt::test::expectSameBuckets(out, everyRow(s, channel, width, first, last));
            EXPECT_TRUE(std::is_sorted(indices.begin(), indices.end()));
        }
        if (last - first < 2)
            continue;
        // Stopping before the slices after `middle`: the returned row opens the next slice.
        const qint64 middle = (first + last) / 2;
        std::vector<MinMaxBucket> out;
        std::vector<qint64> indices;
        const qsizetype stop = s.decimateOnGrid(0, 0, width, middle, out, indices);
        ASSERT_LT(stop, s.size());
        EXPECT_GT(std::floor(s.timeAt(stop) / width), static_cast<double>(middle));
        EXPECT_LE(std::floor(s.timeAt(stop - 1) / width), static_cast<double>(middle));
        vt::test::expectSameBuckets(out, everyRow(s, 0, width, first, middle));
    }
}

// A plot that follows: 20 redraws a second while rows arrive, the ring wraps, values are missing
// now and then. Every redraw returns what reading every row gives for the window, and reads only
// the rows that arrived since the last one. The second channel has a few levels only, so a
// slice's newest rows often tie with its extremes of the redraw before (the earlier must win).
TEST(DecimationCache, FollowingTheNewestRowsReadsOnlyTheNewOnesAndMatchesEveryRow)
{
    std::mt19937 rng(11);
    std::normal_distribution<double> noise(0.0, 1.0);
    SampleStore s(channels(2), 40'000);
    DecimationCache cache;
    DecimationCache coarse;
    constexpr double kWindow = 10.0;
    constexpr int kBuckets = 640; // width 10/640 = 1/64 s
    qint64 rows = 0;
    for (int redraw = 0; redraw < 200; ++redraw) {
        const int arriving = 100 + static_cast<int>(rng() % 3000);
        for (int i = 0; i < arriving; ++i, ++rows) {
            const double v =
                rows % 997 == 0 ? kNaN : std::sin(0.001 * static_cast<double>(rows)) + noise(rng);
            s.append(static_cast<double>(rows) / 4096.0, std::vector<double>{v, std::round(v)});
        }
        const double t1 = s.lastTime();
        const double t0 = t1 - kWindow;
        const double width = kWindow / kBuckets;
        const auto first = static_cast<qint64>(std::floor(t0 / width));
        const auto last = static_cast<qint64>(std::floor(t1 / width));
        vt::test::expectSameBuckets(cache.slices(s, 0, t0, t1, kBuckets),
                                    everyRow(s, 0, width, first, last));
        vt::test::expectSameBuckets(coarse.slices(s, 1, t0, t1, kBuckets),
                                    everyRow(s, 1, width, first, last));
        if (redraw > 0) {
            EXPECT_FALSE(cache.lastRebuilt()) << redraw;
            EXPECT_EQ(cache.lastRowsRead(), arriving) << redraw;
            EXPECT_FALSE(coarse.lastRebuilt()) << redraw;
        }
    }
    EXPECT_GT(s.droppedCount(), 0u); // the ring wrapped while following
}

// What makes the cache start again from the store: a new width (zoom, resize), a range that
// begins before what it holds (panning back), a clear(), rows overwritten before they were read
// (a paused view), another channel. After each, the answer is still what every row gives.
TEST(DecimationCache, ZoomPanClearAndLostRowsStartAgainAndStayExact)
{
    SampleStore s(channels(2), 5'000);
    DecimationCache cache;
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> level(-50, 50);
    qint64 rows = 0;
    const auto add = [&](int n) {
        for (int i = 0; i < n; ++i, ++rows) {
            const double v = level(rng);
            s.append(static_cast<double>(rows) / 512.0, std::vector<double>{v, -v});
        }
    };
    const auto check = [&](int channel, double t0, double t1, int buckets, bool rebuilt) {
        const std::vector<MinMaxBucket> got = cache.slices(s, channel, t0, t1, buckets);
        EXPECT_EQ(cache.lastRebuilt(), rebuilt);
        const double width = (t1 - t0) / buckets;
        vt::test::expectSameBuckets(got, everyRow(s, channel, width,
                                                  static_cast<qint64>(std::floor(t0 / width)),
                                                  static_cast<qint64>(std::floor(t1 / width))));
    };
    add(3000); // 0 .. 5.86 s
    check(0, 1.0, 5.0, 128, true);
    check(0, 1.0, 5.0, 128, false); // nothing new: nothing read
    EXPECT_EQ(cache.lastRowsRead(), 0);
    check(0, 2.0, 6.0, 128, false); // moved right, same width
    check(0, 0.5, 4.5, 128, true);  // panned back before what it held
    check(0, 0.5, 4.5, 256, true);  // zoomed: another width
    check(1, 0.5, 4.5, 256, true);  // another channel
    add(8000);                      // the rows it had not read yet were overwritten
    check(1, s.firstTime() + 1, s.lastTime(), 256, true);
    add(100);
    check(1, s.firstTime() + 1, s.lastTime(), 256, false);
    s.clear();
    add(1000);
    check(1, 0.25, 1.75, 256, true);                   // cleared: row numbers start again
    EXPECT_TRUE(cache.slices(s, 2, 0, 1, 10).empty()); // no such channel
    EXPECT_TRUE(cache.slices(s, 0, 1, 1, 10).empty()); // no range
    EXPECT_TRUE(cache.slices(s, 0, 0, 1, 0).empty());  // no buckets
}

// A view that does not follow (paused on an older range) while rows keep arriving: the cache
// reads up to the range's last slice and no further, so it does not grow with the recording.
TEST(DecimationCache, APausedViewDoesNotReadOrKeepRowsBeyondItsRange)
{
    SampleStore s(channels(1), 100'000);
    DecimationCache cache;
    qint64 rows = 0;
    const auto add = [&](int n) {
        for (int i = 0; i < n; ++i, ++rows)
            s.append(static_cast<double>(rows) / 1024.0,
                     std::vector<double>{static_cast<double>(rows % 7)});
    };
    add(10'000); // 0 .. 9.8 s
    const std::vector<MinMaxBucket> first = cache.slices(s, 0, 2.0, 4.0, 64);
    EXPECT_EQ(first.size(), 65u); // the grid's slices 64 .. 128 (the last holds t = 4.0 only)
    add(50'000);
    const std::vector<MinMaxBucket> again = cache.slices(s, 0, 2.0, 4.0, 64);
    EXPECT_FALSE(cache.lastRebuilt());
    EXPECT_EQ(cache.lastRowsRead(), 0);
    vt::test::expectSameBuckets(again, first);
}
