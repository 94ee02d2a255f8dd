// The Modbus RTU master against valvetune-sim --wire, a strict slave on a pseudo-terminal that
// holds every byte for its character time and ignores a request starting before the line was
// quiet for t3.5 (Modbus over Serial Line V1.02 §2.5.1.1). ValveTune's master reads a whole
// three-module node without tripping it; the same master told not to keep the silent interval is
// refused, so the first test can fail.
#include "../../app/sim_process.h"
#include "dict/dictionary_loader.h"
#include "modbus/rtu_timing.h"
#include "model/session/adapter_factory.h"
#include "model/session/device_access.h"
#include "model/session/session.h"
#include "model/telegrams/telegram_log.h"
#include "model/telegrams/telegram_recorder.h"
#include "test_wait.h"
#include "transports/serial_link.h"
#include "transports/serial_settings.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <vector>

namespace vt::test {
namespace {

using simtest::Sim;

constexpr const char *kFamily = "dma-pn-v51";
constexpr const char *kRefused = "wire: refused request";

struct WireMaster
{
    link::SerialLink link;
    model::Session session;
    model::DeviceAccess access;

    WireMaster(link::SerialSettings settings, model::SessionOptions options)
        : link(settings),
          session(&link, model::makeAdapter(dev::LinkProtocol::ModbusRtu, kFamily), options),
          access(session, *dev::builtinDictionaries())
    {
    }

    bool open()
    {
        link.open();
        return waitForState(link, link::LinkState::Open);
    }

