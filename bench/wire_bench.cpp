// Wire-true serial timing, end to end against valvetune-sim processes on pseudo-terminals:
//  readall_wire_{19200,115200}_limit_ratio: read all of a three-module DMA-2 V51 node from
//    valvetune-sim --wire (every byte held for its character time, 3.5-character silent intervals
//    enforced, device turnaround --turnaround) by ValveTune's Session over SerialLink with the RTU
//    line timing on (the default). Physical limit = Σ over the requests made of (request + answer
//    bytes × 11 bits / baud + t3.5 + turnaround); figure = limit / achieved time (1.0 = the wire).
//  readall_wire_19200_vs_libmodbus: the same read by a libmodbus master in the same run, keeping
//    t3.5 after each answer itself (libmodbus sends the next request at once, which a strict slave
//    ignores); figure = ValveTune time / libmodbus time.
//  readall_pty_vs_libmodbus: the same read from valvetune-sim --pty without wire time, both
//    masters sending the next request as soon as an answer is complete (ValveTune with
//    --no-silent-interval --frame-end crc): the engine's own overhead per exchange.
//  monitor_wire_115200_limit_ratio: d1.07..d1.13 polled back to back over the --wire pty at
//    115200 baud; figure = limit / achieved time, the limit counted as above.
// Not a test: prints `RESULT name=value` lines and the figures behind them (docs/PERFORMANCE.md).
#include "access/hcs_rows.h"
#include "access/modbus_adapter.h"
#include "dict/dictionary_loader.h"
#include "modbus/rtu_timing.h"
#include "model/monitor/monitor_scheduler.h"
#include "model/session/device_access.h"
#include "model/session/session.h"
#include "sim_process_bench.h"
#include "transports/serial_link.h"
#include "transports/serial_settings.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <cstdio>
#include <optional>

namespace {

using namespace vt;
using bench::spin;

constexpr int kBits = 11;             // 8E1
constexpr double kTurnaroundMs = 3.0; // valvetune-sim --wire's default
constexpr const char *kFamily = "dma-pn-v51";
const std::vector<int> kUnits{1, 2, 3};

struct Run
{
    double seconds = -1;     // achieved, per round
    double limitSeconds = 0; // the wire's physical limit for the same requests, per round
    quint64 requests = 0;    // per round
};

// The master's RTU line timing: the default (silent interval, frame end by silence), the silent
// interval with answers taken at their CRC (--frame-end crc), or none (also --no-silent-interval).
enum class Timing { Strict, CrcEnd, None };

// ValveTune's master on `pty`: a Session over SerialLink, with or without the RTU line timing.
class Master
{
public:
    Master(const QString &pty, int baud, Timing timing, double turnaroundMs)
        : m_baud(baud), m_turnaroundMs(turnaroundMs), m_serial(settings(pty, baud, timing)),
          m_session(&m_serial,
                    std::make_unique<dev::access::ModbusRtuAdapter>(dev::hcs::Family::Dma),
                    options(baud)),
          m_access(m_session, *dev::builtinDictionaries())
    {
        QObject::connect(&m_session, &model::Session::frameSent, [this](const QByteArray &b) {
            m_bytes += static_cast<quint64>(b.size());
            ++m_requests;
        });
        QObject::connect(&m_session, &model::Session::frameReceived, [this](const QByteArray &b) {
            m_bytes += static_cast<quint64>(b.size());
        });
        m_serial.open();
        spin([&] { return m_serial.state() != link::LinkState::Opening; }, 5000);
    }
    bool open() const { return m_serial.state() == link::LinkState::Open; }
    model::DeviceAccess &access() { return m_access; }
    const model::Session &session() const { return m_session; }

    void resetCounts() { m_bytes = m_requests = 0; }
    // The physical limit of the exchanges counted since resetCounts().
    double limitSeconds() const
    {
        const double silence =
            static_cast<double>(dev::modbus::silentIntervalUs(m_baud, kBits)) * 1e-6;
        return static_cast<double>(m_bytes) * kBits / m_baud +
               static_cast<double>(m_requests) * (silence + m_turnaroundMs * 1e-3);
    }
    quint64 requests() const { return m_requests; }

