// What does min/max decimation (STYLE.md rule 10) cost against handing the plot a
// plain copy of the range? 5 channels × 100 000 rows (8.3 min at 200 Hz) in a wrapped ring,
// decimated to 1 000 buckets (a wide plot, one min/max pair per pixel) per channel. Each
// decimation is a redraw from scratch, as after a zoom: a fresh DecimationCache over
// SampleStore::decimateOnGrid (a live plot that follows the samples reads only the new rows).
#include "model/monitor/decimation_cache.h"
#include "model/monitor/sample_store.h"

#include <benchmark/benchmark.h>
#include <cmath>

namespace {

using vt::model::DecimationCache;
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
            SampleStore::toPolyline(
                DecimationCache().slices(s, c, s.firstTime(), s.lastTime(), buckets), times,
                values);
            benchmark::DoNotOptimize(values.data());
        }
    }
    state.SetItemsProcessed(state.iterations() * kChannels * kRows);
}
BENCHMARK(BM_Decimate)->Arg(1000)->Arg(4000)->Arg(200)->Arg(100);

// The dense case the block summaries are for: a whole hour at 200 Hz (the default ring, 720 000
// rows, wrapped) in a 1000-pixel plot, 720 rows per slice; noisy values, so the extremes move.
void BM_DecimateHour(benchmark::State &state)
{
    static const SampleStore s = [] {
        QList<vt::model::SampleChannel> channels;
        for (int c = 0; c < kChannels; ++c)
            channels.append({QStringLiteral("d1.%1").arg(7 + c),
                             QStringLiteral("channel %1").arg(c), QString()});
        SampleStore filled(channels);
        quint32 noise = 12345;
        double values[kChannels] = {};
        for (qsizetype i = 0; i < filled.capacity() + 1000; ++i) {
            const double t = static_cast<double>(i) * 0.005;
            for (int c = 0; c < kChannels; ++c) {
                noise = noise * 1664525u + 1013904223u;
                values[c] = std::sin(t * (c + 1)) * 100.0 + static_cast<double>(noise >> 24);
            }
            filled.append(t, values);
        }
        return filled;
    }();
    QList<double> times, values;
    for (auto _ : state) {
        for (int c = 0; c < kChannels; ++c) {
            SampleStore::toPolyline(
                DecimationCache().slices(s, c, s.firstTime(), s.lastTime(), 1000), times, values);
            benchmark::DoNotOptimize(values.data());
        }
    }
    state.SetItemsProcessed(state.iterations() * kChannels * s.size());
}
BENCHMARK(BM_DecimateHour)->Unit(benchmark::kMicrosecond);

} // namespace