    std::optional<model::ReadResult> read(int module,
                                          const std::vector<const dev::ParamMeta *> &rows)
    {
        std::optional<model::ReadResult> result;
        access.read(module, rows, model::Priority::User,
                    [&](const model::ReadResult &r) { result = r; });
        EXPECT_TRUE(waitFor(result));
        return result;
    }
};

std::string failures(const std::optional<model::ReadResult> &result)
{
    std::string text;
    if (result)
        for (const model::RowFailure &f : result->failures)
            text += f.rows.front()->name + ": " + f.outcome.reason.toStdString() + "\n";
    return text;
}

// Stops the simulator and collects all it said on stderr (stderrSeen()).
void stop(Sim &sim)
{
    sim.process().terminate();
    ASSERT_TRUE(sim.process().waitForFinished(kWaitMs));
    sim.waitForStderr(QStringLiteral("requests refused"));
}

// One module, a strict slave at 4800 baud (t3.5 = 8 ms), and a master's line and options for it.
const QStringList kSlowSim{"--device", kFamily,  "--pty",        "--baud",
                           "4800",     "--wire", "--turnaround", "0.5"};

link::SerialSettings slowLine(const QString &pty)
{
    link::SerialSettings settings = link::SerialSettings::hcsDefault(pty);
    settings.baudRate = 4800;
    return settings;
}

model::SessionOptions slowOptions(std::chrono::milliseconds turnaround)
{
    model::SessionOptions options;
    options.baudRate = 4800;
    options.turnaround = turnaround;
    return options;
}

std::vector<const dev::ParamMeta *> allRows()
{
    return model::readableRows(*dev::builtinDictionaries()->find(kFamily), "51", "3");
}

TEST(SessionWire, TheMasterNeverTripsAStrictSlaveOverAReadAllOfANode)
{
    Sim sim({"--device", kFamily, "--modules", "3", "--pty", "--baud", "115200", "--wire",
             "--turnaround", "0.5"});
    const QString pty = sim.listening();
    ASSERT_FALSE(pty.isEmpty()) << sim.stderrText().toStdString();
    link::SerialSettings settings = link::SerialSettings::hcsDefault(pty);
    settings.baudRate = 115200;
    model::SessionOptions options;
    options.baudRate = 115200;
    // Patient enough that a retry never leaves while a slow simulator is still answering (that
    // would collide with the answer and count as a refusal that is not the master's doing), short
    // enough that an answer a loaded machine splits (the simulator paused longer than t3.5 inside
    // it, which the master rightly takes as the frame's end) costs little.
    options.turnaround = std::chrono::milliseconds(200);
    WireMaster master(settings, options);
    ASSERT_TRUE(master.open());

    const auto rows = allRows();
    for (int module = 1; module <= 3; ++module) {
        const auto result = master.read(module, rows);
        ASSERT_TRUE(result && result->complete())
            << module << "\n"
            << failures(result) << sim.stderrText().toStdString();
        EXPECT_EQ(result->values.size(), rows.size());
    }
    // The simulator counts every request it refused and says so when it stops. (A timeout is
    // no proof either way: on a loaded machine the simulator itself may pause longer than t3.5
    // inside an answer, which the master rightly takes as the frame's end.)
    stop(sim);
    EXPECT_TRUE(sim.stderrSeen().contains(QLatin1String("wire: 0 requests refused")))
        << sim.stderrSeen().toStdString();
}

TEST(SessionWire, AMasterThatDoesNotWaitForTheSilentIntervalIsRefused)
{
    // 4800 baud: t3.5 is 8 ms, far more than a master that sends at once needs to turn round,
    // even on a loaded machine; two short exchanges keep the test at a quarter of a second.
    Sim sim(kSlowSim);
    const QString pty = sim.listening();
    ASSERT_FALSE(pty.isEmpty()) << sim.stderrText().toStdString();
    link::SerialSettings settings = slowLine(pty);
    settings.silentInterval = false;    // --no-silent-interval
    settings.frameEndBySilence = false; // --frame-end crc: the next request follows the CRC
    WireMaster master(settings, slowOptions(std::chrono::milliseconds(30)));
    ASSERT_TRUE(master.open());

    // Two blocks of eight IDs: the second request starts right after the first answer.
    auto rows = allRows();
    rows.resize(16);
    const auto result = master.read(1, rows);
    ASSERT_TRUE(sim.waitForStderr(QLatin1String(kRefused))) << sim.stderrSeen().toStdString();
    EXPECT_GE(master.session.counters().timeouts, 1u);
    stop(sim);
    EXPECT_FALSE(sim.stderrSeen().contains(QLatin1String("wire: 0 requests refused")));
    // The retry, after the back-off, kept the interval by accident and was answered.
    EXPECT_TRUE(result && result->complete()) << failures(result);
}

// The telegram list stamps a request with when it went to the line, not when the session handed
// it to the link: the master keeps t3.5 of silence after each answer (at 4800 baud 8 ms), so in
// the list the next request follows an answer by about that. Stamped at the hand-over it followed
// within a fraction of a millisecond.
TEST(SessionWire, TheTelegramListShowsTheSilentIntervalBetweenAnAnswerAndTheNextRequest)
{
    Sim sim(kSlowSim);
    const QString pty = sim.listening();
    ASSERT_FALSE(pty.isEmpty()) << sim.stderrText().toStdString();
    const link::SerialSettings settings = slowLine(pty);
    ASSERT_TRUE(settings.silentInterval);
    WireMaster master(settings, slowOptions(std::chrono::milliseconds(200)));
    model::TelegramLog log;
    model::TelegramRecorder recorder(master.session, log);
    ASSERT_TRUE(master.open());

    auto rows = allRows();
    rows.resize(48); // six blocks of eight IDs: six exchanges back to back
    const auto result = master.read(1, rows);
    ASSERT_TRUE(result && result->complete()) << failures(result);

    std::vector<qint64> gapsNs; // from an answer to the request after it
    int requests = 0;
    const model::TelegramRecord *previous = nullptr;
    for (auto it = log.begin(); it != log.end(); ++it) {
        if (previous) {
            EXPECT_GE(it->monotonicNs, previous->monotonicNs) << "record " << it->seq;
        }
        if (it->direction == dev::Direction::Request) {
            ++requests;
            if (previous && previous->direction == dev::Direction::Response &&
                previous->status == model::TelegramRecord::Status::Ok)
                gapsNs.push_back(it->monotonicNs - previous->monotonicNs);
        }
        previous = &*it;
    }
    EXPECT_EQ(static_cast<quint64>(requests), master.session.counters().attempts);
    ASSERT_GE(gapsNs.size(), 4u);
    std::nth_element(gapsNs.begin(), gapsNs.begin() + std::ssize(gapsNs) / 2, gapsNs.end());
    const qint64 t35Ns = dev::modbus::silentIntervalUs(4800, 11) * 1000;
    // Half of t3.5: the answer is stamped when the session has it, a thread hop after its last
    // byte, which the master's wait counts from.
    EXPECT_GE(gapsNs[gapsNs.size() / 2], t35Ns / 2) << "t3.5 = " << t35Ns << " ns";
    stop(sim);
}

} // namespace
} // namespace vt::test
