// valvetune-cli on a serial line that is a pseudo-terminal, the way a user reaches a remote serial
// server bridged with socat or ser2net: the real SerialLink opens the pty with termios, as
// libserialport refuses it (no test-only workaround in this binary). Against valvetune-sim --pty
// and against one end of a `socat pty,raw,echo=0 pty,raw,echo=0` pair whose other end the
// simulator serves: info, read, set with read-back, get, monitor.
#include "app/cli/exit_codes.h"
#include "cli_device_fixture.h"
#include "sim_process.h"

#include <QStandardPaths>
#include <QTemporaryDir>
#include <sys/stat.h>
#include <unistd.h>

namespace vt::clitest {
namespace {

using cli::kExitConnection;
using cli::kExitOk;

// The commands a commissioning engineer runs over a serial line, on `port`.
void runEveryCommandOver(const QString &port)
{
    const QStringList line{"--port", port};
    const CliRun info = cli(QStringList{"info"} + line);
    ASSERT_EQ(info.code, kExitOk) << what(info);
    EXPECT_TRUE(info.says("connection: serial " + port.toStdString() +
                          " 19200 8E1, modbus-rtu, module 1\n"))
        << info.out;
    EXPECT_TRUE(info.says("module 1: dma-pn-v51 V51.00, mode 3 — ")) << info.out;

    const CliRun read = cli(QStringList{"--json", "read"} + line);
    ASSERT_EQ(read.code, kExitOk) << what(read);
    const auto modules = read.json()["modules"];
    ASSERT_EQ(modules.size(), 1u);
    EXPECT_GT(modules[0]["count"].get<int>(), 100);
    EXPECT_TRUE(modules[0]["failures"].empty()) << modules[0]["failures"].dump();

    const CliRun set = cli(QStringList{"set", "C1.07=1.234"} + line);
    ASSERT_EQ(set.code, kExitOk) << what(set);
    EXPECT_EQ(set.out, "C1.07          0.000 V -> 1.234 V  verified\n");
    EXPECT_EQ(cli(QStringList{"get", "C1.07"} + line).out, "C1.07          1.234 V\n");

    const CliRun monitor =
        cli(QStringList{"--json", "monitor", "--rate", "10", "--duration", "0.5"} + line);
    ASSERT_EQ(monitor.code, kExitOk) << what(monitor);
    const auto doc = monitor.json();
    EXPECT_EQ(doc["rows"].size(), 5u); // the family's default channels
    EXPECT_GE(doc["samples"].get<int>(), 3) << monitor.out;
}

TEST_F(CliDevice, EveryCommandOverTheSimulatorsPty)
{
    simtest::Sim sim({"--device", "dma-pn-v51", "--pty"});
    const QString pty = sim.listening();
    ASSERT_TRUE(pty.startsWith("/dev/pts/")) << sim.stderrText().toStdString();
    runEveryCommandOver(pty);
}

TEST_F(CliDevice, EveryCommandOverASocatPtyPair)
{
    const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
    if (socat.isEmpty())
        GTEST_SKIP() << "socat is not installed (scripts/deps test installs it)";
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString simEnd = dir.filePath("sim"), masterEnd = dir.filePath("master");
    simtest::Sim pair(
        {"-d", "-d", "pty,raw,echo=0,link=" + simEnd, "pty,raw,echo=0,link=" + masterEnd}, {},
        socat);
    ASSERT_TRUE(pair.waitForStderr("starting data transfer loop"))
        << pair.stderrSeen().toStdString();
    simtest::Sim sim({"--device", "dma-pn-v51", "--serial", simEnd});
    ASSERT_EQ(sim.listening(), simEnd) << sim.stderrText().toStdString();
    runEveryCommandOver(masterEnd);

    // The pair gone, its link is gone: a connection error naming the port.
    pair.process().terminate();
    ASSERT_TRUE(pair.process().waitForFinished(simtest::kWaitMs));
    const CliRun gone = cli({"info", "--port", masterEnd});
    EXPECT_EQ(gone.code, kExitConnection) << what(gone);
    EXPECT_TRUE(gone.complains(masterEnd.toStdString())) << gone.err;
}

// A file that is no terminal is refused in words, not opened as a port.
TEST_F(CliDevice, AFileThatIsNoTerminalIsRefused)
{
    const CliRun r = cli({"info", "--port", "/dev/null"});
    EXPECT_EQ(r.code, kExitConnection) << what(r);
    EXPECT_EQ(r.errLines(), 1) << r.err;
    EXPECT_TRUE(r.complains("/dev/null: it is not a serial port or terminal.")) << r.err;
}

// A port the user may not open: the real valvetune-cli, without privileges, on the simulator's pty
// with mode 000, says which group to join and how, in English and in German. Root opens any
// port, so as root the command runs as nobody (setpriv, util-linux).
TEST(CliSerialPermission, PermissionDeniedTellsTheUserToJoinDialout)
{
    simtest::Sim sim({"--device", "dma-pn-v51", "--pty"});
    const QString pty = sim.listening();
    ASSERT_TRUE(pty.startsWith("/dev/pts/")) << sim.stderrText().toStdString();
    ASSERT_EQ(::chmod(pty.toLocal8Bit().constData(), 0), 0);

    const auto runCli = [&](const QStringList &args) {
        if (::geteuid() != 0)
            return simtest::run(QStringLiteral(VT_CLI_PATH), args);
        const QString setpriv = QStandardPaths::findExecutable(QStringLiteral("setpriv"));
        EXPECT_FALSE(setpriv.isEmpty()) << "setpriv (util-linux) is missing";
        return simtest::run(setpriv, QStringList{"--reuid=65534", "--regid=65534", "--clear-groups",
                                                 QStringLiteral(VT_CLI_PATH)} +
                                         args);
    };
    const auto en = runCli({"info", "--port", pty});
    ASSERT_TRUE(en.finished);
    EXPECT_EQ(en.code, kExitConnection) << en.err.toStdString();
    EXPECT_TRUE(en.err.contains(
        pty + ": permission denied. Serial ports are for the members of the group dialout: add "
              "your user to it with \"sudo usermod -aG dialout $USER\", then log out and log in "
              "again."))
        << en.err.toStdString();

    const auto de = runCli({"info", "--port", pty, "--lang", "de"});
    ASSERT_TRUE(de.finished);
    EXPECT_EQ(de.code, kExitConnection) << de.err.toStdString();
    EXPECT_TRUE(de.err.contains("sudo usermod -aG dialout $USER") &&
                de.err.contains("Gruppe dialout"))
        << de.err.toStdString();
}

} // namespace
} // namespace vt::clitest
