// valvetune-sim on CAN ("Front ends: … CANopen SDO over a CAN fd"): the
// real binary serves expedited SDO transfers (CiA 301 §7.2.4.3; request 0x600 + node, response
// 0x580 + node) for an HCS module's manufacturer objects 0x2000 + ID, sub 0, and the ED1's CiA 408
// objects (ARCHITECTURE.md "CAN"). This kernel has no SocketCAN, so the bus is one end of
// socketpair(AF_UNIX, SOCK_SEQPACKET) handed to the child with --can-fd (one struct can_frame per
// datagram, as CAN_RAW delivers them); the vcan0 test skips without SocketCAN. Every wait is
// bounded; no sleeps.
#include "canopen/can_frame.h"
#include "canopen/sdo.h"
#include "sim_process.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <linux/can.h>
#include <net/if.h>
#include <optional>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

using namespace vt::simtest;
namespace canopen = vt::dev::canopen;
using canopen::Sdo;
using canopen::SdoCommand;

namespace {

// One end of a datagram socket on which the test plays the SDO client.
class SdoClient
{
public:
    SdoClient(int fd, std::uint8_t node) : m_fd(fd), m_node(node) {}

    bool sendFrame(const canopen::CanFrame &frame)
    {
        const auto image = canopen::toSocketCan(frame);
        return ::send(m_fd, image.data(), image.size(), MSG_NOSIGNAL) ==
               static_cast<ssize_t>(image.size());
    }
    bool sendSdo(const Sdo &request, std::uint8_t node)
    {
        auto frame = canopen::toCanFrame(request, node);
        return frame.ok() && sendFrame(*frame);
    }
    // The next frame from the simulator, at most kWaitMs away.
    std::optional<canopen::CanFrame> nextFrame()
    {
        pollfd p{m_fd, POLLIN, 0};
        if (::poll(&p, 1, kWaitMs) != 1)
            return std::nullopt;
        std::uint8_t buffer[80];
        const ssize_t n = ::recv(m_fd, buffer, sizeof buffer, MSG_DONTWAIT);
        if (n <= 0)
            return std::nullopt;
        EXPECT_EQ(n, static_cast<ssize_t>(canopen::kSocketCanFrameSize));
        auto frame = canopen::fromSocketCan(
            std::span<const std::uint8_t>(buffer, static_cast<std::size_t>(n)));
        return frame.ok() ? std::optional<canopen::CanFrame>(*frame) : std::nullopt;
    }
    // Request → the server's answer on 0x580 + node (an empty Sdo when none came).
    Sdo transact(const Sdo &request)
    {
        EXPECT_TRUE(sendSdo(request, m_node));
        const auto frame = nextFrame();
        if (!frame) {
            ADD_FAILURE() << "no answer within " << kWaitMs << " ms";
            return {};
        }
        EXPECT_EQ(frame->id, canopen::sdoResponseId(m_node));
        auto message = canopen::fromCanFrame(*frame);
        EXPECT_TRUE(message.ok());
        return message.ok() ? message->sdo : Sdo{};
    }
    Sdo upload(std::uint16_t index, std::uint8_t sub = 0)
    {
        return transact(canopen::uploadRequest(index, sub));
    }
    Sdo download(std::uint16_t index, std::uint32_t value, std::size_t bytes)
    {
        return transact(canopen::expeditedDownload(index, 0, value, bytes));
    }

private:
    int m_fd;
    std::uint8_t m_node;
};

std::optional<std::uint32_t> abortCode(const Sdo &sdo)
{
    return sdo.command == SdoCommand::Abort ? std::optional<std::uint32_t>(sdo.abortCode)
                                            : std::nullopt;
}

std::uint16_t hcsObject(const std::string &family, const std::string &name)
{
    const int id = paramId(family, name);
    EXPECT_GE(id, 0) << name;
    return static_cast<std::uint16_t>(0x2000 + id);
}

// valvetune-sim with --can-fd on one end of a SEQPACKET socketpair; the test keeps the other.
// Both ends are close-on-exec; the child's end survives only the simulator's exec.
class CanSim
{
public:
    explicit CanSim(QStringList args, std::uint8_t node = 1)
    {
        int fds[2] = {-1, -1};
        if (::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, fds) != 0) {
            ADD_FAILURE() << "socketpair: " << std::strerror(errno);
            return;
        }
        m_peer = fds[0];
        const int child = fds[1];
        args << "--can-fd" << QString::number(child);
        m_sim.emplace(args, [child] { ::fcntl(child, F_SETFD, 0); });
        ::close(child); // the simulator has its copy now
        m_client.emplace(m_peer, node);
    }
    ~CanSim()
    {
        m_sim.reset();
        if (m_peer >= 0)
            ::close(m_peer);
    }
    CanSim(const CanSim &) = delete;
    CanSim &operator=(const CanSim &) = delete;

