// valvetune-sim end to end ("valvetune-sim --device FAMILY … prints one
// line `listening on …` when ready, serves until SIGINT/SIGTERM"; "mbpoll reads and writes
// holding registers over a socat pseudo-terminal pair (Modbus RTU) and over Modbus TCP on
// loopback"): the real binary is spawned and reached the way a user reaches it — mbpoll over its
// pty, over a socat pty pair and over loopback TCP, a raw HART command 0 over its pty; usage
// errors exit 2 with one line; SIGTERM ends it with 0; --fault drops and cuts. Every wait is
// bounded; no sleeps. CANopen on --can-fd: sim_can_test.cpp.
#include "hart/deframer.h"
#include "hart/frame.h"
#include "hart/universal.h"
#include "sim_process.h"

#include <QCoreApplication>
#include <QTemporaryDir>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <map>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

using namespace vt::simtest;

// Modbus RTU over the pty: IDs 0..3 of an OPAT master (point-to-point, unit 1) read their
// defaults (Vers = 3400; --factory: the display values of a commissioned loop would move).
// -P none: a pty takes any parity, the simulator does not insist on 8E1.
TEST(SimCli, MbpollReadsOpatOverPty)
{
    if (mbpoll().isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (scripts/deps test installs it)";
    Sim sim({"--device", "opat", "--modules", "1", "--factory", "--pty"});
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
    ASSERT_TRUE(sim.process().waitForFinished(kWaitMs));
    const QString log = sim.stderrText();
    EXPECT_TRUE(log.contains(QRegularExpression(R"(\] <- 00 01 00 00 00 06 01 03 00 30 00 01)")))
        << log.toStdString();
    EXPECT_TRUE(log.contains(QRegularExpression(R"(\] -> .* 01 86 03)"))) << log.toStdString();
}

// The modules start commissioned (docs/SIMULATOR.md "Commissioned preset"): E17 = 2 and the
// position sensor C1.09 = 4 (0 … 10 V); --factory starts them at the dictionary defaults.
TEST(SimCli, CommissionedUnlessFactory)
{
    if (mbpoll().isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (scripts/deps test installs it)";
    const int e17 = paramId("dma-pn-v51", "E17");
    const int c109 = paramId("dma-pn-v51", "C1.09");
    ASSERT_GT(e17, 0);
    ASSERT_GT(c109, 0);
    const auto readBoth = [&](const QStringList &extra) {
        Sim sim(QStringList{"--device", "dma-pn-v51", "--tcp", "127.0.0.1:0"} + extra);
        const QString where = sim.listening();
        EXPECT_TRUE(where.startsWith("127.0.0.1:")) << sim.stderrText().toStdString();
        std::map<int, int> out;
        for (int id : {e17, c109}) {
            const ProcessRun r =
                run(mbpoll(), {"-m", "tcp", "-p", where.section(':', -1), "-a", "1", "-r",
                               QString::number(id), "-c", "1", "-1", "-0", "-o", "2", "127.0.0.1"});
            EXPECT_EQ(r.code, 0) << r.out.toStdString() << r.err.toStdString();
            const auto values = registers(r.out);
            if (values.count(id))
                out[id] = values.at(id);
        }
        return out;
    };
    const auto commissioned = readBoth({});
    EXPECT_EQ(commissioned.at(e17), 2);  // only digital set values
    EXPECT_EQ(commissioned.at(c109), 4); // 0 … 10 V position sensor
    const auto factory = readBoth({"--factory"});
    EXPECT_EQ(factory.at(e17), freshWord("dma-pn-v51", 1, 0, e17));
    EXPECT_EQ(factory.at(c109), freshWord("dma-pn-v51", 1, 0, c109));
    EXPECT_EQ(factory.at(e17), 0);
}

// Modbus TCP writes: C1.07 (dead band A, 0..9999) of the DMA-2 with E22 = 2 takes a new value
// that reads back, while module 1 keeps its default (unit id = module address).
TEST(SimCli, MbpollWritesOverTcp)
{
    if (mbpoll().isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (scripts/deps test installs it)";
    Sim sim({"--device", "dma-pn-v51", "--modules", "3", "--tcp", ":0"});
    const QString where = sim.listening();
    ASSERT_TRUE(where.startsWith("127.0.0.1:")) << sim.stderrText().toStdString();
    const int id = paramId("dma-pn-v51", "C1.07");
    ASSERT_GE(id, 0);
    auto tcp = [&](const QString &unit, const QStringList &values) {
        return run(mbpoll(),
                   QStringList{"-m", "tcp", "-p", where.section(':', -1), "-a", unit, "-t", "4",
                               "-r", QString::number(id), "-1", "-0", "-o", "2", "127.0.0.1"} +
                       values);
    };
    const ProcessRun writing = tcp("2", {"1234"});
    ASSERT_TRUE(writing.finished);
    ASSERT_EQ(writing.code, 0) << writing.out.toStdString() << writing.err.toStdString();
    EXPECT_TRUE(writing.out.contains("Written 1 references")) << writing.out.toStdString();
    EXPECT_EQ(registers(tcp("2", {}).out)[id], 1234);
    EXPECT_EQ(registers(tcp("1", {}).out)[id], freshWord("dma-pn-v51", 3, 0, id));
}

// Modbus RTU over a socat pseudo-terminal pair, the way a master without a null-modem cable
// reaches the simulator: valvetune-sim --serial on one end (plain termios), mbpoll on the other,
// one mbpoll run per transaction. C1.07 of a DMA-2 V51 reads
// its default, takes a write and reads it back; 10000 (above 9999) gets exception 3 and leaves
// the value alone. The runs after the first one also pin down that an empty line is no end of
// file for --serial (VMIN 1).
TEST(SimCli, MbpollReadsAndWritesOverSocatPtyPair)
{
    if (mbpoll().isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (scripts/deps test installs it)";
    const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
    if (socat.isEmpty())
        GTEST_SKIP() << "socat is not installed (scripts/deps test installs it)";
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString simEnd = dir.filePath("sim"), masterEnd = dir.filePath("master");
    Sim pair({"-d", "-d", "pty,raw,echo=0,link=" + simEnd, "pty,raw,echo=0,link=" + masterEnd}, {},
             socat);
    ASSERT_TRUE(pair.waitForStderr("starting data transfer loop"))
        << pair.stderrSeen().toStdString();

    Sim sim({"--device", "dma-pn-v51", "--serial", simEnd, "--parity", "none"});
    ASSERT_EQ(sim.listening(), simEnd) << sim.stderrText().toStdString();
    const int id = paramId("dma-pn-v51", "C1.07");
    ASSERT_GE(id, 0);
    auto rtu = [&](const QStringList &values) {
        return run(mbpoll(),
                   QStringList{"-m", "rtu", "-b", "19200", "-P", "none", "-a", "1", "-t", "4", "-r",
                               QString::number(id), "-1", "-0", "-o", "2", masterEnd} +
                       values);
    };
    const ProcessRun before = rtu({});
    ASSERT_EQ(before.code, 0) << before.out.toStdString() << before.err.toStdString();
    EXPECT_EQ(registers(before.out)[id], freshWord("dma-pn-v51", 1, 0, id));

    const ProcessRun writing = rtu({"1500"});
    ASSERT_EQ(writing.code, 0) << writing.out.toStdString() << writing.err.toStdString();
    EXPECT_TRUE(writing.out.contains("Written 1 references")) << writing.out.toStdString();
    EXPECT_EQ(registers(rtu({}).out)[id], 1500);

    const ProcessRun refused = rtu({"10000"});
    EXPECT_TRUE((refused.out + refused.err).contains("Illegal data value"))
        << refused.out.toStdString() << refused.err.toStdString();
    EXPECT_EQ(registers(rtu({}).out)[id], 1500);
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
        // CAN: canopen only, one module per node id, node 1..127, no line settings, no HART.
        {"--device", "opat", "--can", "vcan0", "--protocol", "modbus-rtu"},
        {"--device", "dma-pn-v51", "--modules", "2", "--can", "vcan0"},
        {"--device", "dma-pn-v51", "--can", "vcan0", "--node", "128"},
        {"--device", "dma-pn-v51", "--tcp", ":0", "--node", "3"},
        {"--device", "dma-pn-v51", "--can-fd", "x"},
        {"--device", "opat", "--can", "vcan0", "--baud", "9600"},
        {"--device", "wandfluh-sd7", "--can", "vcan0"},
        {"--device", "wandfluh-ed1", "--can", "vcan0", "--modules", "2"},
        {"--device", "opat", "--can", "vcan0", "--pty"},
        // --wire: Modbus RTU on a pty or serial port only; --turnaround with it, 0..1000 ms.
        {"--device", "opat", "--tcp", ":0", "--wire"},
        {"--device", "wandfluh-sd7", "--pty", "--wire"},
        {"--device", "opat", "--pty", "--turnaround", "2"},
        {"--device", "opat", "--pty", "--wire", "--turnaround", "-1"},
        {"--device", "opat", "--pty", "--wire", "--no-wire"},
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
    ASSERT_TRUE(sim.process().waitForFinished(kWaitMs));
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
    const QDeadlineTimer deadline(kWaitMs);
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
    ASSERT_TRUE(answer.has_value()) << "no HART answer within " << kWaitMs << " ms";
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
    ASSERT_TRUE(sim.process().waitForFinished(kWaitMs));
    EXPECT_EQ(sim.process().exitCode(), 0);
    EXPECT_TRUE(sim.stderrText().contains("fault cut after 1 answers"));
}

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
