// CanLink and the 16-byte can_frame image (fd-based SocketCAN
// link). This kernel has no AF_CAN, so the I/O path is exercised through
// socketpair(AF_UNIX, SOCK_SEQPACKET), which keeps datagram boundaries as CAN_RAW does.
#include "qt_printers.h"
#include "test_wait.h"
#include "transports/can_link.h"

#include <QSignalSpy>
#include <cerrno>
#include <cstring>
#include <gtest/gtest.h>
#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace {

using vt::link::CanFrame;
using vt::link::CanLink;
using vt::link::LinkState;
using vt::test::waitForCount;
using vt::test::waitForState;

bool littleEndianHost()
{
    const std::uint32_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

// CANopen SDO upload request to node 5 for 0x6041 sub 0 (CiA 301 §7.2.4.3.3).
CanFrame sdoRequest()
{
    CanFrame f;
    f.id = 0x605;
    f.data = QByteArray::fromHex("4041600000000000");
    return f;
}

class CanSocketPair : public ::testing::Test
{
protected:
    void SetUp() override
    {
        int fds[2] = {-1, -1};
        ASSERT_EQ(::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, fds), 0)
            << std::strerror(errno);
        m_link = std::make_unique<CanLink>(CanLink::AdoptedFd{fds[0]}, QStringLiteral("pair"));
        m_peer = fds[1];
    }
    void TearDown() override
    {
        if (m_peer >= 0)
            ::close(m_peer);
    }
    // The peer's next datagram, waiting at most kWaitMs for it.
    QByteArray peerRead()
    {
        pollfd p{m_peer, POLLIN, 0};
        if (::poll(&p, 1, vt::test::kWaitMs) != 1)
            return {};
        char buffer[128];
        const ssize_t n = ::recv(m_peer, buffer, sizeof buffer, MSG_DONTWAIT);
        return n > 0 ? QByteArray(buffer, static_cast<qsizetype>(n)) : QByteArray();
    }
    bool peerWrite(const QByteArray &bytes)
    {
        return ::send(m_peer, bytes.constData(), static_cast<size_t>(bytes.size()), MSG_NOSIGNAL) ==
               bytes.size();
    }

    std::unique_ptr<CanLink> m_link;
    int m_peer = -1;
};

TEST(CanFrame, ImageIsTheLinuxCanFrameLayoutByteForByte)
{
    ASSERT_TRUE(littleEndianHost()) << "expected bytes below are written for little-endian hosts";
    const QByteArray image = sdoRequest().toImage();
    ASSERT_EQ(image.size(), 16);
    // can_id LE, len, 3 padding bytes, data[8]
    EXPECT_EQ(image, QByteArray::fromHex("05060000"
                                         "08"
                                         "000000"
                                         "4041600000000000"));

    // The same bytes as the kernel's struct.
    can_frame kernel;
    std::memset(&kernel, 0, sizeof kernel);
    kernel.can_id = 0x605;
    kernel.len = 8;
    const unsigned char payload[] = {0x40, 0x41, 0x60, 0, 0, 0, 0, 0};
    std::memcpy(kernel.data, payload, sizeof payload);
    EXPECT_EQ(image, QByteArray(reinterpret_cast<const char *>(&kernel), sizeof kernel));

    CanFrame ext;
    ext.id = 0x18FF1234;
    ext.extended = true;
    ext.data = QByteArray::fromHex("aabb");
    EXPECT_EQ(ext.toImage(), QByteArray::fromHex("3412ff98"
                                                 "02"
                                                 "000000"
                                                 "aabb000000000000"));
}

TEST(CanFrame, ParsesImagesAndRejectsMalformedOnes)
{
    const CanFrame original = sdoRequest();
    const auto back = CanFrame::fromImage(original.toImage());
    ASSERT_TRUE(back);
    EXPECT_EQ(*back, original);

    CanFrame rtr;
    rtr.id = 0x705;
    rtr.remote = true;
    const auto rtrBack = CanFrame::fromImage(rtr.toImage());
    ASSERT_TRUE(rtrBack);
    EXPECT_TRUE(rtrBack->remote);
    EXPECT_EQ(rtrBack->id, 0x705u);

    EXPECT_FALSE(CanFrame::fromImage(QByteArray(15, '\0')));
    EXPECT_FALSE(CanFrame::fromImage(QByteArray(17, '\0')));
    QByteArray badLen = original.toImage();
    badLen[4] = 9;
    EXPECT_FALSE(CanFrame::fromImage(badLen));

    CanFrame tooWide;
    tooWide.id = 0x800; // 12 bits in an 11-bit frame
    EXPECT_FALSE(tooWide.isValid());
    tooWide.extended = true;
    EXPECT_TRUE(tooWide.isValid());
    tooWide.data = QByteArray(9, 'x');
    EXPECT_FALSE(tooWide.isValid());
}

