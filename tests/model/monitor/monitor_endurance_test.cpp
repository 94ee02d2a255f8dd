// Endurance (issue #21): one hour of monitoring at 200 Hz on three modules, on the simulated
// clock so it runs in seconds. Every 5 ms of simulated time each module of a simulated
// three-module DMA-2 node is read for the monitor's default channels (the block d1.07..d1.11 the
// poll asks for, converted as the adapter converts registers); each answer becomes the
// scheduler's sample and goes through recordSamples() into the module's SampleStore, as in the
// monitor. (The wire path of a poll is the session tests' subject; 2.2 million exchanges through
// it would not run in seconds.) Checked: no sample lost or duplicated (every row's time is its
// poll's, every value the one answered), and the stores' memory is flat once the rings are full.
#include "access/hcs_rows.h"
#include "dict/cooking.h"
#include "model/monitor/monitor_recording.h"
#include "sim/hcs_module.h"
#include "sim/hcs_node.h"
#include "sim/sim_device.h"
#include "sim_rig.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vt::test {
namespace {

constexpr std::size_t kModules = 3;
constexpr std::int64_t kPeriodUs = 5'000;   // 200 Hz
constexpr qsizetype kHourRows = 3600 * 200; // the stores' default capacity
constexpr qsizetype kAfterRows = 60 * 200;  // one more minute, once the rings are full

// FNV-1a over the float bit patterns: the values answered against the values stored.
struct Digest
{
    std::uint64_t h = 14695981039346656037ull;
    void add(float v)
    {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &v, sizeof bits);
        for (int i = 0; i < 4; ++i) {
            h ^= (bits >> (8 * i)) & 0xffu;
            h *= 1099511628211ull;
        }
    }
};

TEST(MonitorEndurance, AnHourAt200HzOnThreeModulesLosesNoSampleAndStaysFlat)
{
    // The scheduler whose `sampled` signal the recording listens to (not started: the simulated
    // clock below polls instead of its timers).
    SimSetup setup;
    setup.family = "dma-pn-v51";
    setup.modules = kModules;
    auto rig = openSim(setup);
    ASSERT_TRUE(rig);
    model::MonitorScheduler scheduler(rig->access());

    const dev::Dictionary &dictionary = rig->dictionary();
    // One integration step per poll: the plant moves, and an hour costs seconds.
    dev::sim::SimClock clock(kPeriodUs);
    dev::sim::SimDeviceSpec spec;
    spec.family = "dma-pn-v51";
    spec.modules = kModules;
    auto device = dev::sim::SimDevice::build(clock, dictionaries(), spec);
    ASSERT_TRUE(device.ok());
    dev::sim::SimDevice &sim = *device.value();

    const auto rows = model::defaultMonitorRows(dictionary, "3");
    ASSERT_FALSE(rows.empty());
    std::vector<std::unique_ptr<model::SampleStore>> stores;
    std::vector<Digest> answered(kModules);
    std::vector<int> addresses;
    for (std::size_t m = 0; m < kModules; ++m) {
        addresses.push_back(sim.moduleAddress(m));
        stores.push_back(std::make_unique<model::SampleStore>(
            model::monitorChannels(rows, dev::Language::English), kHourRows));
        model::recordSamples(scheduler, addresses.back(), *stores.back());
    }
    // One block of consecutive IDs, as the poll asks for it (d1.07..d1.11).
    for (const dev::ParamMeta *row : rows)
        ASSERT_TRUE(row->id) << row->name;
    const auto [lowest, highest] = std::minmax_element(
        rows.begin(), rows.end(), [](const auto *a, const auto *b) { return *a->id < *b->id; });
    const auto firstId = static_cast<std::uint16_t>(*(*lowest)->id);
    const auto idCount = static_cast<std::uint16_t>(*(*highest)->id - *(*lowest)->id + 1);
    const qint64 footprint = stores.front()->memoryBytes();

    qsizetype polled = 0;
    auto pollAll = [&](qsizetype polls, bool digest) {
        for (qsizetype k = 0; k < polls; ++k, ++polled) {
            clock.advanceTo(static_cast<std::int64_t>(polled) * kPeriodUs);
            for (std::size_t m = 0; m < kModules; ++m) {
                const auto words = sim.node()->module(m).read(firstId, idCount);
                if (!words.ok() || words.values.size() != idCount)
                    FAIL() << "poll " << polled << " of module " << addresses[m] << " failed";
                std::vector<dev::RawValue> values;
                for (std::size_t c = 0; c < rows.size(); ++c)
                    values.emplace_back(dev::access::registerToRaw(
                        *rows[c], words.values[static_cast<std::size_t>(*rows[c]->id - firstId)]));
                model::MonitorSample sample;
                sample.module = addresses[m];
                sample.seconds = static_cast<double>(polled * kPeriodUs) * 1e-6;
                sample.rows = rows;
                sample.values = std::move(values);
                if (digest) {
                    for (std::size_t c = 0; c < rows.size(); ++c)
                        answered[m].add(static_cast<float>(
                            dev::toDisplay(*rows[c], dev::rawNumber(sample.values[c]))));
                }
                emit scheduler.sampled(sample);
            }
        }
    };

    // The first hour fills the rings exactly.
    pollAll(kHourRows, true);
    for (std::size_t m = 0; m < kModules; ++m) {
        SCOPED_TRACE(m);
        const model::SampleStore &store = *stores[m];
        ASSERT_EQ(store.size(), kHourRows);
        EXPECT_EQ(store.droppedCount(), 0u);
        EXPECT_EQ(store.memoryBytes(), footprint);
        Digest stored;
        for (qsizetype i = 0; i < store.size(); ++i) {
            // Row i is poll i: nothing lost (a gap), nothing twice (a repeat).
            ASSERT_EQ(store.timeAt(i), static_cast<double>(i * kPeriodUs) * 1e-6) << i;
            for (int c = 0; c < store.channelCount(); ++c) {
                const double v = store.valueAt(c, i);
                ASSERT_TRUE(std::isfinite(v)) << "row " << i << " channel " << c;
                stored.add(static_cast<float>(v));
            }
        }
        EXPECT_EQ(stored.h, answered[m].h) << "the stored values are the answered ones";
    }

    // Past the hour the rings turn over: the oldest rows go, one for each new one, and the
    // memory stays what it was.
    pollAll(kAfterRows, false);
    for (std::size_t m = 0; m < kModules; ++m) {
        SCOPED_TRACE(m);
        const model::SampleStore &store = *stores[m];
        EXPECT_EQ(store.size(), kHourRows);
        EXPECT_EQ(store.capacity(), kHourRows);
        EXPECT_EQ(store.droppedCount(), static_cast<quint64>(kAfterRows));
        EXPECT_EQ(store.memoryBytes(), footprint);
        EXPECT_EQ(store.firstTime(), static_cast<double>(kAfterRows * kPeriodUs) * 1e-6);
        EXPECT_EQ(store.lastTime(),
                  static_cast<double>((kHourRows + kAfterRows - 1) * kPeriodUs) * 1e-6);
    }
}

} // namespace
} // namespace vt::test