    Sim &sim() { return *m_sim; }
    SdoClient &client() { return *m_client; }
    void closePeer()
    {
        ::close(m_peer);
        m_peer = -1;
    }

private:
    int m_peer = -1;
    std::optional<Sim> m_sim;
    std::optional<SdoClient> m_client;
};

} // namespace

// HCS parameters as objects 0x2000 + ID, sub 0: Vers (ID 0) and C1.03 read the values a fresh
// DMA-2 V51 holds; C1.07 takes a download and reads it back; a read-only d-value, a value
// above the row's maximum and a sub-index ≠ 0 get their CiA 301 §7.2.4.3.17 aborts. A request
// to another node is not answered (the next answer is the one to ours); -v logs candump lines.
TEST(SimCan, HcsParametersOverSdo)
{
    const std::string family = "dma-pn-v51";
    CanSim can({"--device", QString::fromStdString(family), "--node", "5", "-v"}, 5);
    const QString where = can.sim().listening();
    ASSERT_TRUE(where.startsWith("can-fd ") && where.endsWith(" node 5"))
        << where.toStdString() << can.sim().stderrText().toStdString();
    SdoClient &client = can.client();

    ASSERT_TRUE(client.sendSdo(canopen::uploadRequest(0x2000, 0), 6)); // node 6: nobody
    const Sdo vers = client.upload(0x2000);
    ASSERT_EQ(vers.command, SdoCommand::InitiateUploadResponse) << abortCode(vers).value_or(0);
    EXPECT_EQ(vers.index, 0x2000);
    EXPECT_EQ(vers.data.size(), 2u);
    EXPECT_EQ(canopen::expeditedValue(vers), freshWord(family, 1, 0, 0));
    EXPECT_EQ(canopen::expeditedValue(vers), 5100u); // V51 × 100

    const std::uint16_t c103 = hcsObject(family, "C1.03");
    EXPECT_EQ(canopen::expeditedValue(client.upload(c103)),
              freshWord(family, 1, 0, paramId(family, "C1.03")));

    const std::uint16_t c107 = hcsObject(family, "C1.07");
    const Sdo written = client.download(c107, 1234, 2);
    EXPECT_EQ(written.command, SdoCommand::InitiateDownloadResponse)
        << abortCode(written).value_or(0);
    EXPECT_EQ(canopen::expeditedValue(client.upload(c107)), 1234u);

    EXPECT_EQ(abortCode(client.download(hcsObject(family, "d1.01"), 1, 2)), 0x06010002u);
    EXPECT_EQ(abortCode(client.download(c107, 10000, 2)), 0x06090031u); // C1.07 ≤ 9999
    EXPECT_EQ(canopen::expeditedValue(client.upload(c107)), 1234u);
    EXPECT_EQ(abortCode(client.upload(0x2000, 1)), 0x06090011u);

    can.sim().process().terminate();
    ASSERT_TRUE(can.sim().process().waitForFinished(kWaitMs));
    EXPECT_EQ(can.sim().process().exitCode(), 0);
    const QString log = can.sim().stderrText();
    EXPECT_TRUE(log.contains("] <- 605#4000200000000000")) << log.toStdString();
    EXPECT_TRUE(log.contains("] -> 585#4B002000EC130000")) << log.toStdString();
}

// The Wandfluh ED1 over CAN: CiA 301 0x1000 device type = profile 408; the CiA 408 status word
// 0x6041 reads (2 bytes) and refuses a download; the control word 0x6040 is write-only; device
// mode 0x6042 reads its dictionary default (1 = preset value via bus).
TEST(SimCan, Ed1Cia408Objects)
{
    CanSim can({"--device", "wandfluh-ed1"});
    ASSERT_EQ(can.sim().listening().section(' ', -2), "node 1")
        << can.sim().stderrText().toStdString();
    SdoClient &client = can.client();
    EXPECT_EQ(canopen::expeditedValue(client.upload(0x1000)), 408u);
    const Sdo status = client.upload(0x6041);
    ASSERT_EQ(status.command, SdoCommand::InitiateUploadResponse) << abortCode(status).value_or(0);
    EXPECT_EQ(status.data.size(), 2u);
    EXPECT_EQ(abortCode(client.download(0x6041, 0, 2)), 0x06010002u);
    EXPECT_EQ(abortCode(client.upload(0x6040)), 0x06010001u);
    EXPECT_EQ(canopen::expeditedValue(client.upload(0x6042)), 1u);
}

