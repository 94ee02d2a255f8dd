// SerialLink against a pseudo-terminal pair: the test holds the master, the link opens the slave
// through a symlink, as a user opens one end of `socat pty,link=…`. libserialport refuses a pty
// (no sysfs entry, no modem lines), so this is the termios way of the product code, unchanged:
// settings, unplug, reopen. The termios a UART would receive (parity, character size, which a
// pty drops) is checked on applyLineSettings() itself.
#include "modbus/rtu_timing.h"
#include "pty_pair.h"
#include "qt_printers.h"
#include "test_wait.h"
#include "transports/serial_link.h"
#include "transports/serial_ports.h"
#include "transports/termios_line.h"

#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <chrono>
#include <cstring>
#include <gtest/gtest.h>
#include <memory>

namespace {

using vt::link::LinkState;
using vt::link::Parity;
using vt::link::SerialLink;
using vt::link::SerialSettings;
using vt::link::StopBits;
using vt::test::PtyPair;
using vt::test::waitForCount;
using vt::test::waitForState;

// std::chrono::steady_clock, as Link::frameOnWire() reports it.
qint64 steadyNs()
{
    using namespace std::chrono;
    return duration_cast<nanoseconds>(steady_clock::now().time_since_epoch()).count();
}

class SerialLinkPty : public ::testing::Test
{
protected:
    void SetUp() override
    {
        ASSERT_TRUE(m_dir.isValid());
        m_symlink = m_dir.filePath(QStringLiteral("port"));
        newPty();
    }

    // A fresh pty behind the same symlink: what re-plugging an adapter looks like to the link.
    void newPty()
    {
        m_pty = std::make_unique<PtyPair>();
        ASSERT_TRUE(m_pty->ok()) << m_pty->error().toStdString();
        QFile::remove(m_symlink);
        ASSERT_TRUE(QFile::link(m_pty->slavePath(), m_symlink));
    }

    QString portName() const { return m_symlink; }

    // What the pty itself kept: speed, stop bits, PARODD, the raw-mode flags.
    termios slaveTermios() const
    {
        termios t{};
        EXPECT_TRUE(m_pty->slaveTermios(&t));
        return t;
    }

    QTemporaryDir m_dir;
    QString m_symlink;
    std::unique_ptr<PtyPair> m_pty;
};

TEST_F(SerialLinkPty, OpensAsynchronouslyAndMovesBytesBothWays)
{
    SerialLink link(SerialSettings::hcsDefault(portName()));
    QSignalSpy received(&link, &SerialLink::received);
    QSignalSpy failed(&link, &SerialLink::failed);

    link.open();
    // STYLE.md rule 9: open() only queues work for the worker; the caller never waits.
    EXPECT_EQ(link.state(), LinkState::Opening);
    ASSERT_TRUE(waitForState(link, LinkState::Open))
        << failed.value(0).value(0).toString().toStdString();
    m_pty->startReading();

    const QByteArray request = QByteArray::fromHex("0103000000084a0c");
    link.send(request);
    ASSERT_TRUE(vt::test::waitUntil([&] { return m_pty->received().size() >= request.size(); },
                                    vt::test::kWaitMs));
    EXPECT_EQ(m_pty->received(), request);

    const QByteArray answer = QByteArray::fromHex("010310000100020003000400050006000700089f4b");
    ASSERT_TRUE(m_pty->write(answer));
    QByteArray got;
    ASSERT_TRUE(vt::test::collectBytes(received, got, answer.size()));
    EXPECT_EQ(got, answer);
    EXPECT_EQ(failed.count(), 0);

    link.close();
    EXPECT_EQ(link.state(), LinkState::Closed);
}

// Modbus over Serial Line §2.5.1.1: a frame ends when the line is quiet for t3.5. At 1200 baud
// 8E1 t3.5 is 32 ms, so two writes of the far end a moment apart are one frame, handed on in one
// piece and followed by lineQuiet(); bytes after the quiet are the next frame.
TEST_F(SerialLinkPty, AFrameEndsWhenTheLineGoesQuiet)
{
    SerialSettings settings = SerialSettings::hcsDefault(portName());
    settings.baudRate = 1200;
    ASSERT_TRUE(settings.frameEndBySilence); // the default for Modbus RTU
    SerialLink link(settings);
    QSignalSpy received(&link, &SerialLink::received);
    QSignalSpy quiet(&link, &SerialLink::lineQuiet);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));

    const QByteArray first = QByteArray::fromHex("0103100001");
    const QByteArray rest = QByteArray::fromHex("00020003");
    ASSERT_TRUE(m_pty->write(first));
    ASSERT_TRUE(m_pty->write(rest));
    ASSERT_TRUE(waitForCount(quiet, 1));
    ASSERT_EQ(received.count(), 1);
    EXPECT_EQ(received.at(0).at(0).toByteArray(), first + rest);

    const QByteArray next = QByteArray::fromHex("0a0b0c");
    ASSERT_TRUE(m_pty->write(next));
    ASSERT_TRUE(waitForCount(quiet, 2));
    ASSERT_EQ(received.count(), 2);
    EXPECT_EQ(received.at(1).at(0).toByteArray(), next);
}