TEST_F(CanSocketPair, FramesTravelBothWaysByteExact)
{
    QSignalSpy received(m_link.get(), &CanLink::received);
    m_link->open();
    EXPECT_EQ(m_link->state(), LinkState::Opening);
    ASSERT_TRUE(waitForState(*m_link, LinkState::Open));
    EXPECT_EQ(m_link->description(), QStringLiteral("can pair"));

    m_link->sendFrame(sdoRequest());
    EXPECT_EQ(peerRead(), sdoRequest().toImage());

    // Two images in one send(): two datagrams on the wire.
    CanFrame second = sdoRequest();
    second.id = 0x606;
    m_link->send(sdoRequest().toImage() + second.toImage());
    EXPECT_EQ(peerRead(), sdoRequest().toImage());
    EXPECT_EQ(peerRead(), second.toImage());

    // SDO upload response from node 5: status word 0x0237.
    CanFrame answer;
    answer.id = 0x585;
    answer.data = QByteArray::fromHex("4b41600037020000");
    CanFrame heartbeat;
    heartbeat.id = 0x705;
    heartbeat.data = QByteArray::fromHex("05");
    ASSERT_TRUE(peerWrite(answer.toImage()));
    ASSERT_TRUE(peerWrite(heartbeat.toImage()));
    ASSERT_TRUE(waitForCount(received, 2));
    EXPECT_EQ(received.at(0).value(0).toByteArray(), answer.toImage());
    EXPECT_EQ(received.at(1).value(0).toByteArray(), heartbeat.toImage());
    EXPECT_EQ(received.at(1).value(0).toByteArray().size(), 16);
}

TEST_F(CanSocketPair, MalformedImagesAreDroppedBothWays)
{
    QSignalSpy received(m_link.get(), &CanLink::received);
    m_link->open();
    ASSERT_TRUE(waitForState(*m_link, LinkState::Open));

    m_link->send(QByteArray(15, '\x01')); // not a whole image: logged and dropped
    m_link->sendFrame(sdoRequest());
    EXPECT_EQ(peerRead(), sdoRequest().toImage()); // the good one is the first to arrive

    ASSERT_TRUE(peerWrite(QByteArray(7, '\x02'))); // a short datagram from the far side
    ASSERT_TRUE(peerWrite(sdoRequest().toImage()));
    ASSERT_TRUE(waitForCount(received, 1));
    EXPECT_EQ(received.first().value(0).toByteArray(), sdoRequest().toImage());
    EXPECT_EQ(m_link->state(), LinkState::Open);
}

TEST_F(CanSocketPair, PeerClosingFailsTheLink)
{
    QSignalSpy failed(m_link.get(), &CanLink::failed);
    m_link->open();
    ASSERT_TRUE(waitForState(*m_link, LinkState::Open));
    ::close(m_peer);
    m_peer = -1;
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(m_link->state(), LinkState::Failed);
    // An adopted fd is gone once closed: reopening says so instead of crashing.
    m_link->open();
    ASSERT_TRUE(waitForCount(failed, 2));
    EXPECT_TRUE(failed.at(1).value(0).toString().contains(QStringLiteral("cannot be reopened")));
}

TEST(CanLink, NamedInterfaceThatCannotOpenFailsWithAClearReason)
{
    CanLink link(QStringLiteral("vtnocan0"));
    QSignalSpy failed(&link, &CanLink::failed);
    link.open();
    ASSERT_TRUE(waitForCount(failed, 1));
    EXPECT_EQ(link.state(), LinkState::Failed);
    const QString reason = failed.first().value(0).toString();
    // Without AF_CAN: "SocketCAN is not available"; with it: "no such network interface".
    EXPECT_TRUE(reason.contains(QStringLiteral("vtnocan0"))) << reason.toStdString();
    EXPECT_TRUE(reason.contains(QStringLiteral("SocketCAN")) ||
                reason.contains(QStringLiteral("no such network interface")))
        << reason.toStdString();
}

TEST(CanLink, RealVcan0LoopsFramesBetweenTwoSockets)
{
    const int probe = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
    if (probe < 0)
        GTEST_SKIP() << "no SocketCAN in this kernel (socket(PF_CAN): " << std::strerror(errno)
                     << "); the fd path is covered through socketpair";
    ::close(probe);
    if (::if_nametoindex("vcan0") == 0)
        GTEST_SKIP() << "no vcan0 (ip link add dev vcan0 type vcan && ip link set up vcan0)";

    CanLink a(QStringLiteral("vcan0"));
    CanLink b(QStringLiteral("vcan0"));
    QSignalSpy atB(&b, &CanLink::received);
    a.open();
    b.open();
    ASSERT_TRUE(waitForState(a, LinkState::Open));
    ASSERT_TRUE(waitForState(b, LinkState::Open));
    a.sendFrame(sdoRequest());
    ASSERT_TRUE(waitForCount(atB, 1));
    EXPECT_EQ(atB.first().value(0).toByteArray(), sdoRequest().toImage());
}

} // namespace
