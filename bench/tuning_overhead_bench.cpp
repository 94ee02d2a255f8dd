// What does running a test signal cost beyond the signal itself? A stepped-sine sweep (0.5 .. 5 Hz,
// 3 points per decade, 2 measured + 1 settling cycles) on the built-in simulator of a DMA-2
// module (commissioned preset), through the product's own path: Connection, TestRun, the
// write + read cycles as fast as the link allows. The figure is the test's wall time, from
// start() to the finished outcome (source check, the sweep, the verified restore), against the
// sum of the signal's durations — the physical minimum of the test. Goal ≤ 1.1 (issue: "Test
// overhead"). Prints `RESULT name=value` lines (docs/PERFORMANCE.md).
#include "dict/dictionary_loader.h"
#include "model/session/connection.h"
#include "model/tuning/test_run.h"
#include "model/tuning/workbench_rows.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <cstdio>
#include <optional>

using namespace vt;

namespace {

template<typename Done> bool spinUntil(Done done, int ms)
{
    QEventLoop loop;
    QTimer poll;
    poll.setInterval(1);
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (done())
            loop.quit();
    });
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    poll.start();
    if (!done())
        loop.exec();
    return done();
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    model::ConnectionSpec spec;
    spec.kind = model::ConnectionKind::Sim;
    spec.sim.family = "dma-pn-v51";
    spec.sim.modules = 1;
    auto made = model::Connection::create(spec, *dev::builtinDictionaries());
    if (!made.ok()) {
        std::fprintf(stderr, "no simulator: %s\n", qPrintable(made.error()));
        return 1;
    }
    auto connection = std::move(made).value();
    connection->open();
    if (!spinUntil([&] { return connection->isOpen(); }, 5000))
        return 1;
    const int address = connection->moduleAddresses().front();
    std::optional<model::IdentifyResult> id;
    connection->access().identify(address, [&](const model::IdentifyResult &r) { id = r; });
    if (!spinUntil([&] { return id.has_value(); }, 5000) || !id->ok)
        return 1;
    const model::ModuleInfo module = id->module;
    const dev::ParamMeta *setValue =
        model::testSetValueRow(*module.dictionary, module.identification.mode, 1);

    model::SignalSpec s;
    s.kind = model::SignalKind::Sweep;
    s.amplitude = 0.5;
    s.offset = 4;
    s.fromHz = 0.5;
    s.toHz = 5;
    s.pointsPerDecade = 3;
    s.cycles = 2;
    s.settlingCycles = 1;
    const auto signal = model::TestSignal::make(s);
    model::TestRunSetup setup = model::TestRun::setupFor(module, *setValue, *signal);
    setup.switchSource = true;
    model::TestRun test(connection->access(), setup);
    std::optional<model::TestOutcome> outcome;
    QObject::connect(&test, &model::TestRun::finished,
                     [&](const model::TestOutcome &o) { outcome = o; });
    QElapsedTimer wall;
    wall.start();
    test.start();
    spinUntil([&] { return outcome.has_value(); }, 120'000);
    const double seconds = static_cast<double>(wall.nsecsElapsed()) * 1e-9;
    if (!outcome || outcome->end != model::TestEnd::Finished || !outcome->restored) {
        std::fprintf(stderr, "the sweep did not finish: %s\n",
                     outcome ? qPrintable(outcome->reason) : "no outcome");
        return 1;
    }
    const model::TestRecording &r = test.recording();
    std::printf("sweep of %.2f s (%zu points): %.3f s wall, %d writes at %.0f Hz, %d cycles at "
                "%.0f Hz\n",
                signal->duration(), signal->points().size(), seconds, r.writes, r.updateRateHz(),
                r.cycles, r.sampleRateHz());
    std::printf("RESULT sweep_wall_vs_signal_ratio=%.3f\n", seconds / signal->duration());
    return 0;
}
