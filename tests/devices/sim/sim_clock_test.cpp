// SimClock: fixed internal steps, exact microsecond time, chunking-independent
// ("deterministically in simulated time").
#include "sim/sim_clock.h"

#include <gtest/gtest.h>
#include <vector>

using namespace vt::dev::sim;

namespace {

struct Recorder : SimModel
{
    std::vector<std::int64_t> times;
    void step(const SimStep &s) override { times.push_back(s.timeUs); }
};

} // namespace

TEST(SimClock, StepsOnlyWholeStepsAndKeepsTheRemainder)
{
    SimClock clock(500);
    Recorder r;
    clock.attach(r);
    clock.advance(1200);
    EXPECT_EQ(r.times, (std::vector<std::int64_t>{500, 1000}));
    EXPECT_EQ(clock.nowUs(), 1200);
    EXPECT_EQ(clock.steppedUs(), 1000);
    clock.advance(300);
    EXPECT_EQ(r.times.back(), 1500);
    EXPECT_EQ(clock.stepsDone(), 3);
}

TEST(SimClock, ChunkingDoesNotChangeTheSteps)
{
    SimClock a(500), b(500);
    Recorder ra, rb;
    a.attach(ra);
    b.attach(rb);
    a.advance(1'000'000);
    for (int i = 0; i < 1000; ++i)
        b.advance(i % 2 ? 999 : 1001);
    EXPECT_EQ(ra.times, rb.times);
    EXPECT_EQ(ra.times.size(), 2000u);
}

TEST(SimClock, IgnoresNegativeTimeAndDetachedModels)
{
    SimClock clock;
    Recorder r;
    clock.attach(r);
    clock.attach(r); // twice is once
    clock.advance(-5000);
    clock.advanceTo(1000);
    EXPECT_EQ(r.times.size(), 2u);
    clock.detach(r);
    clock.advance(10'000);
    EXPECT_EQ(r.times.size(), 2u);
    clock.advanceTo(500); // backwards: ignored
    EXPECT_EQ(clock.nowUs(), 11'000);
}
