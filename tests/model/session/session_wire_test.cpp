// The Modbus RTU master against valvetune-sim --wire, a strict slave on a pseudo-terminal that
// holds every byte for its character time and ignores a request starting before the line was
// quiet for t3.5 (Modbus over Serial Line V1.02 §2.5.1.1). ValveTune's master reads a whole
// three-module node without tripping it; the same master told not to keep the silent interval is
// refused, so the first test can fail.
#include "../../app/sim_process.h"
#include "dict/dictionary_loader.h"
#include "model/session/adapter_factory.h"
#include "model/session/device_access.h"
#include "model/session/session.h"
#include "test_wait.h"
#include "transports/serial_link.h"
#include "transports/serial_settings.h"

#include <gtest/gtest.h>

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
    Sim sim({"--device", kFamily, "--pty", "--baud", "4800", "--wire", "--turnaround", "0.5"});
    const QString pty = sim.listening();
    ASSERT_FALSE(pty.isEmpty()) << sim.stderrText().toStdString();
    link::SerialSettings settings = link::SerialSettings::hcsDefault(pty);
    settings.baudRate = 4800;
    settings.silentInterval = false;    // --no-silent-interval
    settings.frameEndBySilence = false; // --frame-end crc: the next request follows the CRC
    model::SessionOptions options;
    options.baudRate = 4800;
    options.turnaround = std::chrono::milliseconds(30);
    WireMaster master(settings, options);
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

} // namespace
} // namespace vt::test