// The answer awaited is handed on as soon as it has the size the session expects, not t3.5 later:
// the session decides on the next request while the line keeps its silent interval. A shorter
// answer (an exception) still ends with the quiet. At 1200 baud 8E1 t3.5 is 32 ms.
TEST_F(SerialLinkPty, AnAnswerOfTheExpectedSizeIsHandedOnWithoutWaitingForTheQuiet)
{
    SerialSettings settings = SerialSettings::hcsDefault(portName());
    settings.baudRate = 1200;
    SerialLink link(settings);
    QSignalSpy received(&link, &SerialLink::received);
    QSignalSpy quiet(&link, &SerialLink::lineQuiet);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    m_pty->startReading();

    const QByteArray request = QByteArray::fromHex("010300000002c40b");
    const QByteArray answer = QByteArray::fromHex("01030400010002");
    link.expectReply(answer.size() + 2);
    link.send(request);
    ASSERT_TRUE(vt::test::waitUntil([&] { return m_pty->received().size() >= request.size(); }));
    ASSERT_TRUE(m_pty->write(answer));
    ASSERT_TRUE(m_pty->write(QByteArray::fromHex("2a32"))); // its CRC a moment later
    ASSERT_TRUE(waitForCount(received, 1));
    // One piece of the expected size, and no quiet: the link did not wait for one.
    QByteArray got = received.at(0).at(0).toByteArray();
    if (got.size() < answer.size() + 2) { // the two writes read apart: the rest follows at once
        ASSERT_TRUE(waitForCount(received, 2));
        got += received.at(1).at(0).toByteArray();
    }
    EXPECT_EQ(got, answer + QByteArray::fromHex("2a32"));
    EXPECT_EQ(quiet.count(), 0);

    // The next answer is an exception, shorter than expected: it ends with the quiet.
    const qsizetype before = received.count();
    link.expectReply(answer.size() + 2);
    link.send(request);
    ASSERT_TRUE(
        vt::test::waitUntil([&] { return m_pty->received().size() >= 2 * request.size(); }));
    ASSERT_TRUE(m_pty->write(QByteArray::fromHex("018302c0f1")));
    ASSERT_TRUE(waitForCount(quiet, 1));
    ASSERT_EQ(received.count(), before + 1);
    EXPECT_EQ(received.last().at(0).toByteArray(), QByteArray::fromHex("018302c0f1"));
}

