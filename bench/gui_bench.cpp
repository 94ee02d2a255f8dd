// The GUI under load (issue #21), two figures, each printed as `RESULT name=value`
// (docs/PERFORMANCE.md "GUI responsiveness and redraw (#21)"):
//   gui_event_latency_p99_ms: the monitor view (offscreen, visible, following) polls three
//     modules of the built-in simulator (DMA-2 PROFINET V51 node) as fast as the link allows;
//     a 10 ms GUI timer is re-armed on every timeout and its lateness (fire − due) recorded for
//     the run; the 99th percentile (goal ≤ 16 ms, one frame at 60 Hz).
//   redraw_720k_ms: one MonitorPlot redraw (load the range + replot at 1000 × 600) of 5 channels
//     × 720 000 samples (1 h at 200 Hz) in view, with the plot's min/max decimation, against the
//     same data handed to QCustomPlot whole (its adaptive sampling off: no decimation at all),
//     and the ratio; medians of several runs, wall time.
// Not a Google Benchmark: one figure each, like session_bench.
//   vt_bench_gui [--seconds S]   (latency run length, default 20)
#include "dict/dictionary_loader.h"
#include "model/monitor/monitor_session.h"
#include "model/session/connection.h"
#include "widgets/monitor/monitor_plot.h"
#include "widgets/monitor/monitor_view.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

namespace {

using namespace vt;

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return std::nan("");
    std::sort(v.begin(), v.end());
    const auto i = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size()))) - 1;
    return v[std::min(i, v.size() - 1)];
}

double median(std::vector<double> v)
{
    return percentile(std::move(v), 0.5);
}

// Runs the event loop until `done` holds or `ms` pass.
template<typename F> bool spinUntil(F done, int ms)
{
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    return done();
}

