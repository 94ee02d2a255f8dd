// valvetune-sim over TCP with more than one client: a Modbus TCP node serves every connection at
// once, as a gateway does, each answer on the connection of its request with that request's
// transaction id (Modbus Messaging on TCP/IP Implementation Guide V1.0b §3.1.3); the node image
// has one master and turns a second one away.
#include "modbus/tcp.h"
#include "sim_process.h"

#include <QTcpSocket>
#include <gtest/gtest.h>

namespace vt::simtest {
namespace {

namespace modbus = dev::modbus;

// A Modbus TCP master on its own connection, with blocking, bounded waits.
class Master
{
public:
    explicit Master(const QString &where)
    {
        m_socket.connectToHost(QStringLiteral("127.0.0.1"), where.section(':', -1).toUShort());
        m_connected = m_socket.waitForConnected(kWaitMs);
    }
    bool connected() const { return m_connected; }
    QTcpSocket &socket() { return m_socket; }

    void send(std::uint16_t transaction, std::uint8_t unit, modbus::RequestPdu pdu)
    {
        const auto adu = modbus::encodeTcp(modbus::TcpRequest{transaction, unit, std::move(pdu)});
        ASSERT_TRUE(adu.ok());
        m_socket.write(reinterpret_cast<const char *>(adu->data()),
                       static_cast<qint64>(adu->size()));
        ASSERT_TRUE(m_socket.waitForBytesWritten(kWaitMs));
    }
    // The next answer on this connection (nullopt: none within the bound).
    std::optional<modbus::TcpResponse> answer()
    {
        const QDeadlineTimer deadline(kWaitMs);
        for (;;) {
            if (m_buffer.size() >= static_cast<qsizetype>(modbus::kMbapSize)) {
                const auto *data = reinterpret_cast<const std::uint8_t *>(m_buffer.constData());
                const auto header = modbus::decodeMbap(
                    std::span<const std::uint8_t>(data, static_cast<std::size_t>(m_buffer.size())));
                if (!header.ok())
                    return std::nullopt;
                const auto size = static_cast<qsizetype>(header->aduSize());
                if (m_buffer.size() >= size) {
                    auto response = modbus::decodeTcpResponse(
                        std::span<const std::uint8_t>(data, static_cast<std::size_t>(size)));
                    m_buffer.remove(0, size);
                    if (!response.ok())
                        return std::nullopt;
                    return *response;
                }
            }
            if (deadline.hasExpired() || !m_socket.waitForReadyRead(static_cast<int>(
                                             std::max<qint64>(1, deadline.remainingTime()))))
                return std::nullopt;
            m_buffer += m_socket.readAll();
        }
    }

private:
    QTcpSocket m_socket;
    QByteArray m_buffer;
    bool m_connected = false;
};

std::optional<std::uint16_t> firstRegister(const std::optional<modbus::TcpResponse> &r)
{
    if (!r)
        return std::nullopt;
    const auto *read = std::get_if<modbus::ReadResponse>(&r->pdu);
    if (!read || read->registers.empty())
        return std::nullopt;
    return read->registers.front();
}

// Two masters, their requests interleaved on one simulated 3-fold DMA-2 and using the same
// transaction ids: each gets its own answers, in its own order, and both see one node — what
// one writes, the other reads.
TEST(SimTcpClients, TwoMastersInterleavedOnOneNode)
{
    Sim sim({"--device", "dma-pn-v51", "--modules", "3", "--tcp", "127.0.0.1:0", "-v"});
    const QString where = sim.listening();
    ASSERT_TRUE(where.startsWith("127.0.0.1:")) << sim.stderrText().toStdString();
    const int id = paramId("dma-pn-v51", "C1.07");
    ASSERT_GT(id, 0);
    const auto reg = static_cast<std::uint16_t>(id);

    Master a(where);
    Master b(where);
    ASSERT_TRUE(a.connected());
    ASSERT_TRUE(b.connected());

    // Both ask before either reads: B's write to unit 2 and A's read of unit 1 are in flight
    // together, under the same transaction id 7.
    a.send(7, 1, modbus::ReadRequest{reg, 1});
    b.send(7, 2, modbus::WriteRequest{reg, 1234});
    const auto b7 = b.answer();
    const auto a7 = a.answer();
    ASSERT_TRUE(a7 && b7);
    EXPECT_EQ(a7->transaction, 7);
    EXPECT_EQ(a7->unit, 1);
    EXPECT_EQ(firstRegister(a7), freshWord("dma-pn-v51", 3, 0, id));
    EXPECT_EQ(b7->transaction, 7);
    EXPECT_EQ(b7->unit, 2);
    EXPECT_EQ(b7->pdu, modbus::ResponsePdu(modbus::WriteResponse{reg, 1234}));
    a.send(8, 2, modbus::ReadRequest{reg, 1}); // after B's write was answered
    const auto a8 = a.answer();
    ASSERT_TRUE(a8);
    EXPECT_EQ(a8->transaction, 8);
    EXPECT_EQ(firstRegister(a8), 1234); // A reads what B wrote: one node

    // B leaves; A goes on, and a third master comes and goes beside it.
    b.socket().disconnectFromHost();
    Master c(where);
    ASSERT_TRUE(c.connected());
    c.send(1, 2, modbus::ReadRequest{reg, 1});
    a.send(9, 2, modbus::WriteRequest{reg, 0});
    EXPECT_EQ(firstRegister(c.answer()), 1234);
    const auto a9 = a.answer();
    ASSERT_TRUE(a9);
    EXPECT_EQ(a9->transaction, 9);

    sim.process().terminate();
    ASSERT_TRUE(sim.process().waitForFinished(kWaitMs));
    const QString log = sim.stderrText();
    EXPECT_TRUE(log.contains(QRegularExpression(R"(client 2 127\.0\.0\.1:\d+ connected)")))
        << log.toStdString();
    EXPECT_TRUE(log.contains("(client 3)")) << log.toStdString();
}

// valvetune-cli get while another master holds a connection with a request answered: the
// second client is served at once (it used to wait behind the first and fail to identify).
TEST(SimTcpClients, CliGetWhileAnotherClientIsConnected)
{
    Sim sim({"--device", "dma-pn-v51", "--modules", "3", "--tcp", "127.0.0.1:0"});
    const QString where = sim.listening();
    ASSERT_TRUE(where.startsWith("127.0.0.1:")) << sim.stderrText().toStdString();
    const int id = paramId("dma-pn-v51", "C1.07");
    Master first(where);
    ASSERT_TRUE(first.connected());
    first.send(1, 3, modbus::WriteRequest{static_cast<std::uint16_t>(id), 2500});
    ASSERT_TRUE(first.answer());

    const ProcessRun get =
        run(QStringLiteral(VT_CLI_PATH), {"get", "--tcp", where, "--unit", "3", "C1.07"});
    ASSERT_TRUE(get.finished);
    EXPECT_EQ(get.code, 0) << get.err.toStdString();
    EXPECT_EQ(get.out, "C1.07          2.500 V\n");

    first.send(2, 3, modbus::ReadRequest{static_cast<std::uint16_t>(id), 1});
    EXPECT_EQ(firstRegister(first.answer()), 2500); // the first connection was kept throughout
}

// The node image is one master's process image: a second client is closed at once and told
// why on the simulator's stderr; the first keeps its connection.
TEST(SimTcpClients, NodeImageTurnsASecondMasterAway)
{
    Sim sim({"--device", "dma-pn-v51", "--modules", "3", "--tcp", "127.0.0.1:0", "--protocol",
             "node-image"});
    const QString where = sim.listening();
    ASSERT_TRUE(where.startsWith("127.0.0.1:")) << sim.stderrText().toStdString();
    Master first(where);
    ASSERT_TRUE(first.connected());
    Master second(where);
    ASSERT_TRUE(second.connected()); // accepted by the kernel, then closed by the node
    EXPECT_TRUE(second.socket().state() == QAbstractSocket::UnconnectedState ||
                second.socket().waitForDisconnected(kWaitMs));
    EXPECT_TRUE(sim.waitForStderr("node image: refused 127.0.0.1:"))
        << sim.stderrSeen().toStdString();
    EXPECT_TRUE(sim.stderrSeen().contains("belongs to client 1"));
    EXPECT_EQ(first.socket().state(), QAbstractSocket::ConnectedState);

    const ProcessRun info =
        run(QStringLiteral(VT_CLI_PATH), {"info", "--tcp", where, "--protocol", "node-image"});
    ASSERT_TRUE(info.finished);
    EXPECT_EQ(info.code, 3) << info.out.toStdString() << info.err.toStdString(); // connection
}

} // namespace
} // namespace vt::simtest