// §2.5.1.1: the next request waits t3.5 after the last byte on the line, however soon the
// session sends it. With the frame ended by its CRC (no wait for the quiet) the session answers
// at once; the link holds the request until 32 ms (1200 baud 8E1) after the answer's last byte.
TEST_F(SerialLinkPty, KeepsTheSilentIntervalBeforeARequest)
{
    SerialSettings settings = SerialSettings::hcsDefault(portName());
    settings.baudRate = 1200;
    settings.frameEndBySilence = false;
    ASSERT_TRUE(settings.silentInterval); // the default for Modbus RTU
    SerialLink link(settings);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    m_pty->startReading();
    ASSERT_TRUE(link.reportsWireTime());
    QSignalSpy onWire(&link, &SerialLink::frameOnWire);
    const QByteArray request = QByteArray::fromHex("0103000000084a0c");
    QElapsedTimer sinceAnswer;
    QObject::connect(
        &link, &SerialLink::received, &link, [&] { link.send(request); }, Qt::SingleShotConnection);
    sinceAnswer.start(); // before the write: the link reads the answer after this
    const qint64 answerNs = steadyNs();
    ASSERT_TRUE(m_pty->write(QByteArray::fromHex("0103020001")));
    ASSERT_TRUE(vt::test::waitUntil([&] { return m_pty->received().size() >= request.size(); }));
    // A lower bound: the link cannot have sent before the interval it must keep.
    const qint64 t35Ns = vt::dev::modbus::silentIntervalUs(1200, 11) * 1000;
    EXPECT_GE(sinceAnswer.nsecsElapsed(), t35Ns);
    EXPECT_EQ(m_pty->received(), request);
    // The time the link reports for the request is when it went out, after the interval: what
    // the telegram list shows (not when send() was called, right after the answer).
    ASSERT_TRUE(waitForCount(onWire, 1));
    const qint64 onWireNs = onWire.value(0).value(0).toLongLong();
    EXPECT_GE(onWireNs - answerNs, t35Ns);
    EXPECT_LE(onWireNs, steadyNs());
}

TEST_F(SerialLinkPty, HcsDefaultIs19200Baud8E1OnTheLine)
{
    SerialLink link(SerialSettings::hcsDefault(portName()));
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    const termios kept = slaveTermios();
    EXPECT_EQ(cfgetospeed(&kept), static_cast<speed_t>(B19200));
    EXPECT_EQ(cfgetispeed(&kept), static_cast<speed_t>(B19200));
    EXPECT_EQ(kept.c_cflag & PARODD, 0u);
    EXPECT_EQ(kept.c_cflag & CSTOPB, 0u);
    EXPECT_EQ(kept.c_iflag & IGNPAR, 0u); // parity errors are not ignored: parity is on
    // Raw: no canonical processing, echo or CR/LF translation that would eat or invent bytes.
    EXPECT_EQ(kept.c_lflag & (ICANON | ECHO | ISIG), 0u);
    EXPECT_EQ(kept.c_iflag & (ICRNL | INLCR | IGNCR), 0u);
    EXPECT_EQ(kept.c_oflag & OPOST, 0u);
    EXPECT_EQ(kept.c_cc[VMIN], 1);
    EXPECT_EQ(kept.c_cc[VTIME], 0);
    EXPECT_EQ(link.description(), QStringLiteral("serial %1 19200 8E1").arg(portName()));
}

TEST_F(SerialLinkPty, HartPresetIs1200Baud8O1OnTheLine)
{
    SerialLink link(SerialSettings::hart(portName()));
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    const termios kept = slaveTermios();
    EXPECT_EQ(cfgetospeed(&kept), static_cast<speed_t>(B1200));
    EXPECT_NE(kept.c_cflag & PARODD, 0u);
    EXPECT_EQ(kept.c_cflag & CSTOPB, 0u);
}

TEST_F(SerialLinkPty, NoParityTwoStopBitsAndSevenDataBits)
{
    SerialSettings s;
    s.portName = portName();
    s.baudRate = 9600;
    ASSERT_TRUE(s.setFormatText(u"7N2"));
    SerialLink link(s);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    const termios kept = slaveTermios();
    EXPECT_EQ(cfgetospeed(&kept), static_cast<speed_t>(B9600));
    EXPECT_NE(kept.c_cflag & CSTOPB, 0u);
    EXPECT_NE(kept.c_iflag & IGNPAR, 0u); // the mark for "no parity", as libserialport sets it
    EXPECT_EQ(link.description(), QStringLiteral("serial %1 9600 7N2").arg(portName()));
}

namespace {

// The line timing off (a virtual port, a gateway that frames itself): nothing on the port waits.
SerialSettings withoutLineTiming(const QString &port, int baud = 19200)
{
    SerialSettings s = SerialSettings::hcsDefault(port);
    s.baudRate = baud;
    s.silentInterval = false;
    s.frameEndBySilence = false;
    return s;
}

} // namespace

