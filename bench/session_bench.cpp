// End-to-end benchmarks of the session engine, each against a baseline in the same run:
//  1. Read all parameters of a DMA-2 module from valvetune-sim on a pseudo-terminal: ValveTune's
//     Session (SerialLink → Modbus RTU adapter) against a libmodbus master reading the same
//     register blocks from the same simulator. Reported: time per read-all and the ratio.
//  2. Monitor: d1.07..d1.13 polled back to back over the in-process simulator paced to 115200
//     baud 8E1; reported: achieved samples/s against the wire limit (request + answer bytes on
//     the wire, zero device turnaround).
// Not a test: it prints figures (docs/PERFORMANCE.md says how to run it). SerialLink opens the pty
// the way it opens any terminal libserialport refuses (plain termios).
#include "access/hcs_rows.h"
#include "access/modbus_adapter.h"
#include "dict/dictionary_loader.h"
#include "model/monitor/monitor_scheduler.h"
#include "model/session/device_access.h"
#include "model/session/session.h"
#include "model/session/sim_endpoint.h"
#include "sim_process_bench.h"
#include "transports/serial_link.h"
#include "transports/serial_settings.h"
#include "transports/sim_link.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>
#include <cstdio>
#include <optional>

namespace {

using namespace vt;

constexpr int kRounds = 10;
using bench::spin;

double valvetuneReadAll(const QString &pty, const dev::Dictionary &dict,
                        const std::vector<const dev::ParamMeta *> &rows)
{
    // A pty has no wire time and libmodbus keeps no silent interval: compare like with like
    // (wire_bench.cpp measures the RTU line timing).
    link::SerialSettings settings = link::SerialSettings::hcsDefault(pty);
    settings.silentInterval = false;
    settings.frameEndBySilence = false;
    link::SerialLink serial(settings);
    model::SessionOptions options;
    options.baudRate = 19200;
    options.turnaround = std::chrono::milliseconds(1000);
    model::Session session(
        &serial,
        std::make_unique<dev::access::ModbusRtuAdapter>(dev::access::hcsFamilyOf(dict.family)),
        options);
    model::DeviceAccess access(session, *dev::builtinDictionaries());
    serial.open();
    if (!spin(
            [&] {
                return serial.state() == link::LinkState::Open ||
                       serial.state() == link::LinkState::Failed;
            },
            5000) ||
        serial.state() != link::LinkState::Open) {
        std::fprintf(stderr, "SerialLink cannot open %s\n", qPrintable(pty));
        return -1;
    }
    QElapsedTimer timer;
    timer.start();
    for (int round = 0; round < kRounds; ++round) {
        std::optional<model::ReadResult> result;
        access.read(1, rows, model::Priority::User,
                    [&](const model::ReadResult &r) { result = r; });
        if (!spin([&] { return result.has_value(); }, 60'000) || !result->complete())
            std::fprintf(stderr, "ValveTune: read all incomplete\n");
    }
    const double seconds = static_cast<double>(timer.nsecsElapsed()) * 1e-9 / kRounds;
    serial.close();
    return seconds;
}

void benchReadAll()
{
    const dev::Dictionary &dict = *dev::builtinDictionaries()->find("dma-pn-v51");
    const auto rows = model::readableRows(dict, "51", "3");
    const auto blocks = dev::access::planHcsBlocks(rows);
    bench::SimProcess sim;
    if (!sim.start(
            {QStringLiteral("--device"), QStringLiteral("dma-pn-v51"), QStringLiteral("--pty")})) {
        std::fprintf(stderr, "valvetune-sim did not start\n");
        return;
    }
    // Alternate the two masters so drift in machine load hits both alike.
    double lib = 0, vt = 0;
    for (int pass = 0; pass < 3; ++pass) {
        lib += bench::libmodbusReadAll(sim.pty, 19200, blocks, {1}, kRounds);
        vt += valvetuneReadAll(sim.pty, dict, rows);
    }
    std::printf(
        "read-all dma-pn-v51 over a pty (%zu rows in %zu requests), mean of %d rounds x 3 passes\n",
        rows.size(), blocks.size(), kRounds);
    std::printf("  libmodbus master (baseline): %8.2f ms\n", lib / 3 * 1e3);
    std::printf("  ValveTune session:           %8.2f ms\n", vt / 3 * 1e3);
    std::printf("  ratio ValveTune / libmodbus: %8.2f\n", vt / lib);
}

void benchMonitor()
{
    model::SimSpec spec;
    spec.family = "dma-pn-v51";
    spec.baudRate = 115200;
    spec.bitsPerCharacter = 11;
    auto made = model::makeSimLink(spec);
    if (!made.ok()) {
        std::fprintf(stderr, "%s\n", qPrintable(made.error()));
        return;
    }
    auto link = std::move(made).value();
    model::SessionOptions options;
    options.baudRate = 115200;
    model::Session session(link.get(),
                           std::make_unique<dev::access::ModbusRtuAdapter>(dev::hcs::Family::Dma),
                           options);
    model::DeviceAccess access(session, *dev::builtinDictionaries());
    link->open();
    spin([&] { return link->state() == link::LinkState::Open; }, 5000);
    const dev::Dictionary &dict = *dev::builtinDictionaries()->find("dma-pn-v51");
    // The closed-loop display block d1.07 .. d1.13: seven consecutive IDs, one request per sample.
    std::vector<const dev::ParamMeta *> rows;
    for (int id = 7; id <= 13; ++id)
        rows.push_back(dict.findId(id));
    model::MonitorScheduler monitor(access);
    monitor.setModule(1, rows, 0);
    QElapsedTimer timer;
    timer.start();
    monitor.start();
    spin([&] { return timer.elapsed() >= 5000; }, 10'000);
    monitor.stop();
    const double seconds = static_cast<double>(timer.nsecsElapsed()) * 1e-9;
    const double achieved = static_cast<double>(monitor.samples(1)) / seconds;
    // FC 3 request: 8 bytes; answer: unit + FC + count + 2 × 7 + CRC = 19 bytes.
    const std::size_t wireBytes = 8 + 5 + 2 * rows.size();
    const double limit = 115200.0 / (11.0 * static_cast<double>(wireBytes));
    std::printf("monitor d1.07..d1.13 (%zu values/request) at 115200 8E1, %.1f s back to back\n",
                rows.size(), seconds);
    std::printf("  wire limit:  %8.1f samples/s (%zu bytes per exchange)\n", limit, wireBytes);
    std::printf("  achieved:    %8.1f samples/s\n", achieved);
    std::printf("  achieved / limit: %.3f\n", achieved / limit);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    benchMonitor();
    benchReadAll();
    return 0;
}