    // Reads `rows` of every unit `rounds` times.
    Run readAll(const std::vector<const dev::ParamMeta *> &rows, int rounds)
    {
        resetCounts();
        QElapsedTimer timer;
        timer.start();
        for (int round = 0; round < rounds; ++round) {
            for (const int unit : kUnits) {
                std::optional<model::ReadResult> result;
                m_access.read(unit, rows, model::Priority::User,
                              [&](const model::ReadResult &r) { result = r; });
                if (!spin([&] { return result.has_value(); }, 120'000) || !result->complete())
                    std::fprintf(stderr, "ValveTune: read all of unit %d incomplete\n", unit);
            }
        }
        Run run;
        run.seconds = static_cast<double>(timer.nsecsElapsed()) * 1e-9 / rounds;
        run.limitSeconds = limitSeconds() / rounds;
        run.requests = m_requests / static_cast<quint64>(rounds);
        return run;
    }

private:
    static link::SerialSettings settings(const QString &pty, int baud, Timing timing)
    {
        link::SerialSettings s = link::SerialSettings::hcsDefault(pty);
        s.baudRate = baud;
        s.silentInterval = timing != Timing::None;
        s.frameEndBySilence = timing == Timing::Strict;
        return s;
    }
    static model::SessionOptions options(int baud)
    {
        model::SessionOptions o;
        o.baudRate = baud;
        // Short: an answer the loaded machine splits (the simulator paused longer than t3.5
        // inside it) costs one timeout, counted and printed, not a second.
        o.turnaround = std::chrono::milliseconds(50);
        return o;
    }

    int m_baud;
    double m_turnaroundMs;
    link::SerialLink m_serial;
    model::Session m_session;
    model::DeviceAccess m_access;
    quint64 m_bytes = 0;
    quint64 m_requests = 0;
};

QStringList simArgs(bool wire, int baud)
{
    QStringList args{QStringLiteral("--device"),  QString::fromLatin1(kFamily),
                     QStringLiteral("--modules"), QStringLiteral("3"),
                     QStringLiteral("--pty"),     QStringLiteral("--baud"),
                     QString::number(baud)};
    if (wire)
        args << QStringLiteral("--wire") << QStringLiteral("--turnaround")
             << QString::number(kTurnaroundMs);
    return args;
}

const std::vector<const dev::ParamMeta *> &readAllRows()
{
    static const auto rows =
        model::readableRows(*dev::builtinDictionaries()->find(kFamily), "51", "3");
    return rows;
}

// Read all over the wire at `baud`: the limit ratio, and at 19200 libmodbus beside it.
void benchReadAllOnTheWire(int baud, int rounds, bool withLibmodbus, Timing timing = Timing::Strict)
{
    bench::SimProcess sim;
    if (!sim.start(simArgs(true, baud))) {
        std::fprintf(stderr, "valvetune-sim --wire did not start\n");
        return;
    }
    const auto &rows = readAllRows();
    const auto blocks = dev::access::planHcsBlocks(rows);
    double vt = 0, lib = 0, limit = 0;
    quint64 requests = 0, timeouts = 0;
    // Alternate the masters so drift in machine load hits both alike.
    const int passes = withLibmodbus ? 2 : 1;
    for (int pass = 0; pass < passes; ++pass) {
        {
            Master master(sim.pty, baud, timing, kTurnaroundMs);
            if (!master.open()) {
                std::fprintf(stderr, "SerialLink cannot open %s\n", qPrintable(sim.pty));
                return;
            }
            const Run run = master.readAll(rows, rounds);
            vt += run.seconds / passes;
            limit = run.limitSeconds;
            requests = run.requests;
            timeouts += master.session().counters().timeouts;
        }
        if (withLibmodbus)
            lib += bench::libmodbusReadAll(sim.pty, baud, blocks, kUnits, rounds,
                                           dev::modbus::silentIntervalUs(baud, kBits)) /
                   passes;
    }
    std::printf("read-all of a 3-module %s node over valvetune-sim --wire at %d 8E1, turnaround "
                "%.1f ms, frames ended by %s: %llu requests, %zu rows per module\n",
                kFamily, baud, kTurnaroundMs, timing == Timing::CrcEnd ? "their CRC" : "silence",
                static_cast<unsigned long long>(requests), rows.size());
    std::printf("  physical limit: %8.1f ms\n  ValveTune:      %8.1f ms\n", limit * 1e3, vt * 1e3);
    if (withLibmodbus)
        std::printf("  libmodbus (+ its caller's t3.5 wait): %8.1f ms\n", lib * 1e3);
    const auto wire = sim.stopAndCountWire();
    std::printf("  requests the simulator refused: %d, collisions: %d; ValveTune timeouts: %llu\n",
                wire.refused, wire.collisions, static_cast<unsigned long long>(timeouts));
    std::printf("RESULT readall_wire_%d%s_limit_ratio=%.3f\n", baud,
                timing == Timing::CrcEnd ? "_crc" : "", limit / vt);
    if (withLibmodbus)
        std::printf("RESULT readall_wire_%d_vs_libmodbus=%.3f\n", baud, vt / lib);
}

void benchReadAllOnAPty()
{
    bench::SimProcess sim;
    if (!sim.start(simArgs(false, 19200))) {
        std::fprintf(stderr, "valvetune-sim --pty did not start\n");
        return;
    }
    // A read-all here takes a few ms, so the scheduler's hiccups weigh: 40 rounds in each of 5
    // alternating passes (about a second per master) make the ratio repeatable to a few percent.
    constexpr int kRounds = 40;
    constexpr int kPasses = 5;
    const auto &rows = readAllRows();
    const auto blocks = dev::access::planHcsBlocks(rows);
    double vt = 0, lib = 0;
    for (int pass = 0; pass < kPasses; ++pass) {
        lib += bench::libmodbusReadAll(sim.pty, 19200, blocks, kUnits, kRounds);
        Master master(sim.pty, 19200, Timing::None, 0);
        if (!master.open())
            return;
        vt += master.readAll(rows, kRounds).seconds;
    }
    std::printf("read-all of a 3-module %s node over valvetune-sim --pty (no wire time), mean of "
                "%d rounds x %d passes\n  libmodbus: %8.2f ms\n  ValveTune: %8.2f ms\n",
                kFamily, kRounds, kPasses, lib / kPasses * 1e3, vt / kPasses * 1e3);
    std::printf("RESULT readall_pty_vs_libmodbus=%.3f\n", vt / lib);
}

void benchMonitorOnTheWire()
{
    constexpr int kBaud = 115200;
    bench::SimProcess sim;
    if (!sim.start(simArgs(true, kBaud)))
        return;
    Master master(sim.pty, kBaud, Timing::Strict, kTurnaroundMs);
    if (!master.open())
        return;
    const dev::Dictionary &dict = *dev::builtinDictionaries()->find(kFamily);
    std::vector<const dev::ParamMeta *> rows; // d1.07 .. d1.13: one FC 3 request per sample
    for (int id = 7; id <= 13; ++id)
        rows.push_back(dict.findId(id));
    model::MonitorScheduler monitor(master.access());
    monitor.setModule(1, rows, 0);
    master.resetCounts();
    QElapsedTimer timer;
    timer.start();
    monitor.start();
    spin([&] { return timer.elapsed() >= 4000; }, 10'000);
    monitor.stop();
    const double seconds = static_cast<double>(timer.nsecsElapsed()) * 1e-9;
    const auto wire = sim.stopAndCountWire();
    std::printf("monitor d1.07..d1.13 over valvetune-sim --wire at %d 8E1, turnaround %.1f ms, "
                "%.1f s back to back\n  samples/s: %8.1f (limit %.1f)\n  refused: %d, collisions: "
                "%d, timeouts: %llu\n",
                kBaud, kTurnaroundMs, seconds, static_cast<double>(monitor.samples(1)) / seconds,
                static_cast<double>(master.requests()) / master.limitSeconds(), wire.refused,
                wire.collisions,
                static_cast<unsigned long long>(master.session().counters().timeouts));
    std::printf("RESULT monitor_wire_115200_limit_ratio=%.3f\n", master.limitSeconds() / seconds);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    // `vt_bench_wire [monitor] [readall-115200] [readall-115200-crc] [readall-19200] [pty]`:
    // the figures named, in that order; all of them without arguments.
    QStringList chosen = app.arguments().mid(1);
    const bool all = chosen.isEmpty();
    const auto wanted = [&](const char *name) {
        return all || chosen.removeAll(QString::fromLatin1(name)) > 0;
    };
    if (wanted("monitor"))
        benchMonitorOnTheWire();
    if (wanted("readall-115200"))
        benchReadAllOnTheWire(115200, 3, false);
    if (wanted("readall-115200-crc"))
        benchReadAllOnTheWire(115200, 3, false, Timing::CrcEnd);
    if (wanted("readall-19200"))
        benchReadAllOnTheWire(19200, 1, true);
    if (wanted("pty"))
        benchReadAllOnAPty();
    if (!chosen.isEmpty()) {
        std::fprintf(stderr, "unknown figure: %s\n", qPrintable(chosen.join(QLatin1Char(' '))));
        return 2;
    }
    return 0;
}