int latency(double seconds)
{
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = "dma-pn-v51";
    spec.sim.modules = 3;
    auto made = model::Connection::create(spec, *dev::builtinDictionaries());
    if (!made.ok()) {
        std::fprintf(stderr, "no simulator: %s\n", qPrintable(made.error()));
        return 1;
    }
    std::unique_ptr<model::Connection> connection = std::move(made).value();
    connection->open();
    if (!spinUntil([&] { return connection->isOpen(); }, 10'000)) {
        std::fprintf(stderr, "the simulator link did not open\n");
        return 1;
    }
    std::vector<model::ModuleInfo> modules;
    for (int address : connection->moduleAddresses()) {
        std::optional<model::IdentifyResult> found;
        connection->access().identify(address, [&](const model::IdentifyResult &r) { found = r; });
        if (!spinUntil([&] { return found.has_value(); }, 10'000) || !found->ok) {
            std::fprintf(stderr, "module %d not identified\n", address);
            return 1;
        }
        modules.push_back(found->module);
    }

    auto view = std::make_unique<ui::MonitorView>();
    view->resize(1340, 420);
    view->show();
    view->setConnection(connection.get(), modules);
    std::map<int, std::vector<const dev::ParamMeta *>> channels;
    for (const model::ModuleInfo &m : modules)
        channels[m.address] = model::defaultMonitorRows(*m.dictionary, m.identification.mode);
    view->setChannels(channels);
    view->setRate(0); // as fast as the link allows
    view->start();

    std::vector<double> late;
    QElapsedTimer clock;
    clock.start();
    QTimer probe;
    probe.setSingleShot(true);
    probe.setTimerType(Qt::PreciseTimer);
    qint64 dueNs = 0;
    QObject::connect(&probe, &QTimer::timeout, [&] {
        late.push_back(static_cast<double>(clock.nsecsElapsed() - dueNs) * 1e-6);
        dueNs = clock.nsecsElapsed() + 10'000'000;
        probe.start(10);
    });
    dueNs = clock.nsecsElapsed() + 10'000'000;
    probe.start(10);
    const int replotsBefore = view->replotCount();
    spinUntil([] { return false; }, static_cast<int>(seconds * 1000));
    probe.stop();
    const double elapsed = static_cast<double>(clock.nsecsElapsed()) * 1e-9;

    quint64 samples = 0;
    for (const model::ModuleInfo &m : modules)
        samples += view->session().samples(m.address);
    std::printf("latency run: %.1f s, %zu timer events, %llu samples (%.0f/s over 3 modules), "
                "%d redraws\n",
                elapsed, late.size(), static_cast<unsigned long long>(samples),
                static_cast<double>(samples) / elapsed, view->replotCount() - replotsBefore);
    std::printf("timer lateness: median %.2f ms, p99 %.2f ms, max %.2f ms\n", median(late),
                percentile(late, 0.99), *std::max_element(late.begin(), late.end()));
    std::printf("RESULT gui_event_latency_p99_ms=%.2f\n", percentile(late, 0.99));
    view->clearConnection();
    view.reset();
    return 0;
}

void redraw720k()
{
    constexpr int kChannels = 5;
    constexpr qsizetype kRows = 3600 * 200;
    QList<model::SampleChannel> channels;
    const char *ids[kChannels] = {"d1.10", "d1.11", "d1.07", "d1.08", "d1.09"};
    for (const char *id : ids)
        channels.append({QString::fromLatin1(id), QString::fromLatin1(id), QStringLiteral("V")});
    model::SampleStore store(channels, kRows);
    // A step every 10 s with noise on every channel: the decimation has real extremes to keep.
    quint32 noise = 12345;
    double values[kChannels];
    for (qsizetype i = 0; i < kRows; ++i) {
        const double desired = (i / 2000) % 2 ? 5.0 : -5.0;
        for (int c = 0; c < kChannels; ++c) {
            noise = noise * 1664525u + 1013904223u;
            const double n = (static_cast<double>(noise >> 8) / 16777216.0 - 0.5) * 0.2;
            values[c] =
                desired * (1.0 - std::exp(-static_cast<double>(i % 2000) / (50.0 + 20 * c))) + n;
        }
        store.append(static_cast<double>(i) / 200.0, values);
    }
    ui::MonitorPlot plot;
    std::vector<ui::PlotChannel> plotted;
    for (int c = 0; c < kChannels; ++c)
        plotted.push_back({&store, c, channels[c].id, channels[c].name, channels[c].unit, 3});
    plot.setChannels(std::move(plotted));
    plot.resize(1000, 600);
    plot.show();
    QCoreApplication::processEvents();

    auto run = [&](bool decimate, int times, qsizetype *points) {
        plot.setDecimation(decimate);
        for (int i = 0; i < plot.graphCount(); ++i)
            plot.graph(i)->setAdaptiveSampling(decimate); // whole: no sampling of any kind
        std::vector<double> ms;
        for (int i = 0; i < times; ++i) {
            plot.forgetDecimation(); // a full redraw, as after a zoom: every row of the hour
            QElapsedTimer t;
            t.start();
            plot.loadRange(store.firstTime(), store.lastTime());
            plot.replot(QCustomPlot::rpImmediateRefresh);
            ms.push_back(static_cast<double>(t.nsecsElapsed()) * 1e-6);
        }
        *points = plot.pointCount();
        return median(ms);
    };
    qsizetype decimatedPoints = 0, wholePoints = 0;
    run(true, 2, &decimatedPoints); // warm-up
    const double decimated = run(true, 9, &decimatedPoints);
    const double whole = run(false, 3, &wholePoints);
    std::printf("redraw of 5 × 720 000 samples at %d px: decimated %lld points, whole %lld "
                "points\n",
                plot.axisRect()->width(), static_cast<long long>(decimatedPoints),
                static_cast<long long>(wholePoints));
    std::printf("RESULT redraw_720k_ms=%.2f\n", decimated);
    std::printf("RESULT redraw_720k_whole_ms=%.1f\n", whole);
    std::printf("RESULT redraw_720k_whole_vs_decimated_ratio=%.1f\n", whole / decimated);
}

} // namespace

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    double seconds = 20;
    const QStringList args = QCoreApplication::arguments();
    const int at = static_cast<int>(args.indexOf(QStringLiteral("--seconds")));
    if (at >= 0 && at + 1 < args.size())
        seconds = std::max(1.0, args.at(at + 1).toDouble());
    if (const int failed = latency(seconds))
        return failed;
    redraw720k();
    return 0;
}
