// What does min/max decimation (STYLE.md rule 10) cost against handing the plot a
// plain copy of the range? 5 channels × 100 000 rows (8.3 min at 200 Hz) in a wrapped ring,
// decimated to 1 000 buckets (a wide plot, one min/max pair per pixel) per channel.
#include "model/monitor/sample_store.h"

#include <benchmark/benchmark.h>
#include <cmath>

namespace {

using vt::model::SampleStore;

constexpr int kChannels = 5;
constexpr int kRows = 100'000;

const SampleStore &store()
{
    static const SampleStore s = [] {
        QList<vt::model::SampleChannel> channels;
        for (int c = 0; c < kChannels; ++c)
            channels.append({QStringLiteral("d1.%1").arg(7 + c),
                             QStringLiteral("channel %1").arg(c), QString()});
        SampleStore filled(channels, kRows);
        double values[kChannels] = {};
        for (int i = 0; i < kRows + kRows / 3; ++i) { // wrapped, like a store that ran a while
            const double t = i * 0.005;
            for (int c = 0; c < kChannels; ++c)
                values[c] = std::sin(t * (c + 1)) * 100.0;
            filled.append(t, values);
        }
        return filled;
    }();
    return s;
}

void BM_CopyRangeBaseline(benchmark::State &state)
{
    const SampleStore &s = store();
    QList<double> times, values;
    for (auto _ : state) {
        for (int c = 0; c < kChannels; ++c) {
            s.copyRange(c, s.firstTime(), s.lastTime(), times, values);
            benchmark::DoNotOptimize(values.data());
        }
    }
    state.SetItemsProcessed(state.iterations() * kChannels * kRows);
}
BENCHMARK(BM_CopyRangeBaseline);

void BM_Decimate(benchmark::State &state)
{
    const SampleStore &s = store();
    const auto buckets = static_cast<int>(state.range(0));
    QList<double> times, values;
    for (auto _ : state) {
        for (int c = 0; c < kChannels; ++c) {
            SampleStore::toPolyline(s.decimate(c, s.firstTime(), s.lastTime(), buckets), times,
                                    values);
            benchmark::DoNotOptimize(values.data());
        }
    }
    state.SetItemsProcessed(state.iterations() * kChannels * kRows);
}
BENCHMARK(BM_Decimate)->Arg(1000)->Arg(4000);

} // namespace