// The bus going away (the peer closes its end) is a lost connection: exit 3. --fault cut=1 ends
// the simulator with 0 after its first answer has left.
TEST(SimCan, PeerGoneAndFaultCut)
{
    {
        CanSim can({"--device", "opat"});
        ASSERT_FALSE(can.sim().listening().isEmpty()) << can.sim().stderrText().toStdString();
        can.closePeer();
        ASSERT_TRUE(can.sim().process().waitForFinished(kWaitMs));
        EXPECT_EQ(can.sim().process().exitCode(), 3);
        EXPECT_TRUE(can.sim().stderrText().contains("the peer closed it"));
    }
    CanSim can({"--device", "opat", "--fault", "cut=1"});
    ASSERT_FALSE(can.sim().listening().isEmpty()) << can.sim().stderrText().toStdString();
    EXPECT_EQ(canopen::expeditedValue(can.client().upload(0x2000)), freshWord("opat", 1, 0, 0));
    ASSERT_TRUE(can.sim().process().waitForFinished(kWaitMs));
    EXPECT_EQ(can.sim().process().exitCode(), 0);
    EXPECT_TRUE(can.sim().stderrText().contains("fault cut after 1 answers"));
}

// Endpoints that cannot work exit 3 with one line: an interface that does not exist (or no
// SocketCAN at all), a stream socket (no can_frame boundaries), a descriptor that is not open.
TEST(SimCan, UnusableEndpointsExitThree)
{
    int stream[2] = {-1, -1};
    ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, stream), 0);
    {
        const int child = stream[1];
        Sim sim({"--device", "opat", "--can-fd", QString::number(child)},
                [child] { ::fcntl(child, F_SETFD, 0); });
        ASSERT_TRUE(sim.process().waitForFinished(kWaitMs));
        EXPECT_EQ(sim.process().exitCode(), 3);
        EXPECT_TRUE(sim.stderrText().contains("stream socket")) << sim.stderrText().toStdString();
    }
    ::close(stream[0]);
    ::close(stream[1]);
    const QList<QStringList> cases = {
        {"--device", "opat", "--can", "vtnosuch0"},
        {"--device", "opat", "--can-fd", "999"},
    };
    for (const QStringList &args : cases) {
        const ProcessRun r = run(QStringLiteral(VT_SIM_PATH), args);
        ASSERT_TRUE(r.finished);
        EXPECT_EQ(r.code, 3) << args.join(' ').toStdString() << ": " << r.err.toStdString();
        EXPECT_EQ(lineCount(r.err), 1) << r.err.toStdString();
        EXPECT_TRUE(r.out.isEmpty()) << r.out.toStdString();
    }
}

// A real SocketCAN bus: valvetune-sim --can vcan0 answers an SDO upload sent on a CAN_RAW socket.
// Needs a kernel with SocketCAN and `ip link add dev vcan0 type vcan && ip link set up vcan0`.
TEST(SimCan, Vcan0WhenAvailable)
{
    const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
    if (fd < 0)
        GTEST_SKIP() << "no SocketCAN in this kernel (socket(PF_CAN): " << std::strerror(errno)
                     << ")";
    const unsigned index = ::if_nametoindex("vcan0");
    if (index == 0) {
        ::close(fd);
        GTEST_SKIP()
            << "no vcan0 interface (ip link add dev vcan0 type vcan; ip link set up vcan0)";
    }
    sockaddr_can address{};
    address.can_family = AF_CAN;
    address.can_ifindex = static_cast<int>(index);
    ASSERT_EQ(::bind(fd, reinterpret_cast<const sockaddr *>(&address), sizeof address), 0)
        << std::strerror(errno);
    Sim sim({"--device", "opat", "--can", "vcan0", "--node", "9"});
    ASSERT_EQ(sim.listening(), "can:vcan0 node 9") << sim.stderrText().toStdString();
    SdoClient client(fd, 9);
    EXPECT_EQ(canopen::expeditedValue(client.upload(0x2000)), freshWord("opat", 1, 0, 0));
    ::close(fd);
}
