// valvetune-sim end to end (Device simulator issue: "valvetune-sim --device FAMILY … prints one
// line `listening on …` when ready, serves until SIGINT/SIGTERM"): the real binary is spawned
// and reached the way a user reaches it — mbpoll over its pty (Modbus RTU) and over loopback
// TCP (Modbus TCP), a raw HART command 0 over its pty; usage errors exit 2 with one line;
// SIGTERM ends it with 0; --fault drops and cuts. Every wait is bounded; no sleeps.
#include "hart/deframer.h"
#include "hart/frame.h"
#include "hart/universal.h"
#include "sim/node_config.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <map>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

namespace {

constexpr int kStartMs = 10'000;
constexpr int kRunMs = 20'000;

// The simulator as a child process; SIGTERM (then SIGKILL) when the test is done with it.
class Sim
{
public:
    explicit Sim(const QStringList &args)
    {
        m_process.setProgram(QStringLiteral(VT_SIM_PATH));
        m_process.setArguments(args);
        m_process.start();
    }
    ~Sim()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.terminate();
        if (!m_process.waitForFinished(kStartMs)) {
            m_process.kill();
            m_process.waitForFinished(kStartMs);
        }
    }
    Sim(const Sim &) = delete;
    Sim &operator=(const Sim &) = delete;

    // What follows "listening on " on the first stdout line; empty when none came in time.
    QString listening()
    {
        const QDeadlineTimer deadline(kStartMs);
        while (!m_process.canReadLine()) {
            if (deadline.hasExpired() || m_process.state() == QProcess::NotRunning)
                return {};
            m_process.waitForReadyRead(
                static_cast<int>(std::max<qint64>(1, deadline.remainingTime())));
        }
        const QString line = QString::fromUtf8(m_process.readLine()).trimmed();
        const QString prefix = QStringLiteral("listening on ");
        return line.startsWith(prefix) ? line.mid(prefix.size()) : QString();
    }
    QString stderrText() { return QString::fromUtf8(m_process.readAllStandardError()); }
    QProcess &process() { return m_process; }

private:
    QProcess m_process;
};

struct ProcessRun
{
    bool finished = false;
    int code = -1;
    QString out, err;
};

ProcessRun run(const QString &program, const QStringList &args)
{
    QProcess p;
    p.start(program, args);
    ProcessRun r;
    r.finished = p.waitForFinished(kRunMs);
    if (!r.finished)
        p.kill();
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

QString mbpoll()
{
    return QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
}

// mbpoll's "[ref]: \tvalue" lines, values as the 16-bit register words.
std::map<int, std::uint16_t> registers(const QString &out)
{
    std::map<int, std::uint16_t> values;
    static const QRegularExpression line(QStringLiteral(R"(^\[(\d+)\]:\s+(-?\d+))"),
                                         QRegularExpression::MultilineOption);
    for (auto it = line.globalMatch(out); it.hasNext();) {
        const auto m = it.next();
        values[m.captured(1).toInt()] = static_cast<std::uint16_t>(m.captured(2).toInt());
    }
    return values;
}

// A fresh in-process node: what the simulator's modules hold before anyone writes.
std::uint16_t freshWord(const std::string &family, std::size_t modules, std::size_t index, int id)
{
    vt::dev::sim::SimClock clock;
    auto node = vt::dev::sim::makeNode(clock, family, modules);
    EXPECT_TRUE(node.ok());
    return node.ok() ? (*node)->module(index).storage().word(id) : 0;
}

int lineCount(const QString &text)
{
    return static_cast<int>(text.count(QLatin1Char('\n')));
}

} // namespace

