// The live monitor's redraw cost: MonitorPlot loads 5 channels × 100 000
// samples from a SampleStore and replots offscreen at a fixed size, with min/max decimation to
// about one pair per pixel against the same data handed to QCustomPlot whole (its own adaptive
// sampling on, as shipped, and off), in the same run. Results: docs/PERFORMANCE.md.
#include "widgets/monitor/monitor_plot.h"

#include <QApplication>
#include <benchmark/benchmark.h>
#include <cmath>
#include <memory>

namespace {

constexpr int kChannels = 5;
constexpr qsizetype kRows = 100'000;
constexpr double kRateHz = 200;

struct Scene
{
    std::unique_ptr<vt::model::SampleStore> store;
    std::unique_ptr<vt::ui::MonitorPlot> plot;
};

// A step response with noise on every channel: the decimation has real extremes to keep.
Scene &scene()
{
    static Scene s = [] {
        Scene made;
        QList<vt::model::SampleChannel> channels;
        const char *ids[kChannels] = {"d1.10", "d1.11", "d1.07", "d1.08", "d1.09"};
        const char *units[kChannels] = {"V", "V", "A", "A", "A"};
        for (int c = 0; c < kChannels; ++c)
            channels.append({QString::fromLatin1(ids[c]), QString::fromLatin1(ids[c]),
                             QString::fromLatin1(units[c])});
        made.store = std::make_unique<vt::model::SampleStore>(channels, kRows);
        quint32 noise = 12345;
        double values[kChannels];
        for (qsizetype i = 0; i < kRows; ++i) {
            const double t = static_cast<double>(i) / kRateHz;
            const double desired = (i / 2000) % 2 ? 5.0 : -5.0;
            for (int c = 0; c < kChannels; ++c) {
                noise = noise * 1664525u + 1013904223u;
                const double n = (static_cast<double>(noise >> 8) / 16777216.0 - 0.5) * 0.2;
                values[c] =
                    desired * (1.0 - std::exp(-static_cast<double>(i % 2000) / (50.0 + 20 * c))) +
                    n;
            }
            made.store->append(t, values);
        }
        made.plot = std::make_unique<vt::ui::MonitorPlot>();
        std::vector<vt::ui::PlotChannel> plotted;
        for (int c = 0; c < kChannels; ++c)
            plotted.push_back(
                {made.store.get(), c, channels[c].id, channels[c].name, channels[c].unit, 3});
        made.plot->setChannels(std::move(plotted));
        made.plot->resize(1000, 600);
        made.plot->show(); // the offscreen platform: a real paint buffer of that size
        QCoreApplication::processEvents();
        return made;
    }();
    return s;
}

void redraw(benchmark::State &state, bool decimate, bool adaptiveSampling, bool draw = true)
{
    Scene &s = scene();
    s.plot->setDecimation(decimate);
    for (int i = 0; i < s.plot->graphCount(); ++i)
        s.plot->graph(i)->setAdaptiveSampling(adaptiveSampling);
    const double t0 = s.store->firstTime(), t1 = s.store->lastTime();
    for (auto _ : state) {
        s.plot->loadRange(t0, t1);
        if (draw)
            s.plot->replot(QCustomPlot::rpImmediateRefresh);
    }
    state.counters["points"] = static_cast<double>(s.plot->pointCount());
    state.counters["width_px"] = s.plot->axisRect()->width();
}

void BM_RedrawDecimated(benchmark::State &state)
{
    redraw(state, true, true);
}
void BM_RedrawWholeAdaptiveSampling(benchmark::State &state)
{
    redraw(state, false, true);
}
void BM_RedrawWholeNoSampling(benchmark::State &state)
{
    redraw(state, false, false);
}
// The data half alone (store -> graphs, no painting), to show where the time goes.
void BM_LoadDecimated(benchmark::State &state)
{
    redraw(state, true, true, false);
}
void BM_LoadWhole(benchmark::State &state)
{
    redraw(state, false, true, false);
}

BENCHMARK(BM_RedrawDecimated)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RedrawWholeAdaptiveSampling)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RedrawWholeNoSampling)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadDecimated)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadWhole)->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    // The scene's widgets go before the QApplication.
    Scene &s = scene();
    s.plot.reset();
    s.store.reset();
    return 0;
}