// Without line timing the open worker runs on the link's thread: a request is written and an
// answer handed on without a thread hop. Closing takes it back to its thread; a reopen with the
// timing on keeps it there.
TEST_F(SerialLinkPty, WithoutLineTimingTheExchangesRunOnTheLinksThread)
{
    SerialLink link(withoutLineTiming(portName()));
    QSignalSpy received(&link, &SerialLink::received);
    QSignalSpy failed(&link, &SerialLink::failed);
    link.open();
    EXPECT_EQ(link.state(), LinkState::Opening); // opening still happens on the worker thread
    EXPECT_FALSE(link.exchangesOnLinkThread());
    ASSERT_TRUE(waitForState(link, LinkState::Open))
        << failed.value(0).value(0).toString().toStdString();
    EXPECT_TRUE(link.exchangesOnLinkThread());
    m_pty->startReading();

    QSignalSpy onWire(&link, &SerialLink::frameOnWire);
    for (int round = 0; round < 3; ++round) {
        const QByteArray request = QByteArray::fromHex("0103000000084a0c");
        const qint64 beforeNs = steadyNs();
        link.send(request);
        // Written within send() (the driver took it at once): reported there and then.
        ASSERT_EQ(onWire.count(), round + 1);
        EXPECT_GE(onWire.last().value(0).toLongLong(), beforeNs);
        EXPECT_LE(onWire.last().value(0).toLongLong(), steadyNs());
        ASSERT_TRUE(vt::test::waitUntil(
            [&] { return m_pty->received().size() >= (round + 1) * request.size(); },
            vt::test::kWaitMs));
        const QByteArray answer = QByteArray::fromHex("010310000100020003000400050006000700089f4b");
        ASSERT_TRUE(m_pty->write(answer));
        QByteArray got;
        received.clear();
        ASSERT_TRUE(vt::test::collectBytes(received, got, answer.size()));
        EXPECT_EQ(got, answer);
    }
    EXPECT_EQ(m_pty->received(), QByteArray::fromHex("0103000000084a0c").repeated(3));

    link.close();
    EXPECT_FALSE(link.exchangesOnLinkThread());
    newPty(); // a pty master stops reading once its slave closed (it polls as hung up)
    link.setSettings(SerialSettings::hcsDefault(portName()));
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    EXPECT_FALSE(link.exchangesOnLinkThread()); // the line timing waits: on the worker thread
    m_pty->startReading();
    link.send(QByteArrayLiteral("again"));
    ASSERT_TRUE(vt::test::waitUntil([&] { return m_pty->received().endsWith("again"); },
                                    vt::test::kWaitMs));
    EXPECT_EQ(failed.count(), 0);
}

// STYLE.md rule 9 on the link's own thread: a write larger than the driver takes at once (the
// far end reads nothing yet) returns at once, and the rest goes out as the far end reads.
// Blocking here would freeze the GUI: the far end below only reads once send() has returned.
TEST_F(SerialLinkPty, WithoutLineTimingAFullDriverBufferDoesNotBlockTheLinksThread)
{
    SerialLink link(withoutLineTiming(portName(), 4'000'000));
    QSignalSpy failed(&link, &SerialLink::failed);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    ASSERT_TRUE(link.exchangesOnLinkThread());

    QByteArray big(256 * 1024, Qt::Uninitialized);
    for (qsizetype i = 0; i < big.size(); ++i)
        big[i] = static_cast<char>(i * 7 + i / 251);
    link.send(big);
    EXPECT_TRUE(m_pty->received().isEmpty());
    m_pty->startReading();
    ASSERT_TRUE(vt::test::waitUntil([&] { return m_pty->received().size() >= big.size(); },
                                    vt::test::kWaitMs));
    EXPECT_TRUE(m_pty->received() == big);
    EXPECT_EQ(failed.count(), 0);
    EXPECT_EQ(link.state(), LinkState::Open);
}

// A far end that never reads (a stuck adapter): the write fails after its bound (twice the wire
// time plus 500 ms; 128 KiB at 4 Mbit/s: 1.2 s) with a reason, and the port is free again.
TEST_F(SerialLinkPty, WithoutLineTimingAWriteThatNeverDrainsFailsAfterItsBound)
{
    SerialLink link(withoutLineTiming(portName(), 4'000'000));
    QSignalSpy failed(&link, &SerialLink::failed);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    link.send(QByteArray(128 * 1024, 'x'));
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
    EXPECT_TRUE(failed.first().value(0).toString().contains(QStringLiteral("timed out")))
        << failed.first().value(0).toString().toStdString();
    link.open(); // the same pty: it opens again
    EXPECT_TRUE(waitForState(link, LinkState::Open));
}