// Modbus RTU over the pty: IDs 0..3 of an OPAT master (point-to-point, unit 1) read their
// defaults (Vers = 3400). -P none: a pty takes any parity, the simulator does not insist on 8E1.
TEST(SimCli, MbpollReadsOpatOverPty)
{
    if (mbpoll().isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (scripts/deps test installs it)";
    Sim sim({"--device", "opat", "--modules", "1", "--pty"});
    const QString pty = sim.listening();
    ASSERT_TRUE(pty.startsWith("/dev/")) << sim.stderrText().toStdString();
    const ProcessRun r = run(mbpoll(), {"-m", "rtu", "-b", "19200", "-P", "none", "-a", "1", "-r",
                                        "0", "-c", "4", "-1", "-0", "-o", "2", pty});
    ASSERT_TRUE(r.finished);
    ASSERT_EQ(r.code, 0) << r.out.toStdString() << r.err.toStdString();
    const auto values = registers(r.out);
    ASSERT_EQ(values.size(), 4u) << r.out.toStdString();
    for (int id = 0; id < 4; ++id)
        EXPECT_EQ(values.at(id), freshWord("opat", 1, 0, id)) << "ID " << id;
    EXPECT_EQ(values.at(0), 3400); // Vers = V34 × 100
}

// Modbus TCP on loopback, any port: unit 1 = the OPAT slave with DIP switch 1 reads C1.07 (ID 48)
// at its default; a write out of range (0..9999) gets exception 3 "Illegal data value"; -v logs
// both frames of each transaction.
TEST(SimCli, MbpollOverTcpReadsAndGetsIllegalDataValue)
{
    if (mbpoll().isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (scripts/deps test installs it)";
    Sim sim({"--device", "opat", "--modules", "3", "--tcp", "127.0.0.1:0", "--protocol",
             "modbus-tcp", "-v"});
    const QString where = sim.listening();
    ASSERT_TRUE(where.startsWith("127.0.0.1:")) << sim.stderrText().toStdString();
    const QString port = where.section(':', -1);
    ASSERT_GT(port.toInt(), 0);

    const ProcessRun reading = run(mbpoll(), {"-m", "tcp", "-p", port, "-a", "1", "-r", "48", "-c",
                                              "1", "-1", "-0", "-o", "2", "127.0.0.1"});
    ASSERT_TRUE(reading.finished);
    ASSERT_EQ(reading.code, 0) << reading.out.toStdString() << reading.err.toStdString();
    const auto values = registers(reading.out);
    ASSERT_EQ(values.count(48), 1u) << reading.out.toStdString();
    EXPECT_EQ(values.at(48), freshWord("opat", 3, 1, 48));

    const ProcessRun writing = run(mbpoll(), {"-m", "tcp", "-p", port, "-a", "1", "-r", "48", "-1",
                                              "-0", "-o", "2", "127.0.0.1", "20000"});
    ASSERT_TRUE(writing.finished);
    EXPECT_TRUE((writing.out + writing.err).contains("Illegal data value"))
        << writing.err.toStdString();

    sim.process().terminate();
    ASSERT_TRUE(sim.process().waitForFinished(kStartMs));
    const QString log = sim.stderrText();
    EXPECT_TRUE(log.contains(QRegularExpression(R"(\] <- 00 01 00 00 00 06 01 03 00 30 00 01)")))
        << log.toStdString();
    EXPECT_TRUE(log.contains(QRegularExpression(R"(\] -> .* 01 86 03)"))) << log.toStdString();
}

TEST(SimCli, UsageErrorsExitTwoWithOneLine)
{
    const QList<QStringList> cases = {
        {"--device", "no-such-family", "--pty"},
        {"--device", "opat", "--pty", "--tcp", ":0"},
        {"--device", "wandfluh-ed1", "--pty"},
        {"--device", "dma-pn-v51", "--modules", "6", "--tcp", ":0", "--protocol", "node-image"},
        {"--device", "opat", "--pty", "--protocol", "canopen"},
        {"--device", "opat", "--pty", "--fault", "drop=2"},
        {"--pty"},
    };
    for (const QStringList &args : cases) {
        const ProcessRun r = run(QStringLiteral(VT_SIM_PATH), args);
        ASSERT_TRUE(r.finished) << args.join(' ').toStdString();
        EXPECT_EQ(r.code, 2) << args.join(' ').toStdString();
        EXPECT_EQ(lineCount(r.err), 1) << r.err.toStdString();
        EXPECT_TRUE(r.err.startsWith("valvetune-sim: ")) << r.err.toStdString();
        EXPECT_TRUE(r.out.isEmpty()) << r.out.toStdString();
    }
    EXPECT_TRUE(run(QStringLiteral(VT_SIM_PATH), {"--device", "wandfluh-ed1", "--pty"})
                    .err.contains("PROFIBUS"));
}

TEST(SimCli, SigtermEndsWithZero)
{
    Sim sim({"--device", "dma-pn-v51", "--modules", "3", "--tcp", ":0"});
    ASSERT_FALSE(sim.listening().isEmpty()) << sim.stderrText().toStdString();
    sim.process().terminate(); // SIGTERM
    ASSERT_TRUE(sim.process().waitForFinished(kStartMs));
    EXPECT_EQ(sim.process().exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(sim.process().exitCode(), 0);
}

// HART over the pty: a short-frame command 0 (HART-7 manual §5.1) gets the identity with the
// Wandfluh manufacturer id 24835 (§3.4).
TEST(SimCli, HartCommandZeroOverPty)
{
    Sim sim({"--device", "wandfluh-sd7", "--pty"});
    const QString pty = sim.listening();
    ASSERT_TRUE(pty.startsWith("/dev/")) << sim.stderrText().toStdString();
    const int fd = open(pty.toLocal8Bit().constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    ASSERT_GE(fd, 0);
    termios tio{};
    ASSERT_EQ(tcgetattr(fd, &tio), 0);
    cfmakeraw(&tio);
    ASSERT_EQ(tcsetattr(fd, TCSANOW, &tio), 0);

    namespace hart = vt::dev::hart;
    const auto request = hart::encodeFrame(hart::makeRequest(hart::shortAddress(0), 0));
    ASSERT_TRUE(request.ok());
    ASSERT_EQ(write(fd, request->data(), request->size()), static_cast<ssize_t>(request->size()));

    hart::Deframer deframer;
    std::optional<hart::Frame> answer;
    const QDeadlineTimer deadline(kStartMs);
    while (!answer && !deadline.hasExpired()) {
        pollfd p{fd, POLLIN, 0};
        if (poll(&p, 1, static_cast<int>(std::max<qint64>(1, deadline.remainingTime()))) <= 0)
            continue;
        std::uint8_t buf[512];
        const ssize_t n = read(fd, buf, sizeof buf);
        if (n <= 0)
            continue;
        for (const auto &e :
             deframer.feed(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n))))
            if (e.kind == hart::DeframerEvent::Kind::Frame)
                answer = e.frame;
    }
    close(fd);
    ASSERT_TRUE(answer.has_value()) << "no HART answer within " << kStartMs << " ms";
    EXPECT_EQ(answer->type, hart::FrameType::Ack);
    EXPECT_EQ(answer->command, 0);
    const auto payload = hart::decodeUniversal(0, true, answer->data);
    ASSERT_TRUE(payload.ok());
    EXPECT_EQ(std::get<hart::Identity>(*payload).manufacturerId, 24835);
}

// --fault: drop=1 loses every answer (mbpoll times out); cut=1 on a pty closes it after the
// first answer and the simulator ends with 0.
TEST(SimCli, FaultsDropAndCut)
{
    if (mbpoll().isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (scripts/deps test installs it)";
    {
        Sim sim({"--device", "dma-pn-v51", "--tcp", ":0", "--fault", "drop=1"});
        const QString where = sim.listening();
        ASSERT_FALSE(where.isEmpty()) << sim.stderrText().toStdString();
        const ProcessRun r = run(mbpoll(), {"-m", "tcp", "-p", where.section(':', -1), "-a", "1",
                                            "-r", "0", "-1", "-0", "-o", "0.3", "127.0.0.1"});
        ASSERT_TRUE(r.finished);
        EXPECT_NE(r.code, 0) << r.out.toStdString();
        EXPECT_TRUE(registers(r.out).empty()) << r.out.toStdString();
    }
    Sim sim({"--device", "opat", "--pty", "--fault", "cut=1"});
    const QString pty = sim.listening();
    ASSERT_FALSE(pty.isEmpty()) << sim.stderrText().toStdString();
    const ProcessRun r = run(
        mbpoll(), {"-m", "rtu", "-P", "none", "-a", "1", "-r", "0", "-1", "-0", "-o", "2", pty});
    ASSERT_TRUE(r.finished);
    EXPECT_EQ(registers(r.out).size(), 1u) << r.out.toStdString() << r.err.toStdString();
    ASSERT_TRUE(sim.process().waitForFinished(kStartMs));
    EXPECT_EQ(sim.process().exitCode(), 0);
    EXPECT_TRUE(sim.stderrText().contains("fault cut after 1 answers"));
}

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