// Unplugged while the exchanges run on the link's thread: failed() (later, from the event
// loop), and a reopen opens on the worker thread again and exchanges on the link's.
TEST_F(SerialLinkPty, WithoutLineTimingAnUnpluggedPortFailsAndReopens)
{
    SerialLink link(withoutLineTiming(portName()));
    QSignalSpy failed(&link, &SerialLink::failed);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    m_pty->closeMaster();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
    newPty();
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    EXPECT_TRUE(link.exchangesOnLinkThread());
    m_pty->startReading();
    link.send(QByteArrayLiteral("again"));
    ASSERT_TRUE(
        vt::test::waitUntil([&] { return m_pty->received() == "again"; }, vt::test::kWaitMs));
}

TEST_F(SerialLinkPty, UnpluggedFarSideFailsAndReopenWorks)
{
    SerialLink link(SerialSettings::hcsDefault(portName()));
    QSignalSpy failed(&link, &SerialLink::failed);
    QSignalSpy received(&link, &SerialLink::received);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));

    m_pty->closeMaster();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
    EXPECT_FALSE(failed.first().value(0).toString().isEmpty());
    // Sending on a failed link is a logged no-op, not a crash.
    link.send(QByteArrayLiteral("ignored"));

    newPty();
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open));
    m_pty->startReading();
    link.send(QByteArrayLiteral("again"));
    ASSERT_TRUE(
        vt::test::waitUntil([&] { return m_pty->received() == "again"; }, vt::test::kWaitMs));
    ASSERT_TRUE(m_pty->write(QByteArrayLiteral("back")));
    ASSERT_TRUE(waitForCount(received, 1));
    EXPECT_EQ(received.first().value(0).toByteArray(), QByteArrayLiteral("back"));
    EXPECT_EQ(failed.count(), 1);
}

TEST_F(SerialLinkPty, DestroyingAnOpenLinkJoinsTheWorker)
{
    auto link = std::make_unique<SerialLink>(SerialSettings::hcsDefault(portName()));
    link->open();
    ASSERT_TRUE(waitForState(*link, LinkState::Open));
    link->send(QByteArrayLiteral("bye"));
    link.reset();
    // The port was released: a new link on the same pty opens again.
    SerialLink again(SerialSettings::hcsDefault(portName()));
    QSignalSpy failed(&again, &SerialLink::failed);
    again.open();
    EXPECT_TRUE(waitForState(again, LinkState::Open))
        << failed.value(0).value(0).toString().toStdString();
}

// The path the kernel gave the pty, without a symlink: what `valvetune-sim --pty` prints.
TEST_F(SerialLinkPty, OpensThePtyByItsOwnPath)
{
    SerialLink link(SerialSettings::hcsDefault(m_pty->slavePath()));
    QSignalSpy failed(&link, &SerialLink::failed);
    link.open();
    ASSERT_TRUE(waitForState(link, LinkState::Open))
        << failed.value(0).value(0).toString().toStdString();
    m_pty->startReading();
    link.send(QByteArrayLiteral("\x01\x03"));
    ASSERT_TRUE(vt::test::waitUntil([&] { return m_pty->received().size() == 2; }));
}

TEST_F(SerialLinkPty, ARateTermiosLacksFailsWithTheRateInTheReason)
{
    SerialSettings s = SerialSettings::hcsDefault(portName());
    s.baudRate = 12345;
    SerialLink link(s);
    QSignalSpy failed(&link, &SerialLink::failed);
    link.open();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
    EXPECT_TRUE(failed.first().value(0).toString().contains(QStringLiteral("12345")))
        << failed.first().value(0).toString().toStdString();
}

// A character device that is no terminal is refused, not opened as a port.
TEST(SerialLink, NonTerminalIsRefused)
{
    SerialLink link(SerialSettings::hcsDefault(QStringLiteral("/dev/null")));
    QSignalSpy failed(&link, &SerialLink::failed);
    link.open();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
    const QString reason = failed.first().value(0).toString();
    EXPECT_TRUE(reason.contains(QStringLiteral("/dev/null")) &&
                reason.contains(QStringLiteral("not a serial port or terminal")))
        << reason.toStdString();
}

// What the termios way asks a UART for (a pty drops PARENB and CSIZE, so the request is checked
// here): the HCS default 8E1, HART 8O1, 7N2, each raw.
TEST(TermiosLine, SettingsBecomeTheRawLine)
{
    termios t{};
    t.c_lflag = ICANON | ECHO | ISIG;
    t.c_iflag = ICRNL | IXON;
    t.c_oflag = OPOST;
    t.c_cflag = CRTSCTS;
    ASSERT_TRUE(vt::link::applyLineSettings(t, SerialSettings::hcsDefault(QStringLiteral("p"))));
    EXPECT_EQ(cfgetospeed(&t), static_cast<speed_t>(B19200));
    EXPECT_EQ(cfgetispeed(&t), static_cast<speed_t>(B19200));
    EXPECT_EQ(t.c_cflag & CSIZE, static_cast<tcflag_t>(CS8));
    EXPECT_NE(t.c_cflag & PARENB, 0u);
    EXPECT_EQ(t.c_cflag & (PARODD | CSTOPB | CRTSCTS), 0u);
    EXPECT_NE(t.c_cflag & (CLOCAL | CREAD), 0u);
    EXPECT_NE(t.c_iflag & INPCK, 0u);
    EXPECT_EQ(t.c_iflag & (IGNPAR | ICRNL | IXON), 0u);
    EXPECT_EQ(t.c_lflag & (ICANON | ECHO | ISIG), 0u);
    EXPECT_EQ(t.c_oflag & OPOST, 0u);
    EXPECT_EQ(t.c_cc[VMIN], 1);
    EXPECT_EQ(t.c_cc[VTIME], 0);

    ASSERT_TRUE(vt::link::applyLineSettings(t, SerialSettings::hart(QStringLiteral("p"))));
    EXPECT_EQ(cfgetospeed(&t), static_cast<speed_t>(B1200));
    EXPECT_EQ(t.c_cflag & (PARENB | PARODD), static_cast<tcflag_t>(PARENB | PARODD));

    SerialSettings s;
    s.baudRate = 9600;
    ASSERT_TRUE(s.setFormatText(u"7N2"));
    ASSERT_TRUE(vt::link::applyLineSettings(t, s));
    EXPECT_EQ(t.c_cflag & CSIZE, static_cast<tcflag_t>(CS7));
    EXPECT_EQ(t.c_cflag & PARENB, 0u);
    EXPECT_NE(t.c_cflag & CSTOPB, 0u);
    EXPECT_NE(t.c_iflag & IGNPAR, 0u);
    EXPECT_EQ(t.c_iflag & INPCK, 0u);
}

// What a pty holds after an 8E1 request (CS8, no parity) counts as the request; a different rate
// or a cooked line does not.
TEST(TermiosLine, OnlyTheCharacterFormatMayBeDropped)
{
    termios wanted{};
    ASSERT_TRUE(
        vt::link::applyLineSettings(wanted, SerialSettings::hcsDefault(QStringLiteral("p"))));
    termios held = wanted;
    held.c_cflag = (held.c_cflag & ~static_cast<tcflag_t>(CSIZE | PARENB)) | CS8;
    EXPECT_TRUE(vt::link::differsOnlyInCharacterFormat(held, wanted));
    termios slower = held;
    cfsetospeed(&slower, B9600);
    EXPECT_FALSE(vt::link::differsOnlyInCharacterFormat(slower, wanted));
    termios cooked = held;
    cooked.c_lflag |= ICANON;
    EXPECT_FALSE(vt::link::differsOnlyInCharacterFormat(cooked, wanted));
    termios twoStops = held;
    twoStops.c_cflag |= CSTOPB;
    EXPECT_FALSE(vt::link::differsOnlyInCharacterFormat(twoStops, wanted));
}

TEST(TermiosLine, UnknownRateLeavesTheTermiosAlone)
{
    termios t{};
    ASSERT_TRUE(vt::link::applyLineSettings(t, SerialSettings::hcsDefault(QStringLiteral("p"))));
    const termios before = t;
    SerialSettings s = SerialSettings::hcsDefault(QStringLiteral("p"));
    s.baudRate = 12345;
    EXPECT_FALSE(vt::link::applyLineSettings(t, s));
    EXPECT_EQ(std::memcmp(&t, &before, sizeof t), 0);
    EXPECT_EQ(vt::link::termiosBaud(*vt::link::termiosSpeed(115200)), 115200);
    EXPECT_FALSE(vt::link::termiosSpeed(0));
}

TEST(SerialLink, MissingPortFailsWithItsNameInTheReason)
{
    const QString name = QStringLiteral("/dev/ttyVT_no_such_port");
    SerialLink link(SerialSettings::hcsDefault(name));
    QSignalSpy failed(&link, &SerialLink::failed);
    link.open();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
    EXPECT_TRUE(failed.first().value(0).toString().contains(name))
        << failed.first().value(0).toString().toStdString();
}

TEST(SerialLink, InvalidSettingsFailCleanly)
{
    SerialSettings s = SerialSettings::hcsDefault(QString());
    SerialLink link(s);
    QSignalSpy failed(&link, &SerialLink::failed);
    link.open();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
}

TEST(SerialLink, CloseBeforeOpenCompletesStaysClosed)
{
    SerialLink link(SerialSettings::hcsDefault(QStringLiteral("/dev/ttyVT_no_such_port")));
    QSignalSpy failed(&link, &SerialLink::failed);
    QSignalSpy states(&link, &SerialLink::stateChanged);
    link.open();
    link.close();
    EXPECT_EQ(link.state(), LinkState::Closed);
    // The worker's late "not found" belongs to the closed session and is ignored.
    EXPECT_FALSE(failed.wait(100));
    EXPECT_EQ(link.state(), LinkState::Closed);
}

TEST(SerialPorts, EnumerationReturnsWithoutCrashing)
{
    const auto ports = vt::link::availableSerialPorts(); // may well be empty in a container
    for (const auto &port : ports) {
        EXPECT_FALSE(port.name.isEmpty());
        EXPECT_FALSE(port.description.isEmpty());
        EXPECT_TRUE(port.displayText().startsWith(port.name));
    }
}

TEST(SerialPorts, DisplayTextShowsUsbIds)
{
    vt::link::SerialPortInfo info;
    info.name = QStringLiteral("/dev/ttyUSB0");
    info.description = QStringLiteral("FT232R USB UART");
    info.transport = vt::link::SerialTransport::Usb;
    info.usbVid = 0x0403;
    info.usbPid = 0x6001;
    EXPECT_EQ(info.displayText(), QStringLiteral("/dev/ttyUSB0 — FT232R USB UART (0403:6001)"));
}

TEST(SerialSettings, PresetsFromTheArchitecture)
{
    const auto hcs = SerialSettings::hcsDefault(QStringLiteral("/dev/ttyUSB0"));
    EXPECT_EQ(hcs.baudRate, 19200);
    EXPECT_EQ(hcs.formatText(), QStringLiteral("8E1"));
    EXPECT_EQ(hcs.bitsPerCharacter(), 11);
    const auto hart = SerialSettings::hart(QStringLiteral("/dev/ttyUSB1"));
    EXPECT_EQ(hart.baudRate, 1200);
    EXPECT_EQ(hart.formatText(), QStringLiteral("8O1"));
    EXPECT_EQ(SerialLink(hart).description(), QStringLiteral("serial /dev/ttyUSB1 1200 8O1"));
}

TEST(SerialSettings, FormatTextParsesAndRejects)
{
    SerialSettings s;
    EXPECT_TRUE(s.setFormatText(u"8n2"));
    EXPECT_EQ(s.parity, Parity::None);
    EXPECT_EQ(s.stopBits, StopBits::Two);
    EXPECT_EQ(s.bitsPerCharacter(), 11);
    for (const char16_t *bad : {u"", u"8E", u"9E1", u"8X1", u"8E3", u"8E11"}) {
        EXPECT_FALSE(s.setFormatText(bad)) << QString::fromUtf16(bad).toStdString();
    }
    EXPECT_EQ(s.formatText(), QStringLiteral("8N2")); // untouched by the failures
    s.portName = QStringLiteral("/dev/ttyS0");
    EXPECT_FALSE(s.problem());
    s.baudRate = 0;
    EXPECT_TRUE(s.problem());
}

} // namespace
